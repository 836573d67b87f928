// The A-buffer's passes (techniques/abuffer/README.md): per screen band, a build pass appending
// every transparent fragment to its pixel's linked list (Yang, Hensley, Grün & Thibieroz 2010) and
// a resolve pass that sorts each list and composites it with Over onto the opaque colour. Reusable:
// the `abuffer` technique adds them for the transparency stage, and another technique can add them
// under its own prefix to compare against the exact result (a debug view of its error).
#pragma once
#include "frame/technique.h"
#include "gl/buffer.h"
#include "techniques/common/transparency/abuffer_plan.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace rtlab {

class FrameGraph;
struct PassContext;

struct AbufferSetup {
  std::string prefix = "abuffer";     // pass and resource names: "<prefix>.build0", "<prefix>.heads", ...
  int maxFragments = 32;              // per pixel: the resolve's local array (MAX_FRAGMENTS), 1..128
  std::string colorIn, colorOut;      // the opaque colour read (sampled); the composited colour (RGBA16F)
  std::uint64_t poolBudgetBytes = std::uint64_t(1) << 30; // the node pool's most bytes (and the GL limit)
  std::string complexityView, droppedView; // resources of the debug views ("" for none)
  // Size the node pool when the first build runs rather than when the passes are added: for passes
  // the graph may cull (another technique's debug view), which then hold one node until they run.
  bool deferPool = false;
};

// Owns what outlives a frame (the node pool, the stats buffer, the last frame's counts that plan
// the next one); add() adds one frame's passes, which run in order from the graph.
class AbufferPasses {
public:
  void add(FrameGraph& frame, const AbufferSetup& setup);
  // The pool and the stats buffer (technique-owned, imported into each frame).
  std::size_t ownedBytes() const;
  // The last frame's counts: the GPU's (dropped fragments, largest list; read back, a stall) and
  // the CPU's (nodes, bands, rebuilds, pool).
  std::vector<TechniqueCounter> counters() const;
  // Frees the GPU memory and forgets the history (a scene change).
  void release();

private:
  struct FrameCounts {
    std::uint64_t nodes = 0;          // nodes stored (the final build of every rectangle)
    std::uint64_t maxRectNodes = 0;   // the most nodes one rectangle needed
    std::uint64_t poolDropped = 0;    // fragments of single pixels deeper than the whole pool
    int rects = 0, rebuilds = 0;
    bool split = false;
    int width = 0, height = 0;
  };
  void plan(int width, int height);
  void sizePool(); // the pool for m_poolTarget nodes (plan() computes it)
  void beginFrame(const PassContext& ctx);
  abuffer::Rect buildNext(const PassContext& ctx);
  std::uint64_t buildRect(const PassContext& ctx, const abuffer::Rect& rect);
  void resolveRect(const PassContext& ctx, const abuffer::Rect& rect);
  void allocatePool(std::uint64_t nodes);
  std::string name(const char* what) const { return m_setup.prefix + "." + what; }

  AbufferSetup m_setup;
  gl::BufferObject m_pool, m_stats;
  std::uint64_t m_capacity = 0, m_maxNodes = 0, m_poolTarget = 0;
  std::vector<abuffer::Rect> m_bands;
  std::deque<abuffer::Rect> m_pending; // rectangles of the current band still to build
  abuffer::Rect m_built;               // the rectangle whose lists the pool holds
  FrameCounts m_frame, m_last;         // this frame's counts; the last complete frame's
  bool m_hasLast = false;
};

} // namespace rtlab
