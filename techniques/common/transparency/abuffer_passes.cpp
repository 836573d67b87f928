// The A-buffer's passes (abuffer_passes.h; techniques/abuffer/README.md "Algorithm" and "Memory").
// Per band i: `<prefix>.build<i>` clears the band's heads, draws the transparent geometry into the
// lists and reads the node count back; `<prefix>.resolve<i>` composites the band. When a band's
// fragments do not fit the pool, the build grows the pool (up to the budget and
// GL_MAX_SHADER_STORAGE_BLOCK_SIZE) and builds again; when they exceed even that, it splits the
// band into parts built and resolved one after another (the resolve pass does the later parts),
// and the next frame plans more bands from this frame's count.
#include "techniques/common/transparency/abuffer_passes.h"

#include "frame/frame_graph.h"
#include "gl/program_cache.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "shading/hdr_clamp.h"
#include "shading/scene_gpu.h"

#include <algorithm>

namespace rtlab {
namespace {

constexpr int kHeadsUnit = 0, kCountsUnit = 1, kOutputUnit = 2; // image units (build.frag, resolve.comp)
constexpr int kNodesBinding = 0, kStatsBinding = 1; // storage buffers
constexpr int kCounterBinding = 0;                  // atomic counter
constexpr GLuint kEnd = GLuint(abuffer::kEndOfList);

gl::TextureDesc uintImage(const FrameGraph& frame) { return frameTexture(frame, GL_R32UI); }

std::uint64_t glBlockLimit() {
  GLint64 bytes = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);
  return bytes > 0 ? std::uint64_t(bytes) : std::uint64_t(1) << 27; // 128 MiB: GL 4.5's minimum
}

} // namespace

void AbufferPasses::release() {
  m_pool = gl::BufferObject();
  m_stats = gl::BufferObject();
  m_capacity = 0;
  m_hasLast = false;
}

std::size_t AbufferPasses::ownedBytes() const {
  return (m_pool ? m_pool.desc().bytes : 0) + (m_stats ? m_stats.desc().bytes : 0);
}

void AbufferPasses::allocatePool(std::uint64_t nodes) {
  m_pool = gl::BufferObject({gl::BufferKind::Storage, std::size_t(nodes * abuffer::kNodeBytes)}, name("nodes"));
  m_capacity = nodes;
}

// The bands of this frame and the pool's size, from the last frame's counts (or 4 nodes per pixel
// on the first frame): enough bands that the expected nodes fit; a frame that had to split plans
// at least as many rectangles as it used. The pool is sized for the largest band expected, grown
// or shrunk (when more than twice too large) to 1.25x that.
void AbufferPasses::plan(int width, int height) {
  const bool history = m_hasLast && m_last.width == width && m_last.height == height;
  const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
  const std::uint64_t expected = history ? m_last.nodes + m_last.poolDropped : pixels * abuffer::kInitialNodesPerPixel;
  int count = abuffer::bandCount(expected, m_maxNodes, height);
  if (history && m_last.split) count = std::min(std::max(count, m_last.rects), height);
  m_bands = abuffer::bands(width, height, count);
  const std::uint64_t perBand = history ? std::max<std::uint64_t>(m_last.maxRectNodes, 1) : expected / std::uint64_t(count);
  m_poolTarget = abuffer::grownCapacity(perBand, m_maxNodes);
  if (!m_setup.deferPool) sizePool();
  else if (!m_pool) allocatePool(1); // imported into the frame, sized by the first build
  if (!m_stats) m_stats = gl::BufferObject({gl::BufferKind::Storage, 2 * sizeof(GLuint)}, name("stats"));
}

void AbufferPasses::sizePool() {
  const std::uint64_t target = m_poolTarget;
  if (!m_pool || m_capacity < target || m_capacity > 2 * target || m_capacity > m_maxNodes) allocatePool(target);
}

void AbufferPasses::add(FrameGraph& frame, const AbufferSetup& setup) {
  m_setup = setup;
  m_maxNodes = abuffer::maxNodes(setup.poolBudgetBytes, glBlockLimit());
  plan(frame.width(), frame.height());
  const std::string pool = name("nodes"), stats = name("stats"), heads = name("heads"), counter = name("node_count"),
                    counts = name("counts");
  frame.importBuffer(pool, m_pool);
  frame.importBuffer(stats, m_stats);
  const gl::TextureDesc uintDesc = uintImage(frame);
  const gl::BufferDesc counterDesc{gl::BufferKind::AtomicCounter, sizeof(GLuint)};
  for (std::size_t i = 0; i < m_bands.size(); ++i) {
    const abuffer::Rect band = m_bands[i];
    frame.addPass(name("build") + std::to_string(i),
        [&](PassBuilder& b) {
          b.read(res::kDepth);
          b.writeImage(heads, uintDesc, kHeadsUnit);
          b.readWriteBuffer(pool, BufferBinding::Storage, kNodesBinding);
          b.writeBuffer(counter, counterDesc, BufferBinding::AtomicCounter, kCounterBinding);
          if (i == 0) b.readWriteBuffer(stats, BufferBinding::Storage, kStatsBinding);
          HdrClampCounters::declareUse(frame, b);
        },
        [this, i, band](PassContext& ctx) {
          if (i == 0) beginFrame(ctx);
          m_pending = {band};
          m_built = buildNext(ctx);
        });
    // The resolve also builds and resolves the later parts of a band that had to be split, so it
    // declares what the build uses too.
    frame.addPass(name("resolve") + std::to_string(i),
        [&](PassBuilder& b) {
          b.read(setup.colorIn);
          b.read(res::kDepth);
          b.writeImage(setup.colorOut, frameTexture(frame, GL_RGBA16F), kOutputUnit);
          b.readWriteImage(heads, kHeadsUnit);
          b.writeImage(counts, uintDesc, kCountsUnit);
          b.readWriteBuffer(pool, BufferBinding::Storage, kNodesBinding);
          b.readWriteBuffer(stats, BufferBinding::Storage, kStatsBinding);
          b.readWriteBuffer(counter, BufferBinding::AtomicCounter, kCounterBinding);
          HdrClampCounters::declareUse(frame, b);
        },
        [this, last = i + 1 == m_bands.size()](PassContext& ctx) {
          resolveRect(ctx, m_built);
          while (!m_pending.empty()) {
            m_built = buildNext(ctx);
            resolveRect(ctx, m_built);
          }
          if (last) { // the frame's counts plan the next frame
            m_last = m_frame;
            m_hasLast = true;
          }
        });
  }
  const int maxFragments = setup.maxFragments;
  for (const auto& [view, define] : {std::pair{setup.complexityView, "VIEW_COMPLEXITY"}, std::pair{setup.droppedView, "VIEW_DROPPED"}}) {
    if (view.empty()) continue;
    const std::string out = view, label = name(define[5] == 'C' ? "view_complexity" : "view_dropped");
    frame.addPass(label,
        [&](PassBuilder& b) {
          b.read(counts);
          b.write(out, frameTexture(frame, GL_RGBA32F));
        },
        [=](PassContext& ctx) {
          gl::Program& p = ctx.programs.get(
              {{"common/fullscreen.vert", "abuffer/view.frag"}, {define, "MAX_FRAGMENTS " + std::to_string(maxFragments)}, label});
          ctx.beginFullscreen(label, {out});
          p.use();
          ctx.texture(counts).bind(0);
          p.set("uCounts", 0);
          ctx.common.drawFullscreen();
        });
  }
}

void AbufferPasses::beginFrame(const PassContext& ctx) {
  if (m_setup.deferPool) sizePool();
  m_frame = FrameCounts{};
  m_frame.width = ctx.view.width;
  m_frame.height = ctx.view.height;
  m_stats.clear();
}

// Builds the first pending rectangle. A build that needed more nodes than the pool holds is done
// again: with a grown pool when the largest pool suffices, else in parts (pushed in front of the
// pending ones). A single pixel deeper than the largest pool keeps the nodes that fit; the rest
// of its fragments are counted as dropped.
abuffer::Rect AbufferPasses::buildNext(const PassContext& ctx) {
  for (;;) {
    const abuffer::Rect rect = m_pending.front();
    m_pending.pop_front();
    std::uint64_t count = buildRect(ctx, rect);
    if (count > m_capacity && count <= m_maxNodes) {
      allocatePool(abuffer::grownCapacity(count, m_maxNodes));
      ++m_frame.rebuilds;
      count = buildRect(ctx, rect);
    }
    if (count > m_capacity) {
      const std::vector<abuffer::Rect> parts = abuffer::split(rect, count, m_maxNodes);
      if (parts.size() > 1) {
        ++m_frame.rebuilds;
        m_frame.split = true;
        m_pending.insert(m_pending.begin(), parts.begin(), parts.end());
        continue;
      }
      m_frame.poolDropped += count - m_capacity;
    }
    const std::uint64_t stored = std::min(count, m_capacity);
    m_frame.nodes += stored;
    m_frame.maxRectNodes = std::max(m_frame.maxRectNodes, count);
    ++m_frame.rects;
    return rect;
  }
}

// Clears the rectangle's heads and the node counter, draws the transparent geometry into the
// lists (scissored to the rectangle) and returns the counter: the fragments that wanted a node.
std::uint64_t AbufferPasses::buildRect(const PassContext& ctx, const abuffer::Rect& rect) {
  // The previous rectangle's resolve read the nodes this build overwrites (a write after read,
  // which the graph's planned barriers, made for reads after writes, do not cover).
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                  GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  const gl::Texture& heads = ctx.texture(name("heads"));
  const gl::BufferObject& counter = ctx.buffer(name("node_count"));
  glClearTexSubImage(heads.id(), 0, rect.x, rect.y, 0, rect.width, rect.height, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, &kEnd);
  counter.clear();
  glBindImageTexture(kHeadsUnit, heads.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kNodesBinding, m_pool.id());
  glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, kCounterBinding, counter.id());

  const gl::Framebuffer& fbo = ctx.framebuffer(name("build"), {}, res::kDepth);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glViewport(0, 0, ctx.view.width, ctx.view.height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect.x, rect.y, rect.width, rect.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  std::vector<std::string> defines;
  if (ctx.common.hdrClamp.counting()) defines.push_back("HDR_CLAMP_COUNT");
  gl::Program& p = ctx.programs.get({{"shading/surface.vert", "abuffer/build.frag"}, defines, name("build")});
  setLayerUniforms(p, ctx);
  p.set("uCapacity", unsigned(m_capacity));
  ctx.common.hdrClamp.bind(p, name("build"));
  ctx.sceneGpu.draw(p, SceneGpu::Filter::Transparent, true, ctx.view.cameraPosition);
  glDisable(GL_SCISSOR_TEST);
  glDepthMask(GL_TRUE);

  // The node count, read back (the CPU waits for this rectangle's build: README "Memory").
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT);
  GLuint count = 0;
  glGetNamedBufferSubData(counter.id(), 0, sizeof(GLuint), &count);
  return count;
}

// Sorts and composites the rectangle's lists onto the opaque colour: one invocation a pixel.
void AbufferPasses::resolveRect(const PassContext& ctx, const abuffer::Rect& rect) {
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(kHeadsUnit, ctx.texture(name("heads")).id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glBindImageTexture(kCountsUnit, ctx.texture(name("counts")).id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
  glBindImageTexture(kOutputUnit, ctx.texture(m_setup.colorOut).id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kNodesBinding, m_pool.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kStatsBinding, m_stats.id());
  gl::Program& p = ctx.programs.get(
      {{"abuffer/resolve.comp"}, {"MAX_FRAGMENTS " + std::to_string(m_setup.maxFragments)}, name("resolve")});
  p.use();
  ctx.texture(m_setup.colorIn).bind(0);
  p.set("uColor", 0)
      .set("uCapacity", unsigned(m_capacity))
      .set("uOrigin", glm::ivec2(rect.x, rect.y))
      .set("uSize", glm::ivec2(rect.width, rect.height));
  glDispatchCompute(GLuint((rect.width + 7) / 8), GLuint((rect.height + 7) / 8), 1);
}

std::vector<TechniqueCounter> AbufferPasses::counters() const {
  std::vector<TechniqueCounter> out;
  if (!m_stats) return out;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<GLuint> v = m_stats.downloadAs<GLuint>();
  out.push_back({"dropped_fragments", double(v[0])});
  out.push_back({"max_depth_complexity", double(v[1])});
  out.push_back({"nodes", double(m_frame.nodes)});
  out.push_back({"pool_dropped_fragments", double(m_frame.poolDropped)});
  out.push_back({"bands", double(m_frame.rects)});
  out.push_back({"rebuilds", double(m_frame.rebuilds)});
  out.push_back({"pool_nodes", double(m_capacity)});
  return out;
}

} // namespace rtlab
