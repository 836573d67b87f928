// viewer/viewer_layout: the frame's region is the window minus the side panel; the panel's width
// follows the font size (lecture mode) within its limits; hidden, the frame is the whole window;
// the colour bar lies inside the frame.
#include "viewer/viewer_layout.h"
#include "viewer/viewer_state.h"

#include <gtest/gtest.h>

using namespace rtlab;

TEST(ViewerLayout, FrameIsTheWindowBesideThePanel) {
  const ViewerLayout l = computeViewerLayout(1280, 720, true, kPanelWidthEmDefault, 15.0f);
  EXPECT_EQ(l.panel.width, 330); // 22 font sizes of 15 pixels
  EXPECT_EQ(l.frame.x, 330);
  EXPECT_EQ(l.frame.width, 1280 - 330);
  EXPECT_EQ(l.frame.height, 720);
  // Lecture mode's 30-pixel text: twice as wide, within half the window.
  const ViewerLayout lecture = computeViewerLayout(1280, 720, true, kPanelWidthEmDefault, 30.0f);
  EXPECT_EQ(lecture.panel.width, 640);
  EXPECT_EQ(lecture.frame.x + lecture.frame.width, 1280);
  const ViewerLayout small = computeViewerLayout(640, 360, true, kPanelWidthEmDefault, 30.0f);
  EXPECT_EQ(small.panel.width, 320) << "at most half the window";
}

TEST(ViewerLayout, HiddenPanelLeavesTheWholeWindowToTheFrame) {
  const ViewerLayout l = computeViewerLayout(1920, 1080, false, kPanelWidthEmDefault, 30.0f);
  EXPECT_EQ(l.panel.width, 0);
  EXPECT_EQ(l.frame.x, 0);
  EXPECT_EQ(l.frame.width, 1920);
  EXPECT_EQ(l.frame.height, 1080);
}

TEST(ViewerLayout, DraggedWidthsStayWithinTheLimits) {
  EXPECT_FLOAT_EQ(panelWidthEmFor(450.0f, 1280, 15.0f), 30.0f);
  EXPECT_FLOAT_EQ(panelWidthEmFor(10.0f, 1280, 15.0f), kPanelWidthEmMin);
  EXPECT_FLOAT_EQ(panelWidthEmFor(1000.0f, 1280, 20.0f), 32.0f); // half the window: 640 px
  const ViewerLayout l = computeViewerLayout(1280, 720, true, panelWidthEmFor(450.0f, 1280, 15.0f), 15.0f);
  EXPECT_EQ(l.panel.width, 450);
}

TEST(ViewerLayout, ColourBarLiesInsideTheFrame) {
  for (bool panel : {true, false}) {
    const ViewerLayout l = computeViewerLayout(320, 180, panel, kPanelWidthEmDefault, 15.0f);
    EXPECT_GE(l.colorBar.x, l.frame.x);
    EXPECT_LE(l.colorBar.x + l.colorBar.width, l.frame.x + l.frame.width);
    EXPECT_GE(l.colorBar.y, 0);
    EXPECT_LE(l.colorBar.y + l.colorBar.height, l.frame.height);
    EXPECT_GT(l.colorBar.width, 50);
  }
}
