// The shadow terminator (docs/measuring.md, "The shading point"): on the built-in spheres the
// reference and the shadow techniques start from the same point of the smooth surface that the
// vertex normals describe, so neither shows the tessellation's faceted staircase where the shading
// normal turns away from the light, and the error near the terminator is no larger than elsewhere.
#include "render_fixture.h"
#include "scene_geometry.h"

#include "app/frame_options.h"
#include "app/reference_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace rtlab {
namespace {

constexpr int kWidth = 640, kHeight = 360;
constexpr int kSpp = 64;
// |n.l| below this on a sphere pixel is "near the terminator": about 6 degrees either side of it,
// wider than the angle between a facet's normal and its vertex normals on the built-in 48x24
// spheres (up to about 5 degrees), so the whole faceted staircase lies inside the band.
constexpr float kBand = 0.1f;

// Per pixel of the sphere (the mesh named "sphere"): the cosine between the exact sphere's normal
// at the G-buffer point and the direction toward light 0's centre; NaN elsewhere.
std::vector<float> sphereCosines(const ReferenceInput& in) {
  const Bounds bounds = test::instanceBounds(in.scene, "sphere");
  const glm::vec3 centre = bounds.center();
  const float radius = 0.5f * (bounds.max.x - bounds.min.x);
  const Light& light = in.scene.lights.front();
  std::vector<float> cosines(in.surfaces.pixelCount(), NAN);
  for (std::size_t i = 0; i < cosines.size(); ++i) {
    const glm::vec3 p = in.surfaces.position[i];
    if (!in.surfaces.valid[i] || std::abs(glm::length(p - centre) - radius) > 0.01f * radius) continue;
    const glm::vec3 toLight =
        light.type == LightType::Directional ? -light.direction : glm::normalize(light.position - p);
    cosines[i] = glm::dot(glm::normalize(p - centre), toLight);
  }
  return cosines;
}

struct TerminatorError {
  double errorShare = 0; // share of the frame's squared visibility error in the band
  double pixelShare = 0; // share of the frame's surface pixels in the band
  std::size_t bandPixels = 0;
};

TerminatorError measure(const std::string& scene, const std::string& technique, const std::vector<std::string>& sets) {
  TestFrame f = makeTestFrame(scene, technique, sets, kWidth, kHeight);
  TestRender r = renderTestFrame(f, {"visibility"});
  const Image visibility = r.renderer->readAov("visibility");
  const ResolvedFrame resolved = resolvedOf(f);
  const ReferenceInput in = referenceInput(*r.renderer, resolved);
  const Image reference = renderReferenceFrame(*r.renderer, resolved, "visibility", kSpp, false);
  const std::vector<float> cosines = sphereCosines(in);
  double total = 0, band = 0;
  std::size_t pixels = 0;
  TerminatorError e;
  for (std::size_t i = 0; i < cosines.size(); ++i) {
    if (reference.mask[i] < 0.5f) continue;
    const double d = double(visibility.pixels[i]) - double(reference.pixels[i]);
    total += d * d;
    ++pixels;
    if (std::abs(cosines[i]) < kBand) {
      band += d * d;
      ++e.bandPixels;
    }
  }
  e.errorShare = total > 0 ? band / total : 0.0;
  e.pixelShare = pixels ? double(e.bandPixels) / double(pixels) : 0.0;
  std::printf("%-10s %-8s terminator band: %zu px (%.2f%% of the frame), %.1f%% of the squared error\n",
              technique.c_str(), scene.c_str(), e.bandPixels, 100.0 * e.pixelShare, 100.0 * e.errorShare);
  return e;
}

TEST(Terminator, ErrorNearTheTerminatorDoesNotDominate) {
  // On contact the band is 0.22% of the surface pixels. Measured (pcss, 640x360, llvmpipe, the
  // same definition computed from the CLI's images): before the rule it held 40% of the frame's
  // squared visibility error; with it 17%, what is left being pcss's own filtering of the
  // sphere's silhouette in its map. The bound 25% lies between the two.
  const TerminatorError e = measure("contact", "pcss", {});
  ASSERT_GT(e.bandPixels, std::size_t(200)) << "the sphere's terminator should be in view";
  EXPECT_LT(e.errorShare, 0.25);
}

TEST(Terminator, ReferenceFollowsTheSmoothSurface) {
  // A light of size zero: the reference is exactly 0 or 1. Off a thin margin around the
  // terminator of the exact sphere, it must be lit where the sphere faces the light and dark
  // where it faces away, whichever way the facets there face. Nothing else shadows the sphere in
  // contact. Measured at 640x360: 24 of the sphere's 2847 pixels disagree before the rule, 0 with it.
  TestFrame f = makeTestFrame("contact", "", {"light0.radius=0"}, kWidth, kHeight);
  const ResolvedFrame resolved = resolvedOf(f);
  Renderer& renderer = *renderTestFrame(f, {"depth"}).renderer;
  const ReferenceInput in = referenceInput(renderer, resolved);
  const Image reference = renderReferenceFrame(renderer, resolved, "visibility", 1, false);
  const std::vector<float> cosines = sphereCosines(in);
  std::size_t sphere = 0, wrong = 0;
  for (std::size_t i = 0; i < cosines.size(); ++i) {
    if (std::isnan(cosines[i]) || std::abs(cosines[i]) < 0.02f) continue;
    ++sphere;
    if ((reference.pixels[i] > 0.5f) != (cosines[i] > 0.0f)) ++wrong;
  }
  std::printf("contact sphere: %zu of %zu pixels off the smooth terminator\n", wrong, sphere);
  ASSERT_GT(sphere, std::size_t(2000));
  EXPECT_EQ(wrong, std::size_t(0));
}

} // namespace
} // namespace rtlab
