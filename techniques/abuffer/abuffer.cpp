// A-buffer — exact order-independent transparency: every transparent fragment of a pixel kept in
// a per-pixel linked list (Carpenter 1984, "The A-buffer, an antialiased hidden surface method";
// on the GPU with an atomic counter and head pointers: Yang, Hensley, Grün & Thibieroz 2010,
// "Real-Time Concurrent Linked List Construction on the GPU"), sorted per pixel and composited
// with Over back to front onto the opaque colour (docs/contract.md "Transparency"). Exact up to
// the 16-bit storage of each fragment's colour, as long as no pixel has more than
// abuffer.max_fragments layers (the rest are dropped, counted and shown). techniques/abuffer/README.md
// has the memory plan (bands when the fragments exceed the pool) and the measured cost.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "techniques/common/transparency/abuffer_passes.h"

namespace rtlab {
namespace {

class Abuffer final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "abuffer";
    info.stage = "transparency";
    info.title = "A-buffer (per-pixel fragment lists, Yang et al. 2010)";
    info.summary = "Exact Over: every transparent fragment appended to its pixel's list, the nearest max_fragments "
                   "sorted and composited back to front";
    info.showcaseScene = "layers";
    info.params = {
        ParamSpec::integer("abuffer.max_fragments", "Max fragments", 32, 1, 128)
            .withUnit("per pixel")
            .withFlags(kParamRecompile)
            .withHelp("Fragments per pixel the resolve sorts (its local array); the nearest are kept, farther ones "
                      "are dropped, counted (stats dropped_fragments) and shown (view abuffer.dropped)"),
        ParamSpec::real("abuffer.pool_mib", "Node pool budget", 1024.0, 0.0625, 4096.0)
            .logScale()
            .withUnit("MiB")
            .withFlags(kParamRealloc)
            .withHelp("Most memory the node pool (16 bytes a fragment) may take, also capped by "
                      "GL_MAX_SHADER_STORAGE_BLOCK_SIZE; a frame whose fragments need more is built and resolved in "
                      "horizontal bands (same image, more passes)"),
    };
    info.debugViews = {
        {"abuffer.complexity", 1, "fragments per pixel: the transparent layers in front of the opaque surface"},
        {"abuffer.dropped", 1, "fragments per pixel beyond abuffer.max_fragments, dropped (the farthest ones)"},
    };
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    AbufferSetup s;
    s.prefix = "abuffer";
    s.maxFragments = frame.params().getInt("abuffer.max_fragments");
    s.colorIn = frame.colorInput();
    s.colorOut = frame.colorOutput();
    s.poolBudgetBytes = std::uint64_t(frame.params().getFloat("abuffer.pool_mib") * 1024.0 * 1024.0);
    s.complexityView = aovResource("abuffer.complexity");
    s.droppedView = aovResource("abuffer.dropped");
    m_passes.add(frame, s);
  }

  // A new scene: the pool sized for the old one goes (an opaque-only scene then holds nothing).
  void sceneChanged(const SceneChange& change) override {
    if (change.geometry) m_passes.release();
  }
  std::size_t ownedBytes() const override { return m_passes.ownedBytes(); }
  std::vector<TechniqueCounter> counters() const override { return m_passes.counters(); }

private:
  TechniqueInfo m_info = staticInfo();
  AbufferPasses m_passes;
};

} // namespace

void registerTechnique_abuffer(TechniqueRegistry& registry) { registerTechniqueType<Abuffer>(registry); }

} // namespace rtlab
