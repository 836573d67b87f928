#include "frame/frame_graph.h"

#include "frame/pass_timer.h"
#include "frame/resource_pool.h"
#include "util/error.h"

#include <algorithm>

namespace rtlab {

bool PassContext::has(const std::string& resource) const { return pool.has(resource); }

gl::Texture& PassContext::texture(const std::string& resource) const {
  gl::Texture* t = pool.find(resource);
  if (!t) throw Error(ExitCode::Internal, "frame resource '" + resource + "' was not produced this frame");
  return *t;
}

const gl::Framebuffer& PassContext::framebuffer(const std::string& label, const std::vector<std::string>& colors,
                                               const std::string& depth, int layer) const {
  std::vector<const gl::Texture*> textures;
  for (const auto& c : colors) textures.push_back(&texture(c));
  return pool.framebuffer(label, textures, depth.empty() ? nullptr : &texture(depth), layer);
}

void PassContext::beginFullscreen(const std::string& label, const std::vector<std::string>& colors) const {
  const gl::Framebuffer& fbo = framebuffer(label, colors);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  const gl::TextureDesc& d = texture(colors.front()).desc();
  glViewport(0, 0, d.width, d.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
}

namespace {
// The state every pass starts from; run() restores it after each pass.
void resetPassState() {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(0);
  glBindVertexArray(0);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  for (GLuint unit = 0; unit < 8; ++unit) glBindSampler(unit, 0);
}
} // namespace

FrameGraph::FrameGraph(const Scene& scene, const ParamSet& params, const FrameView& view, SceneGpu& sceneGpu,
                       gl::ProgramCache& programs, ResourcePool& pool, const GpuCommon& common)
    : m_ctx{scene, params, view, sceneGpu, programs, pool, common} {}

void FrameGraph::addPass(const std::string& name, const std::function<void(PassBuilder&)>& setup,
                         std::function<void(PassContext&)> execute) {
  Pass pass;
  pass.name = name;
  pass.technique = m_technique;
  setup(pass.decl);
  pass.execute = std::move(execute);
  m_passes.push_back(std::move(pass));
}

bool FrameGraph::isProduced(const std::string& resource) const {
  for (const auto& p : m_passes)
    for (const auto& w : p.decl.m_writes)
      if (w.first == resource) return true;
  return false;
}

void FrameGraph::compile(const std::vector<std::string>& targets) {
  std::set<std::string> needed(targets.begin(), targets.end());
  for (const auto& t : targets)
    if (!isProduced(t)) throw Error(ExitCode::Internal, "no pass produces the requested output '" + t + "'");
  // Walk backwards: a pass is kept if it writes something needed; then what it reads is needed.
  for (auto it = m_passes.rbegin(); it != m_passes.rend(); ++it) {
    Pass& p = *it;
    p.kept = std::any_of(p.decl.m_writes.begin(), p.decl.m_writes.end(),
                         [&](const auto& w) { return needed.count(w.first) != 0; });
    if (!p.kept) continue;
    for (const auto& r : p.decl.m_reads) {
      if (!isProduced(r)) throw Error(ExitCode::Internal, "pass '" + p.name + "' reads '" + r + "', which no pass produces");
      needed.insert(r);
    }
    for (const auto& r : p.decl.m_optionalReads)
      if (isProduced(r)) needed.insert(r);
  }
  std::vector<std::string> live;
  for (const auto& p : m_passes) {
    if (!p.kept) continue;
    for (const auto& [name, desc] : p.decl.m_writes) {
      if (std::find(live.begin(), live.end(), name) == live.end()) live.push_back(name);
    }
  }
  m_ctx.pool.releaseExcept(live);
  for (const auto& p : m_passes) {
    if (!p.kept) continue;
    for (const auto& [name, desc] : p.decl.m_writes) m_ctx.pool.acquire(name, desc);
  }
}

void FrameGraph::run(PassTimer& timer) {
  for (auto& p : m_passes) {
    if (!p.kept) continue;
    timer.begin(p.name, p.technique);
    p.execute(m_ctx);
    resetPassState();
    timer.end();
  }
}

std::vector<FrameGraph::PassRecord> FrameGraph::passes() const {
  std::vector<PassRecord> out;
  for (const auto& p : m_passes) out.push_back(PassRecord{p.name, p.technique, p.kept});
  return out;
}

} // namespace rtlab
