// Everything the lecture viewer (`rtlab view`) shows and edits, in one place: the scene, the
// parameters and active techniques, the debug view, the compare mode, render scale, lecture
// mode, and what the last frames measured. The UI panels and the script runner change it only
// through the actions of viewer_actions.h, so both behave the same.
#pragma once
#include "frame/selection.h"
#include "params/param_set.h"
#include "scene/scene.h"
#include "viewer/bookmarks.h"
#include "viewer/camera_controller.h"

#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace rtlab {

enum class DebugMode { Off, Full, Pip };
enum class CompareMode { Off, Reference, Snapshot, Difference };

struct DebugViewSettings {
  std::string aov = "visibility"; // a built-in AOV or an active technique's debug view
  DebugMode mode = DebugMode::Off;
  float min = 0.0f, max = 1.0f;    // value range mapped to black..white (or the false-color scale)
  bool falseColor = false;         // scalar data through a color map
  bool autoRangeRequested = false; // set min/max from the next frame's values (valid pixels)
};

struct CompareSettings {
  CompareMode mode = CompareMode::Off;
  float divider = 0.5f; // the wipe's position from the left edge, [0, 1]
};

// One pass's timing history for the timings panel.
struct PassTiming {
  std::string pass, technique;
  double ms = 0.0;
};

struct ViewerState {
  explicit ViewerState(const TechniqueRegistry& techniques) : registry(&techniques), selection(techniques) {}

  const TechniqueRegistry* registry; // the techniques the panels and actions offer
  std::string sceneSpec;             // --scene value of the loaded scene
  Scene scene;
  ParamSet params;
  TechniqueSelection selection;
  CameraController camera;
  bool sceneChanged = true;          // the renderer must upload the scene again
  unsigned long sceneGeneration = 0; // counts scene loads (the reference's BVH follows it)
  bool techniquesChanged = true;     // the renderer must instantiate/destroy techniques

  DebugViewSettings view;
  CompareSettings compare;
  float renderScale = 1.0f;        // fraction of the window's size the frame is rendered at
  bool lecture = false;            // large TrueType text, bookmarks on the arrow keys
  std::vector<Bookmark> bookmarks; // --bookmarks FILE
  std::string bookmarksSource;
  int bookmark = -1; // the last bookmark applied

  // Measured.
  long frames = 0;                       // frames rendered since start
  long glErrors = 0;                     // GL errors counted over every frame
  std::vector<PassTiming> passes;        // the last frame's passes
  double frameMs = 0.0;                  // the last frame's total, by the timing method
  std::deque<float> frameHistory;        // recent frame totals (ms) for the history graph
  std::string timingMethod;              // "cpu-finish" | "gpu-query"
  std::vector<std::string> shaderErrors; // file:line messages of failed (re)compiles
  std::string status;                    // the last action's message for the status line

  // Compare mode's reference (reference_view.h): which AOV, how far it is, and the live metrics of
  // the visible frame against it (empty until computed).
  struct {
    std::string aov;
    int samples = 0;
    bool running = false;
    std::optional<double> rmse, flip;
    int metricsSamples = 0; // the reference's spp when the metrics were computed
    std::string waiting;    // why there are no metrics yet ("reference: 8 / 16 spp")
    std::string error;
  } reference;
  bool snapshotRequested = false; // freeze the current picture as compare side B

  // Text fields of the panels.
  std::string scenePathInput, presetPathInput = "rtlab_preset.json", screenshotPathInput = "rtlab_view.png";

  bool quit = false;
  std::vector<std::string> pendingScreenshots; // written after the next frame's UI is drawn
};

const char* debugModeName(DebugMode mode);
const char* compareModeName(CompareMode mode);
DebugMode parseDebugMode(const std::string& name);     // full|pip|off
CompareMode parseCompareMode(const std::string& name); // reference|snapshot|difference|off

} // namespace rtlab
