// Everything the lecture viewer (`rtlab view`) shows and edits, in one place: the scene, the
// parameters and active techniques, the debug view, the compare mode, render scale, lecture
// mode, and what the last frames measured. The UI panels and the script runner change it only
// through the actions of viewer_actions.h, so both behave the same.
#pragma once
#include "frame/selection.h"
#include "image/exposure.h"
#include "params/param_set.h"
#include "scene/scene.h"
#include "viewer/bookmarks.h"
#include "viewer/camera_controller.h"
#include "viewer/viewer_layout.h"

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

inline constexpr float kPanelWidthEmDefault = 22.0f; // the panel's default width, in font sizes
inline constexpr float kPanelWidthEmMin = 8.0f;      // the narrowest the panel can be dragged
inline constexpr float kPanelMaxFraction = 0.5f;     // the widest: this fraction of the window

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

  // Layout (docs/viewer.md "Window, camera and keys"): the panel is a side region left of the
  // frame, resizable by dragging its right edge and hidden with Tab, the panel's button or a
  // script's "panel" action; the frame is rendered at the size of the region beside it.
  bool showPanel = true;
  float panelWidthEm = kPanelWidthEmDefault; // the panel's width in font-size units (follows lecture mode)
  // Sections (panel headers) to open (true) or close (false) at the next panel draw, by name
  // (viewerSectionNames()); scripts' "section" action and bookmarks' "sections" fill it.
  std::vector<std::pair<std::string, bool>> sectionRequests;
  std::vector<std::string> openSections; // the sections open at the last panel draw (for reports)
  ViewerLayout layout; // this frame's panel, frame and colour-bar regions (framebuffer pixels)

  // Measured.
  long frames = 0;                       // frames rendered since start
  long glErrors = 0;                     // GL errors counted over every frame
  std::vector<PassTiming> passes;        // the last frame's passes
  double frameMs = 0.0;                  // the last frame's total, by the timing method
  std::deque<float> frameHistory;        // recent frame totals (ms) for the history graph
  std::string timingMethod;              // "cpu-finish" | "gpu-query"
  // The exposure readout of a recent frame's linear colour (docs/viewer.md "Exposure readout"),
  // measured a few times per second; empty until the first one is read back.
  std::optional<ExposureReadout> exposure;
  std::vector<std::string> shaderErrors; // file:line messages of failed (re)compiles
  std::string status;                    // the last action's message for the status line
  // The status is transient (a confirmation such as "screenshot a.png" or "bookmark 2/6"): it
  // is left out of every frame written to a file (screenshots, recorded frames). Errors are not.
  bool statusTransient = false;

  // Compare mode's reference (reference_view.h): which AOV, how far it is, and the live metrics of
  // the visible frame against it (empty until computed).
  struct {
    std::string aov;
    int samples = 0;      // the progressive mean's spp; a one-shot reference's spp once computed
    bool running = false; // refining, or (one-shot) computing
    bool exact = false;   // a one-shot reference that does not sample (bloom): complete once computed
    double seconds = 0.0; // a one-shot reference's compute time, once computed
    std::optional<double> rmse, flip;
    int metricsSamples = 0; // the reference's spp when the metrics were computed
    std::string waiting;    // why there are no metrics yet ("reference: 8 / 16 spp")
    std::string error;
  } reference;
  bool snapshotRequested = false; // freeze the current picture as compare side B

  // The scale bar under a data view (a debug view, a reference wipe of data, the difference heat
  // map), drawn at layout.colorBar by the frame and labelled by the overlay: what the last frame
  // showed.
  struct {
    bool shown = false;
    bool falseColor = false; // the false-color ramp, else gray
    float min = 0.0f, max = 1.0f;
    std::string label; // what the values are ("visibility", "|frame - reference|")
  } colorBar;
  // The wipe's two halves as the overlay labels them (empty when no wipe is shown).
  std::string wipeLeft, wipeRight;

  // Text fields of the panels.
  std::string scenePathInput, presetPathInput = "rtlab_preset.json", screenshotPathInput = "rtlab_view.png";

  bool quit = false;
  std::vector<std::string> pendingScreenshots; // written after the next frame's UI is drawn
  std::string recordDir;                       // a script's "record": every frame drawn is written there
  long recordedFrames = 0;                     // frames written since "record" started
};

// Sets the status line: `transient` for confirmations, false for errors and warnings.
void setStatus(ViewerState& state, std::string message, bool transient);

const char* debugModeName(DebugMode mode);
const char* compareModeName(CompareMode mode);
DebugMode parseDebugMode(const std::string& name);     // full|pip|off
CompareMode parseCompareMode(const std::string& name); // reference|snapshot|difference|off

} // namespace rtlab
