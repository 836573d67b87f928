// The transparency reference (docs/contract.md "Transparency", framework/reference/
// transparency_reference.h): the fragment capture keeps every transparent fragment in front of the
// opaque surfaces, whatever the band size, and the CPU Over of what it captured equals the exact
// Over of known layers.
#include "app/reference_run.h"
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "known_layers.h"
#include "reference/transparency_reference.h"
#include "render_fixture.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rtlab {
namespace {

constexpr int kW = 160, kH = 90;

// Three overlapping layers (alpha 0.5, 0.3, 0.8), an opaque quad in front of part of them, and a
// layer behind that quad's region only partly.
const std::vector<KnownLayer> kLayers = {
    {2.0f, {-0.9f, -0.8f}, {0.3f, 0.6f}, {0.9f, 0.2f, 0.1f}, 0.5f},
    {3.0f, {-0.5f, -0.6f}, {0.6f, 0.8f}, {0.1f, 0.8f, 0.3f}, 0.3f},
    {4.5f, {-0.2f, -0.9f}, {0.9f, 0.4f}, {2.0f, 1.5f, 6.0f}, 0.8f},
    {1.5f, {0.45f, -0.95f}, {0.95f, -0.3f}, {0.05f, 0.05f, 0.3f}, 1.0f, true},
};
const glm::vec3 kBackdrop(0.2f, 0.3f, 0.4f);

TestFrame knownFrame() {
  TestFrame f;
  f.scene = makeKnownLayersScene("oit_known_reference", kLayers, kBackdrop, float(kW) / float(kH));
  f.params = makeParamSet(f.scene, TechniqueRegistry::instance());
  f.width = kW;
  f.height = kH;
  return f;
}

// NDC points inside each region of the layout (none on an edge).
const std::vector<glm::vec2> kProbes = {{-0.8f, 0.5f},  {-0.4f, 0.0f}, {0.0f, 0.0f},  {0.2f, -0.7f}, {0.5f, 0.7f},
                                        {0.7f, -0.1f},  {0.8f, 0.2f},  {0.7f, -0.6f}, {-0.95f, 0.9f}, {0.5f, 0.3f}};

TEST(TransparencyReference, EqualsExactOverOfKnownLayers) {
  const TestFrame f = knownFrame();
  TestRender r = renderTestFrame(f, {"transparency"});
  const Image ref = renderReferenceFrame(*r.renderer, resolvedOf(f), "transparency", 1, false);
  ASSERT_EQ(ref.width, kW);
  ASSERT_EQ(ref.channels, 3);
  for (const glm::vec2& ndc : kProbes) {
    const glm::ivec2 p = pixelAt(ndc, kW, kH);
    const glm::dvec3 want = exactOver(kLayers, kBackdrop, ndc);
    for (int c = 0; c < 3; ++c) {
      // The opaque colour is stored in RGBA16F (relative rounding 2^-11); the layers are captured in fp32.
      EXPECT_NEAR(ref.at(p.x, p.y, c), want[c], 1e-3 * (1.0 + std::abs(want[c])))
          << "ndc (" << ndc.x << ", " << ndc.y << ") channel " << c;
    }
    EXPECT_EQ(ref.mask[std::size_t(p.y) * kW + std::size_t(p.x)], 1.0f);
  }
}

TEST(TransparencyReference, CaptureKeepsOnlyFragmentsInFrontOfOpaqueSurfaces) {
  const TestFrame f = knownFrame();
  TestRender r = renderTestFrame(f, {"transparency"});
  FrameOutputs outputs;
  outputs.transparentFragments = true;
  PassTimer timer(TimingMethod::CpuFinish);
  r.renderer->render(f.params, kW, kH, outputs, timer);
  const CapturedFragments& captured = r.renderer->readTransparentFragments();
  std::vector<int> perPixel(std::size_t(kW) * kH, 0);
  for (const CapturedFragment& c : captured.fragments) ++perPixel[std::size_t(c.y) * kW + c.x];
  auto countAt = [&](glm::vec2 ndc) {
    const glm::ivec2 p = pixelAt(ndc, kW, kH);
    return perPixel[std::size_t(p.y) * kW + std::size_t(p.x)];
  };
  EXPECT_EQ(countAt({0.0f, 0.0f}), 3);     // all three layers
  EXPECT_EQ(countAt({-0.8f, 0.5f}), 1);    // the first only
  EXPECT_EQ(countAt({-0.95f, 0.9f}), 0);   // none
  EXPECT_EQ(countAt({0.7f, -0.6f}), 0);    // behind the opaque quad at depth 1.5: the third layer is hidden
  EXPECT_EQ(countAt({0.7f, -0.1f}), 1);    // the third layer beside the quad
  // Every captured fragment's radiance and alpha is one of the layers' (C = E exactly).
  for (const CapturedFragment& c : captured.fragments) {
    bool known = false;
    for (const KnownLayer& l : kLayers)
      known = known || (!l.opaque && c.alpha == l.alpha && c.r == l.emission.x && c.g == l.emission.y && c.b == l.emission.z);
    ASSERT_TRUE(known) << "fragment at (" << c.x << ", " << c.y << ")";
  }
}

// Capturing in many bands (a buffer limit of a few rows' fragments) gives the same fragments, and
// so the same reference, as one band.
TEST(TransparencyReference, BandsCaptureTheSameFragments) {
  const TestFrame f = makeTestFrame("layers", "", {}, kW, kH);
  TestRender r = renderTestFrame(f, {"transparency"});
  FrameOutputs outputs;
  outputs.transparentFragments = true;
  outputs.colors = {"lit"};
  PassTimer timer(TimingMethod::CpuFinish);
  r.renderer->render(f.params, kW, kH, outputs, timer);
  const CapturedFragments one = r.renderer->readTransparentFragments();
  const Image opaque = r.renderer->readColor("lit");
  EXPECT_EQ(one.bands, 1);
  ASSERT_GT(one.fragments.size(), std::size_t(kW) * kH); // layers: depth complexity up to 24

  outputs.captureBandBytes = 16 + 28 * std::size_t(kW) * 24 * 2; // about two rows of the deepest part
  r.renderer->render(f.params, kW, kH, outputs, timer);
  const CapturedFragments many = r.renderer->readTransparentFragments();
  EXPECT_GT(many.bands, 10);
  EXPECT_EQ(many.fragments.size(), one.fragments.size());
  const Image a = compositeOver(one, opaque), b = compositeOver(many, opaque);
  EXPECT_EQ(a.pixels, b.pixels);
}

} // namespace
} // namespace rtlab
