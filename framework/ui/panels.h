// The viewer's side panel (Dear ImGui), drawn from the declarations: the stage table, the
// technique registry and each ParamSpec. Panels change the state only through the viewer's
// actions (viewer/viewer_actions.h); a rejected edit shows its message in the status line.
#pragma once
#include "ui/param_widgets.h"
#include "viewer/viewer_state.h"

#include <functional>
#include <vector>

namespace rtlab {

// The whole panel: a window docked to the left edge with collapsing sections.
void drawViewerPanel(ViewerState& state);

// The top-right corner: frame time (and its method), render size, and in compare mode the
// reference's sample count with the live RMSE and FLIP.
void drawInfoOverlay(const ViewerState& state, int renderWidth, int renderHeight);
// Lecture mode's caption: the current bookmark's name in large text at the bottom of the window.
void drawLectureCaption(const ViewerState& state);

// Sections (each in its own file).
void drawScenePanel(ViewerState& state);     // scene picker, presets, bookmarks    (scene_panel.cpp)
void drawLightPanel(ViewerState& state);     // light<N>.* keys                     (scene_panel.cpp)
void drawTechniquePanel(ViewerState& state); // per stage: selector with off, params (technique_panel.cpp)
void drawTonemapPanel(ViewerState& state);   // tonemap.* keys                      (technique_panel.cpp)
void drawViewPanel(ViewerState& state);      // debug view, render scale            (view_panel.cpp)
void drawComparePanel(ViewerState& state);   // compare mode, divider, live metrics  (view_panel.cpp)
void drawTimingsPanel(ViewerState& state);   // per-pass ms, method, history graph  (timings_panel.cpp)

// Runs an action, putting an Error's message in the status line instead of throwing.
void runGuarded(ViewerState& state, const std::function<void()>& action);
// Applies parameter edits through setParamValueAction.
void applyEdits(ViewerState& state, const std::vector<ParamEdit>& edits);

} // namespace rtlab
