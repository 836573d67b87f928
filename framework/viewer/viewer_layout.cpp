#include "viewer/viewer_layout.h"

#include "viewer/viewer_state.h"

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

float panelLimitPx(int windowWidth) {
  return std::floor(kPanelMaxFraction * float(windowWidth));
}

} // namespace

ViewerLayout computeViewerLayout(int windowWidth, int windowHeight, bool showPanel, float panelWidthEm, float fontSize) {
  ViewerLayout l;
  const int panel = showPanel ? int(std::lround(std::clamp(panelWidthEm, kPanelWidthEmMin, 1e6f) * fontSize)) : 0;
  l.panel = {0, 0, std::min(panel, int(panelLimitPx(windowWidth))), windowHeight};
  l.frame = {l.panel.width, 0, std::max(windowWidth - l.panel.width, 1), windowHeight};
  // The bar: a strip 0.8 font sizes high, 3.5 above the frame's bottom edge, half the frame wide,
  // centred, leaving room for the min/max labels at its ends and the caption below it.
  const int barWidth = std::max(l.frame.width / 2, 1);
  const int barHeight = std::max(int(std::lround(fontSize * 0.8f)), 4);
  l.colorBar = {l.frame.x + (l.frame.width - barWidth) / 2,
                l.frame.y + l.frame.height - barHeight - int(std::lround(fontSize * 3.5f)), barWidth, barHeight};
  return l;
}

float panelWidthEmFor(float widthPx, int windowWidth, float fontSize) {
  const float px = std::min(widthPx, panelLimitPx(windowWidth));
  return std::max(px / std::max(fontSize, 1.0f), kPanelWidthEmMin);
}

} // namespace rtlab
