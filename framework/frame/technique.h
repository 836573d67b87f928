// A technique plug-in (docs/architecture.md "Techniques and the registry"): one stage, its
// parameters declared once, the passes it adds to the frame with their declared reads and writes,
// and its debug views.
#pragma once
#include "params/param_spec.h"
#include "scene/scene_change.h"

#include <string>
#include <vector>

namespace rtlab {

class FrameGraph;

struct DebugView {
  std::string name;  // AOV name, "<technique>.<view>", e.g. "shadow_map.light_depth"
  int channels = 1;  // 1 or 3
  std::string help;
};

struct TechniqueInfo {
  std::string id;     // "shadow_map"
  std::string stage;  // "shadow"
  std::string title;  // "Shadow map (Williams 1978)"
  std::string summary;
  std::string showcaseScene = "contact"; // built-in scene that shows it best (showcase, tests)
  std::vector<ParamSpec> params;  // keys "<id>.<name>"
  std::vector<DebugView> debugViews;
};

// A count a technique reports about its last frame (e.g. fragments an A-buffer dropped), written
// to the --stats JSON as {"technique", "name", "value"} (docs/cli.md).
struct TechniqueCounter {
  std::string name;  // "dropped_fragments": lower-case, without the technique's id
  double value = 0;
};

class Technique {
public:
  virtual ~Technique() = default;
  virtual const TechniqueInfo& info() const = 0;
  // Called every frame while the technique is active: adds its passes, each declaring the
  // resources it reads and writes. Passes whose outputs nothing needs are culled.
  virtual void setup(FrameGraph& frame) = 0;
  // Called before setup() on a frame where the scene changed since this technique last heard
  // (docs/scene-data.md "Scene changes"): once with everything on the first frame after the
  // technique is activated or a scene is set, once with `lights` after a light<N>.* key changed a
  // light. At most one call per frame; never for a camera move or a repeated value. A technique
  // that bakes scene data marks it stale here and rebuilds it in a pass.
  virtual void sceneChanged(const SceneChange& /*change*/) {}
  // Technique-owned GPU memory outside the frame graph's pool (reported in stats).
  virtual std::size_t ownedBytes() const { return 0; }
  // Counts about the last frame, for stats. Called only when stats are written, after the measured
  // frames, so it may read a GPU buffer back (a stall that no timed frame sees).
  virtual std::vector<TechniqueCounter> counters() const { return {}; }
};

} // namespace rtlab
