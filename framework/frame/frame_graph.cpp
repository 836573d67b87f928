#include "frame/frame_graph.h"

#include "frame/pass_timer.h"
#include "frame/resource_pool.h"
#include "gl/program.h"
#include "gl/state.h"
#include "util/error.h"

#include <algorithm>
#include <map>

namespace rtlab {
namespace {

#ifdef NDEBUG
bool g_stateCheckDefault = false;
#else
bool g_stateCheckDefault = true;
#endif

[[noreturn]] void graphError(const std::string& message) { throw Error(ExitCode::Internal, "frame graph: " + message); }

// A use must suit what the resource is: buffer uses of buffers, texture uses of textures, levels
// and layers in range, no depth texture as an image.
void checkUseFits(const std::string& pass, const PassUse& u, const ResourceDesc& desc) {
  const bool texture = isTextureDesc(desc);
  const bool textureUse = u.kind == UseKind::Sampled || u.kind == UseKind::Attachment || u.kind == UseKind::Image;
  const bool bufferUse = u.kind == UseKind::StorageBuffer || u.kind == UseKind::AtomicCounter || u.kind == UseKind::Indirect;
  if ((texture && bufferUse) || (!texture && textureUse))
    graphError("pass '" + pass + "' uses " + (texture ? "texture" : "buffer") + " '" + u.resource + "' as " +
               (texture ? "a buffer" : "a texture") + " (" + useKindName(u.kind) + ")");
  if (!texture || (u.kind != UseKind::Image && u.kind != UseKind::Attachment)) return;
  const auto& td = std::get<gl::TextureDesc>(desc);
  if (u.level < 0 || u.level >= td.levels || u.layer >= td.layersAt(u.level) || (u.layer >= 0 && !td.layered()))
    graphError("pass '" + pass + "' uses level " + std::to_string(u.level) + " layer " + std::to_string(u.layer) + " of '" +
               u.resource + "', a " + gl::targetName(td.target) + " texture with " + std::to_string(td.levels) +
               " levels and " + std::to_string(td.layersAt(0)) + " layers");
  if (u.kind == UseKind::Image && gl::isDepthFormat(td.format))
    graphError("pass '" + pass + "' binds depth texture '" + u.resource + "' as an image");
}

GLenum imageAccess(Access a) {
  switch (a) {
  case Access::Read: return GL_READ_ONLY;
  case Access::Write: return GL_WRITE_ONLY;
  case Access::ReadWrite: return GL_READ_WRITE;
  }
  return GL_READ_WRITE;
}

int groups(int invocations, int local) { return local > 0 ? (invocations + local - 1) / local : 0; }

} // namespace

// ---- FrameGraph ----

void FrameGraph::setStateCheckDefault(bool on) { g_stateCheckDefault = on; }

FrameGraph::FrameGraph(const Scene& scene, const ParamSet& params, const FrameView& view, SceneGpu& sceneGpu,
                       gl::ProgramCache& programs, ResourcePool& pool, const GpuCommon& common)
    : m_ctx{scene, params, view, sceneGpu, programs, pool, common}, m_stateCheck(g_stateCheckDefault) {}

void FrameGraph::addPass(const std::string& name, const std::function<void(PassBuilder&)>& setup,
                         std::function<void(PassContext&)> execute) {
  Pass pass;
  pass.name = name;
  pass.technique = m_technique;
  setup(pass.decl);
  pass.execute = std::move(execute);
  m_passes.push_back(std::move(pass));
}

void FrameGraph::addComputePass(const std::string& name, const ComputeGrid& grid,
                                const std::function<void(PassBuilder&)>& setup, ComputeExecute execute) {
  Pass pass;
  pass.name = name;
  pass.technique = m_technique;
  pass.compute = true;
  pass.grid = grid;
  setup(pass.decl);
  if (grid.source == ComputeGrid::Source::Indirect) pass.decl.readIndirect(grid.resource);
  pass.computeExecute = std::move(execute);
  m_passes.push_back(std::move(pass));
}

void FrameGraph::importTexture(const std::string& name, gl::Texture& texture) {
  if (m_imports.count(name)) graphError("'" + name + "' is imported twice");
  if (!texture) graphError("imported texture '" + name + "' has no GL object");
  m_imports[name].texture = &texture;
}

void FrameGraph::importBuffer(const std::string& name, gl::BufferObject& buffer) {
  if (m_imports.count(name)) graphError("'" + name + "' is imported twice");
  if (!buffer.id()) graphError("imported buffer '" + name + "' has no GL object");
  m_imports[name].buffer = &buffer;
}

namespace {
ResourceDesc importDesc(const ResourcePool::Import& i) {
  if (i.texture) return i.texture->desc();
  return i.buffer->desc();
}
} // namespace

bool FrameGraph::isProduced(const std::string& resource) const {
  if (m_imports.count(resource)) return true;
  for (const auto& p : m_passes)
    for (const auto& u : p.decl.m_uses)
      if (u.writes() && u.resource == resource) return true;
  return false;
}

void FrameGraph::checkDescriptions() const {
  struct First {
    std::string pass;
    const ResourceDesc* desc;
  };
  std::map<std::string, First> first;
  std::map<std::string, ResourceDesc> imported;
  for (const auto& [name, i] : m_imports) {
    imported.emplace(name, importDesc(i));
    first.emplace(name, First{"(imported)", &imported.at(name)});
  }
  for (const auto& p : m_passes)
    for (const auto& u : p.decl.m_uses) {
      if (!u.hasDesc) continue;
      auto [it, inserted] = first.emplace(u.resource, First{p.name, &u.desc});
      if (inserted) continue;
      const std::string diff = descDifference(u.desc, *it->second.desc);
      if (!diff.empty())
        graphError("pass '" + p.name + "' describes '" + u.resource + "' differently from " +
                 (m_imports.count(u.resource) ? std::string("the imported object") : "pass '" + it->second.pass + "'") +
                 " (" + diff + ")");
    }
}

// In pass order over the kept passes: every read has an earlier writer, every use suits its resource.
void FrameGraph::checkReads() {
  std::set<std::string> written;
  std::map<std::string, ResourceDesc> descs;
  for (const auto& [name, i] : m_imports) {
    written.insert(name);
    descs.emplace(name, importDesc(i));
  }
  for (auto& p : m_passes) {
    if (!p.kept) continue;
    p.decl.m_absent.clear();
    for (const auto& u : p.decl.m_uses) {
      if (!u.reads() || written.count(u.resource)) continue;
      if (u.optional) {
        p.decl.m_absent.insert(u.resource);
        continue;
      }
      graphError("pass '" + p.name + "' reads '" + u.resource + "' (" + useKindName(u.kind) + "), which " +
                 (isProduced(u.resource) ? "no earlier pass writes" : "no pass produces"));
    }
    for (const auto& u : p.decl.m_uses) {
      if (u.hasDesc) descs.emplace(u.resource, u.desc);
      if (u.writes()) written.insert(u.resource);
    }
    for (const auto& u : p.decl.m_uses) {
      auto d = descs.find(u.resource);
      if (d != descs.end()) checkUseFits(p.name, u, d->second);
    }
    if (p.compute && p.grid.source == ComputeGrid::Source::Resource) {
      const bool declared = std::any_of(p.decl.m_uses.begin(), p.decl.m_uses.end(),
                                        [&](const PassUse& u) { return u.resource == p.grid.resource; });
      auto d = descs.find(p.grid.resource);
      if (!declared || d == descs.end() || !isTextureDesc(d->second))
        graphError("compute pass '" + p.name + "' takes its grid from '" + p.grid.resource +
                   "', which it does not declare as a texture it uses");
    }
  }
}

void FrameGraph::planBarriers(const std::vector<std::string>& targets) {
  // Per resource written incoherently: the barrier bits issued since that write.
  std::map<std::string, GLbitfield> pending;
  std::map<std::string, bool> textures;
  m_barriers.clear();
  // An imported object may have been written by an image store or a storage write in an earlier
  // frame (or outside the graph): its first use this frame gets the barrier of its path.
  for (const auto& [name, i] : m_imports) {
    pending[name] = 0;
    textures[name] = i.texture != nullptr;
  }
  auto issue = [&](GLbitfield bits) {
    for (auto& [name, covered] : pending) covered |= bits;
  };
  for (auto& p : m_passes) {
    p.barrier = 0;
    if (!p.kept) continue;
    for (const auto& u : p.decl.m_uses) {
      if (u.hasDesc && !m_imports.count(u.resource)) textures[u.resource] = isTextureDesc(u.desc);
      // Any later use, read or write, must see the incoherent write: the bit of the using path.
      auto it = pending.find(u.resource);
      if (it == pending.end()) continue;
      const GLbitfield bit = barrierBitFor(u.kind, textures[u.resource]);
      if (!(it->second & bit)) p.barrier |= bit;
    }
    if (p.barrier) {
      issue(p.barrier);
      m_barriers.push_back(Barrier{p.name, p.barrier});
    }
    for (const auto& u : p.decl.m_uses)
      if (u.writesIncoherently()) pending[u.resource] = 0;
  }
  m_endBarrier = 0;
  for (const auto& t : targets) {
    auto it = pending.find(t);
    if (it == pending.end()) continue;
    const GLbitfield bits = textures[t] ? GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT : GL_BUFFER_UPDATE_BARRIER_BIT;
    m_endBarrier |= bits & ~it->second;
  }
  if (m_endBarrier) m_barriers.push_back(Barrier{kEndOfFrame, m_endBarrier});
}

GLbitfield FrameGraph::barrierBefore(const std::string& pass) const {
  for (const auto& b : m_barriers)
    if (b.pass == pass) return b.bits;
  return 0;
}

void FrameGraph::compile(const std::vector<std::string>& targets) {
  checkDescriptions();
  std::set<std::string> needed(targets.begin(), targets.end());
  for (const auto& t : targets)
    if (!isProduced(t)) graphError("no pass produces the requested output '" + t + "'");
  // Walk backwards: a pass is kept if it writes something needed; then what it reads is needed.
  auto writtenBefore = [&](std::size_t index, const std::string& resource) {
    for (std::size_t i = 0; i < index; ++i)
      for (const auto& u : m_passes[i].decl.m_uses)
        if (u.writes() && u.resource == resource) return true;
    return false;
  };
  for (std::size_t i = m_passes.size(); i-- > 0;) {
    Pass& p = m_passes[i];
    p.kept = std::any_of(p.decl.m_uses.begin(), p.decl.m_uses.end(),
                         [&](const PassUse& u) { return u.writes() && needed.count(u.resource) != 0; });
    if (!p.kept) continue;
    for (const auto& u : p.decl.m_uses)
      if (u.reads() && (!u.optional || writtenBefore(i, u.resource))) needed.insert(u.resource);
    if (p.compute && p.grid.source == ComputeGrid::Source::Resource) needed.insert(p.grid.resource);
  }
  checkReads();
  planBarriers(targets);
  std::vector<std::string> live;
  for (const auto& p : m_passes) {
    if (!p.kept) continue;
    for (const auto& u : p.decl.m_uses)
      if (u.hasDesc && !m_imports.count(u.resource) && std::find(live.begin(), live.end(), u.resource) == live.end())
        live.push_back(u.resource);
  }
  m_ctx.pool.releaseExcept(live);
  m_ctx.pool.setImports(m_imports);
  for (const auto& p : m_passes) {
    if (!p.kept) continue;
    for (const auto& u : p.decl.m_uses) {
      if (!u.hasDesc || m_imports.count(u.resource)) continue;
      if (isTextureDesc(u.desc)) m_ctx.pool.acquire(u.resource, std::get<gl::TextureDesc>(u.desc));
      else m_ctx.pool.acquire(u.resource, std::get<gl::BufferDesc>(u.desc));
    }
  }
}

void FrameGraph::bindUses(const Pass& pass) const {
  for (const auto& u : pass.decl.m_uses) {
    switch (u.kind) {
    case UseKind::Image: {
      const gl::Texture& t = m_ctx.texture(u.resource);
      glBindImageTexture(GLuint(u.binding), t.id(), u.level, t.desc().layered() ? GL_TRUE : GL_FALSE, 0,
                         imageAccess(u.access), t.desc().format);
      break;
    }
    case UseKind::StorageBuffer:
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(u.binding), m_ctx.buffer(u.resource).id());
      break;
    case UseKind::AtomicCounter:
      glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, GLuint(u.binding), m_ctx.buffer(u.resource).id());
      break;
    case UseKind::Indirect:
      glBindBuffer(GL_DRAW_INDIRECT_BUFFER, m_ctx.buffer(u.resource).id());
      glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, m_ctx.buffer(u.resource).id());
      break;
    default: break;
    }
  }
}

void FrameGraph::dispatch(Pass& pass) {
  glm::ivec3 grid(0);
  switch (pass.grid.source) {
  case ComputeGrid::Source::Frame: grid = glm::ivec3(width(), height(), 1); break;
  case ComputeGrid::Source::Fixed: grid = pass.grid.size; break;
  case ComputeGrid::Source::Resource: {
    const gl::TextureDesc& d = m_ctx.texture(pass.grid.resource).desc();
    grid = glm::ivec3(d.widthAt(pass.grid.level), d.heightAt(pass.grid.level), d.layersAt(pass.grid.level));
    break;
  }
  case ComputeGrid::Source::Indirect: break;
  }
  m_ctx.grid = grid;
  gl::Program& program = pass.computeExecute(m_ctx);
  const glm::ivec3 local = program.workGroupSize();
  program.use();
  if (pass.grid.source == ComputeGrid::Source::Indirect) {
    glDispatchComputeIndirect(GLintptr(pass.grid.offset));
  } else {
    const glm::ivec3 count(groups(grid.x, local.x), groups(grid.y, local.y), groups(grid.z, local.z));
    if (count.x > 0 && count.y > 0 && count.z > 0) glDispatchCompute(GLuint(count.x), GLuint(count.y), GLuint(count.z));
  }
}

void FrameGraph::checkState(const std::string& when) const {
  const std::string diff = gl::firstDifference(gl::captureState(), gl::knownState());
  if (!diff.empty()) graphError("GL state " + when + " is not the known state: " + diff);
}

void FrameGraph::run(PassTimer& timer) {
  if (m_stateCheck) checkState("before the first pass");
  gl::restoreKnownState();
  for (auto& p : m_passes) {
    if (!p.kept) continue;
    timer.begin(p.name, p.technique);
    m_ctx.pass = &p.decl;
    if (p.barrier) glMemoryBarrier(p.barrier);
    bindUses(p);
    if (p.compute) dispatch(p);
    else p.execute(m_ctx);
    gl::restoreKnownState();
    m_ctx.pass = nullptr;
    m_ctx.grid = glm::ivec3(0);
    timer.end();
    if (m_stateCheck) checkState("after pass '" + p.name + "'");
  }
  if (m_endBarrier) glMemoryBarrier(m_endBarrier);
}

std::vector<FrameGraph::PassRecord> FrameGraph::passes() const {
  std::vector<PassRecord> out;
  for (const auto& p : m_passes) out.push_back(PassRecord{p.name, p.technique, p.kept, p.compute});
  return out;
}

} // namespace rtlab
