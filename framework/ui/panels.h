// The viewer's side panel (Dear ImGui), drawn from the declarations: the stage table, the
// technique registry and each ParamSpec. Panels change the state only through the viewer's
// actions (viewer/viewer_actions.h); a rejected edit shows its message in the status line.
#pragma once
#include "ui/param_widgets.h"
#include "viewer/viewer_state.h"

#include <functional>
#include <vector>

namespace rtlab {

// The whole panel: a window filling state.layout.panel, resizable at its right edge, with
// collapsing sections (and speaker notes in lecture mode); hidden, a button to show it again
// when the mouse is at the window's top left. `showTransient`: false in a frame that goes to a
// file, which then shows no confirmation status ("screenshot a.png").
void drawViewerPanel(ViewerState& state, bool showTransient, int windowWidth);

// What is drawn on the frame's region, never over the panel: the top-right info (frame time,
// render size, live RMSE and FLIP), the wipe's two labels, the colour bar's min/max and name, and
// lecture mode's caption (the bookmark's name) at the bottom right; text wraps to the region.
void drawFrameOverlays(const ViewerState& state, int renderWidth, int renderHeight);

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
