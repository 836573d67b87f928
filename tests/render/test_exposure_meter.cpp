// The viewer's exposure readout (viewer/window/exposure_meter.h): the GPU reduction over 16x16 tiles
// gives what the CPU definition (image/exposure.h) gives on the same linear colour, at a size that is
// not a multiple of the tile, and a new measurement is due only kInterval after the last start.
#include <gtest/gtest.h>

#include "frame/pass_timer.h"
#include "gl/debug.h"
#include "gl/state.h"
#include "image/exposure.h"
#include "render_fixture.h"
#include "viewer/window/exposure_meter.h"

#include <chrono>

namespace rtlab {
namespace {

TEST(ExposureMeter, GpuTilesMatchTheCpuReadout) {
  const TestFrame f = makeTestFrame("glow", "", {}, 100, 60);
  Renderer& renderer = *renderTestFrame(f, {}).renderer;
  FrameOutputs outputs;
  outputs.colors = {"hdr"};
  PassTimer timer(TimingMethod::CpuFinish);
  renderer.render(f.params, f.width, f.height, outputs, timer);
  const ExposureReadout cpu = measureExposure(renderer.readColor("hdr"));

  ExposureMeter meter(renderer.programs());
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_TRUE(meter.due(t0));
  EXPECT_FALSE(meter.poll().has_value()); // nothing started
  const gl::Texture* hdr = renderer.resource(renderer.colorVersionResource("hdr"));
  ASSERT_NE(hdr, nullptr);
  meter.start(*hdr, t0);
  EXPECT_EQ(gl::firstDifference(gl::captureState(), gl::knownState()), ""); // the next frame's start
  EXPECT_FALSE(meter.due(t0 + ExposureMeter::kInterval * 2)); // in flight
  const auto gpu = meter.poll(true);
  ASSERT_TRUE(gpu.has_value());
  EXPECT_EQ(drainGlErrors(), 0);
  EXPECT_EQ(gpu->pixels, 6000u);
  EXPECT_EQ(gpu->nonFinite, 0u);
  EXPECT_NEAR(gpu->logAverageLuminance, cpu.logAverageLuminance, 1e-5 * cpu.logAverageLuminance);
  EXPECT_NEAR(gpu->maxLuminance, cpu.maxLuminance, 1e-6 * cpu.maxLuminance); // float vs double weights
  EXPECT_NEAR(gpu->keyExposure, cpu.keyExposure, 1e-5 * cpu.keyExposure);
  EXPECT_FALSE(meter.poll().has_value()); // read once
  EXPECT_FALSE(meter.due(t0 + ExposureMeter::kInterval / 2));
  EXPECT_TRUE(meter.due(t0 + ExposureMeter::kInterval));
}

} // namespace
} // namespace rtlab
