// The viewer window's layout (docs/viewer.md "Window, camera and keys"): the side panel on the
// left, the frame in the region beside it. The frame is rendered at that region's size (times the
// render scale), so the camera's aspect follows the region and no part of the frame lies under
// the panel. GL-free, unit-tested.
#pragma once

namespace rtlab {

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0; // pixels, origin top left
};

struct ViewerLayout {
  PixelRect panel; // width 0 when the panel is hidden
  PixelRect frame; // the rest of the window
  PixelRect colorBar; // inside the frame, at its bottom: where the false-color scale is drawn
};

// The panel is `panelWidthEm` font sizes wide, at least kPanelWidthEmMin font sizes and at most
// kPanelMaxFraction of the window (viewer_state.h); hidden, the frame fills the window. All
// sizes in framebuffer pixels; `fontSize` too.
ViewerLayout computeViewerLayout(int windowWidth, int windowHeight, bool showPanel, float panelWidthEm, float fontSize);

// The panel width in font sizes that a drag to `widthPx` asks for, limited as above.
float panelWidthEmFor(float widthPx, int windowWidth, float fontSize);

} // namespace rtlab
