// A reference gets what it declares and nothing else (app/reference_run.h, docs/measuring.md
// "References per stage"): surface points of the frame's G-buffer only with SurfacePoints, the
// scene's materials only with Materials, the colour before post only with PrePostColor; the
// process-wide registry holds the three built-ins.
#include "app/reference_run.h"
#include "render_fixture.h"
#include "util/error.h"

#include <gtest/gtest.h>

namespace rtlab {
namespace {

ReferenceEntry probe(FrameInputs inputs) {
  ReferenceEntry e;
  e.aov = "probe";
  e.stage = "post";
  e.inputs = inputs;
  e.keys = {"light<N>.", "camera."};
  return e;
}

// What a probe reference saw of its frame.
struct Seen {
  bool hasSurfaces = false;
  int surfaceWidth = 0, surfaceHeight = 0;
  std::size_t validPixels = 0;
  std::vector<Material> materials;
  std::size_t textures = 0;
};

Seen runProbe(FrameInputs inputs, const TestFrame& f) {
  Seen seen;
  ReferenceEntry e = probe(inputs);
  e.compute = [&seen](const ReferenceFrame& frame, ReferenceStats&) {
    try {
      const SurfaceData& s = frame.surfaces();
      seen.hasSurfaces = true;
      seen.surfaceWidth = s.width;
      seen.surfaceHeight = s.height;
      for (auto v : s.valid) seen.validPixels += v;
    } catch (const Error&) {
    }
    seen.materials = frame.scene().materials;
    seen.textures = frame.scene().textures.size();
    return Image(1, 1, 1);
  };
  TestRender r = renderTestFrame(f, {"visibility"});
  ReferenceStats stats;
  renderReferenceFrame(*r.renderer, resolvedOf(f), e, 1, false, stats);
  return seen;
}

TEST(ReferenceInputs, SurfacePointsAndMaterialsOnlyWhenDeclared) {
  const TestFrame f = makeTestFrame("cornell", "", {}, 48, 32);
  ASSERT_GT(f.scene.materials.size(), 1u);

  const Seen points = runProbe({FrameInput::SurfacePoints}, f);
  EXPECT_TRUE(points.hasSurfaces);
  EXPECT_EQ(points.surfaceWidth, 48);
  EXPECT_EQ(points.surfaceHeight, 32);
  EXPECT_GT(points.validPixels, 0u);
  ASSERT_EQ(points.materials.size(), f.scene.materials.size()); // same indices, default values
  for (const auto& m : points.materials) EXPECT_EQ(m.baseColor, Material{}.baseColor);
  EXPECT_EQ(points.textures, 0u);

  const Seen materials = runProbe({FrameInput::Materials}, f);
  EXPECT_FALSE(materials.hasSurfaces);
  ASSERT_EQ(materials.materials.size(), f.scene.materials.size());
  bool coloured = false; // cornell's red and green walls
  for (std::size_t i = 0; i < f.scene.materials.size(); ++i) {
    EXPECT_EQ(materials.materials[i].baseColor, f.scene.materials[i].baseColor);
    coloured = coloured || materials.materials[i].baseColor != Material{}.baseColor;
  }
  EXPECT_TRUE(coloured);
}

// A reference that declares PrePostColor receives the frame's colour before the post stage: with no
// post technique that is the final linear colour, the AOV `color` of the same frame, pixel for
// pixel (panes: the transparent layers are composited before post, so this is not just `lit`).
TEST(ReferenceInputs, PrePostColorIsTheFramesColourBeforePost) {
  const TestFrame f = makeTestFrame("panes", "", {}, 64, 40);
  Image seen;
  ReferenceEntry e = probe({FrameInput::PrePostColor});
  e.compute = [&seen](const ReferenceFrame& frame, ReferenceStats&) {
    EXPECT_THROW(frame.surfaces(), Error); // not declared
    seen = frame.prePostColor();
    return Image(1, 1, 1);
  };
  ReferenceStats stats;
  TestRender probeRender = renderTestFrame(f, {"color"});
  renderReferenceFrame(*probeRender.renderer, resolvedOf(f), e, 1, false, stats);
  ASSERT_EQ(seen.width, 64);
  ASSERT_EQ(seen.height, 40);
  ASSERT_EQ(seen.channels, 3);

  TestRender r = renderTestFrame(f, {"color"});
  const Image color = r.renderer->readAov("color");
  ASSERT_EQ(color.pixels.size(), seen.pixels.size());
  double sum = 0;
  for (std::size_t i = 0; i < color.pixels.size(); ++i) {
    ASSERT_EQ(seen.pixels[i], color.pixels[i]) << "value " << i;
    sum += seen.pixels[i];
  }
  EXPECT_GT(sum, 0.0); // a lit frame, not an empty image
}

TEST(ReferenceInputs, TheProcessRegistryHoldsTheBuiltins) {
  const ReferenceRegistry& r = ReferenceRegistry::instance();
  EXPECT_EQ(r.choices(), "visibility, ao, indirect, transparency, arealight, bloom");
  for (const char* stage : {"shadow", "ao", "indirect", "transparency", "arealight", "post"}) EXPECT_NE(r.findStage(stage), nullptr) << stage;
}

} // namespace
} // namespace rtlab
