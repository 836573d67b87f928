// abuffer (techniques/abuffer/README.md): exact Over of every fragment against a CPU computation on
// a scene of known camera-facing layers, independence of the draw order, the neutral case (all
// alpha 0), max_fragments overflow counted and shown, bands and pool growth leaving the image
// unchanged, extreme layers staying finite, and nothing at all on an opaque-only scene.
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "gl/debug.h"
#include "params/param_set.h"
#include "known_layers.h"
#include "render_fixture.h"
#include "scene/load.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace rtlab {
namespace {

constexpr int kW = 160, kH = 90;

const TechniqueRegistry& registry() {
  static const TechniqueRegistry r = [] {
    TechniqueRegistry t;
    registerAllTechniques(t);
    return t;
  }();
  return r;
}

struct Rig {
  Renderer renderer{registry()};
  ParamSet params;
  explicit Rig(const Scene& scene) {
    testContext().makeCurrent();
    renderer.setScene(scene);
    params = makeParamSet(scene, registry());
  }
  void set(const std::string& key, const std::string& value) { params.setText(key, value); }
  void render(const std::vector<std::string>& techniques, const std::vector<std::string>& aovs, int frames = 1) {
    FrameOutputs outputs;
    outputs.aovs = aovs;
    outputs.colors = {"lit", "pre_post"};
    for (int i = 0; i < frames; ++i) renderOwnFrame(renderer, params, techniques, outputs, kW, kH);
  }
  double counter(const std::string& name) const { return techniqueCounter(renderer, "abuffer", name); }
};

// A layer over the pixel rectangle [x0, x1) x [y0, y1) (rows top to bottom) at view depth z, as a
// KnownLayer (known_layers.h: black base colour, emission E, no light, no ambient: C = E exactly).
// Edges lie on pixel boundaries, so every pixel centre is clearly inside or outside.
struct Layer {
  float z;
  int x0, x1, y0, y1;
  float alpha;
  glm::vec3 emission;
  bool opaque = false;
  bool covers(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

Scene layerScene(const std::vector<Layer>& layers) {
  std::vector<KnownLayer> known;
  for (const Layer& l : layers) {
    KnownLayer k;
    k.depth = l.z;
    k.ndcMin = {-1.0f + 2.0f * float(l.x0) / float(kW), 1.0f - 2.0f * float(l.y1) / float(kH)};
    k.ndcMax = {-1.0f + 2.0f * float(l.x1) / float(kW), 1.0f - 2.0f * float(l.y0) / float(kH)};
    k.emission = l.emission;
    k.alpha = l.alpha;
    k.opaque = l.opaque;
    known.push_back(k);
  }
  return makeKnownLayersScene("abuffer_known_layers", known, {0.2f, 0.3f, 0.4f}, float(kW) / float(kH));
}

// Nine overlapping layers (high alpha in front of low, an HDR emitter, one drawn out of depth
// order) and an opaque square at depth 4.5 that hides the layers behind it.
std::vector<Layer> knownLayers() {
  return {
      {1.0f, 10, 90, 10, 70, 0.9f, {1.0f, 1.0f, 1.0f}},
      {2.0f, 30, 120, 20, 80, 0.2f, {1.0f, 0.1f, 0.1f}},
      {3.0f, 50, 150, 5, 60, 0.35f, {0.1f, 1.0f, 0.2f}},
      {4.0f, 20, 140, 30, 88, 0.5f, {0.1f, 0.2f, 1.0f}},
      {5.0f, 0, 100, 0, 50, 0.15f, {30.0f, 12.0f, 2.0f}},
      {6.0f, 60, 160, 40, 90, 0.6f, {0.8f, 0.8f, 0.1f}},
      {8.0f, 5, 155, 15, 75, 0.25f, {0.3f, 0.9f, 0.9f}},
      {4.5f, 100, 130, 10, 40, 1.0f, {0.05f, 0.05f, 0.05f}, true}, // opaque
      {7.0f, 70, 110, 25, 65, 0.45f, {0.9f, 0.2f, 0.7f}},
      // Off to the side: its centre is farther from the eye than that of the layer at depth 4, so
      // the back-to-front draw puts it first and the lists come unsorted where the two overlap.
      {3.5f, 135, 160, 0, 90, 0.3f, {0.5f, 0.5f, 1.0f}},
  };
}

// Over of the `keep` nearest layers covering (x, y) in front of the opaque surface there, in
// double precision onto `opaque` (the frame's own opaque colour), and the number of layers there
// (known_layers.h's exactOver composites all of them; this one keeps the nearest `keep`).
glm::dvec3 overOfNearest(const std::vector<Layer>& layers, int x, int y, const glm::dvec3& opaque, int keep, int* depth) {
  float opaqueZ = 1e30f;
  for (const auto& l : layers)
    if (l.opaque && l.covers(x, y)) opaqueZ = std::min(opaqueZ, l.z);
  std::vector<const Layer*> here;
  for (const auto& l : layers)
    if (!l.opaque && l.covers(x, y) && l.z < opaqueZ) here.push_back(&l);
  std::sort(here.begin(), here.end(), [](const Layer* a, const Layer* b) { return a->z < b->z; });
  *depth = int(here.size());
  if (int(here.size()) > keep) here.resize(std::size_t(keep));
  glm::dvec3 result = opaque;
  for (auto it = here.rbegin(); it != here.rend(); ++it)
    result = double((*it)->alpha) * glm::dvec3((*it)->emission) + (1.0 - double((*it)->alpha)) * result;
  return result;
}

// The A-buffer equals the exact Over. Its error comes only from 16-bit floats: each node stores
// a*C and a as fp16 (relative error <= 2^-11 each), the n coverages' rounding multiplies into the
// transmittance, and the output is RGBA16F (2^-11 once more): so |got - want| <= (n + 2) 2^-11 want
// (+1e-6 for zeros). With max_fragments = 3 it equals the Over of the 3 nearest layers, and the
// dropped count is the sum over pixels of max(0, n - 3).
TEST(Abuffer, EqualsExactOverOfKnownLayers) {
  const std::vector<Layer> layers = knownLayers();
  Rig r(layerScene(layers));
  for (const int keep : {32, 3}) {
    r.set("abuffer.max_fragments", std::to_string(keep));
    r.render({"abuffer"}, {"abuffer.complexity"});
    const Image lit = r.renderer.readColor("lit"), got = r.renderer.readColor("pre_post");
    const Image complexity = r.renderer.readAov("abuffer.complexity");
    double dropped = 0, worst = 0;
    int maxDepth = 0, covered = 0, outside = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const glm::dvec3 opaque(lit.at(x, y, 0), lit.at(x, y, 1), lit.at(x, y, 2));
        int n = 0;
        const glm::dvec3 want = overOfNearest(layers, x, y, opaque, keep, &n);
        ASSERT_EQ(complexity.at(x, y, 0), float(n)) << x << "," << y;
        dropped += std::max(0, n - keep);
        maxDepth = std::max(maxDepth, n);
        covered += n > 0;
        bool within = true;
        for (int c = 0; c < 3; ++c) {
          const double err = std::abs(double(got.at(x, y, c)) - want[c]);
          within = within && err <= double(std::min(n, keep) + 2) * std::ldexp(1.0, -11) * want[c] + 1e-6;
          if (within) worst = std::max(worst, err / std::max(want[c], 1e-3));
        }
        outside += within ? 0 : 1;
        EXPECT_TRUE(within) << "pixel " << x << "," << y << " keep " << keep << " layers " << n;
      }
    RecordProperty("pixels_outside_fp16_bound_keep" + std::to_string(keep), outside);
    RecordProperty("worst_relative_error_keep" + std::to_string(keep), std::to_string(worst));
    EXPECT_GT(covered, kW * kH / 2);
    EXPECT_GE(maxDepth, 6);
    EXPECT_EQ(r.counter("max_depth_complexity"), double(maxDepth));
    EXPECT_EQ(r.counter("dropped_fragments"), dropped) << "keep " << keep;
    if (keep == 3) {
      EXPECT_GT(dropped, 1000.0);
    }
  }
}

// The order the GPU appends fragments in is not the result's. SceneGpu draws transparent
// instances back to front by their centres (a stable sort), so shuffling the scene's instances
// changes the draw order of instances at equal distances: here two coplanar layers over the same
// rectangle, whose Over differs with their order. The image is the same bit for bit: equal depths
// are ordered by the packed colour (node.glsl abufferInFront), not by arrival.
TEST(Abuffer, InvariantToDrawOrder) {
  std::vector<Layer> layers = knownLayers();
  // Coplanar with layer 2 over the same rectangle: the same distance from the eye, so the shuffle
  // changes which of the two is drawn (and appended) first.
  layers.push_back({3.0f, 50, 150, 5, 60, 0.4f, {0.6f, 0.3f, 0.1f}});
  const Scene scene = layerScene(layers);
  Image first;
  std::mt19937 rng(7);
  for (int trial = 0; trial < 4; ++trial) {
    Scene shuffled = scene;
    if (trial > 0) std::shuffle(shuffled.instances.begin(), shuffled.instances.end(), rng);
    Rig r(shuffled);
    r.render({"abuffer"}, {});
    const Image got = r.renderer.readColor("pre_post");
    if (trial == 0) {
      first = got;
      continue;
    }
    EXPECT_EQ(got.pixels, first.pixels) << "shuffle " << trial;
  }
}

// All coverages 0: every fragment is kept, and contributes nothing: the colour is the opaque
// colour exactly (T stays 1, the sum 0).
TEST(Abuffer, AllAlphaZeroGivesTheOpaqueImageExactly) {
  std::vector<Layer> layers = knownLayers();
  for (auto& l : layers)
    if (!l.opaque) l.alpha = 0.0f;
  Rig r(layerScene(layers));
  r.render({"abuffer"}, {"abuffer.complexity"});
  EXPECT_EQ(r.renderer.readColor("pre_post").pixels, r.renderer.readColor("lit").pixels);
  EXPECT_GE(r.counter("max_depth_complexity"), 6.0);
}

// `layers` has up to 24 layers a pixel: with max_fragments 4 the resolve drops the farthest, the
// count in stats is the sum over pixels of max(0, complexity - 4), and the dropped view shows
// max(0, complexity - 4) per pixel. The nodes counter is the sum of the complexities.
TEST(Abuffer, OverflowIsCountedAndShown) {
  Rig r(loadScene("layers"));
  r.set("abuffer.max_fragments", "4");
  r.render({"abuffer"}, {"abuffer.complexity", "abuffer.dropped"});
  const Image complexity = r.renderer.readAov("abuffer.complexity"), dropped = r.renderer.readAov("abuffer.dropped");
  double sumDropped = 0, sumNodes = 0, deepest = 0;
  for (std::size_t i = 0; i < complexity.pixelCount(); ++i) {
    const double n = complexity.pixels[i * std::size_t(complexity.channels)];
    const double d = dropped.pixels[i * std::size_t(dropped.channels)];
    ASSERT_EQ(d, std::max(0.0, n - 4.0)) << i;
    sumDropped += d;
    sumNodes += n;
    deepest = std::max(deepest, n);
  }
  EXPECT_EQ(deepest, 24.0);
  EXPECT_GT(sumDropped, 10000.0);
  EXPECT_EQ(r.counter("dropped_fragments"), sumDropped);
  EXPECT_EQ(r.counter("nodes"), sumNodes);
  EXPECT_EQ(r.counter("max_depth_complexity"), deepest);
  EXPECT_EQ(r.counter("pool_dropped_fragments"), 0.0);
}

// A pool budget of 64 KiB (4096 nodes) against the ~100k fragments of `layers` at 160x90: the frame
// is built and resolved in bands (and bands that overflow are split within the frame), the image
// is the same bit for bit as with one band, and nothing is dropped. The first frame with the
// default budget starts from 4 nodes a pixel and grows the pool (a rebuild) to fit.
TEST(Abuffer, BandsAndPoolGrowthLeaveTheImageUnchanged) {
  Rig r(loadScene("layers"));
  r.render({"abuffer"}, {});
  EXPECT_EQ(r.counter("bands"), 1.0);
  EXPECT_GE(r.counter("rebuilds"), 1.0) << "4 nodes a pixel do not hold the layers: the pool grows";
  const double nodes = r.counter("nodes");
  EXPECT_GT(nodes, 4.0 * kW * kH);
  EXPECT_GE(r.counter("pool_nodes"), nodes);
  const Image one = r.renderer.readColor("pre_post");
  r.set("abuffer.pool_mib", "0.0625");
  for (int frame = 0; frame < 2; ++frame) { // the first frame splits, the second plans from its count
    r.render({"abuffer"}, {});
    EXPECT_EQ(r.renderer.readColor("pre_post").pixels, one.pixels) << "frame " << frame;
    EXPECT_GT(r.counter("bands"), 20.0);
    EXPECT_EQ(r.counter("nodes"), nodes);
    EXPECT_EQ(r.counter("pool_dropped_fragments"), 0.0);
    EXPECT_EQ(r.counter("dropped_fragments"), 0.0);
    EXPECT_EQ(r.counter("pool_nodes"), 4096.0);
  }
  bool owned = false;
  for (const auto& res : r.renderer.resources()) {
    if (res.name != "abuffer.owned") continue;
    owned = true;
    EXPECT_EQ(res.bytes, 4096u * 16u + 8u);
  }
  EXPECT_TRUE(owned);
}

// 24 full-frame layers of C = 1 and alpha = 1: the nearest hides the rest, the colour is 1,
// finite (no overflow from summing), and max_fragments 24 keeps them all.
TEST(Abuffer, TwentyFourOpaqueLayersStayFinite) {
  std::vector<Layer> layers;
  for (int k = 0; k < 24; ++k) layers.push_back({1.0f + 2.0f * float(k), 0, kW, 0, kH, 1.0f, glm::vec3(1.0f)});
  Rig r(layerScene(layers));
  r.set("abuffer.max_fragments", "24");
  r.render({"abuffer"}, {});
  for (float v : r.renderer.readColor("pre_post").pixels) ASSERT_EQ(v, 1.0f);
  EXPECT_EQ(r.counter("max_depth_complexity"), 24.0);
  EXPECT_EQ(r.counter("dropped_fragments"), 0.0);
}

// Without transparent materials the transparency stage does not run: no abuffer pass and no
// abuffer resource, and the pool of an earlier transparent scene is freed with it.
TEST(Abuffer, OpaqueOnlySceneHasNoPassOrResource) {
  Rig r(loadScene("layers"));
  r.render({"abuffer"}, {});
  const Scene contact = loadScene("contact");
  r.renderer.setScene(contact);
  r.params = makeParamSet(contact, registry());
  r.render({"abuffer"}, {"color"});
  for (const auto& p : r.renderer.lastPasses()) EXPECT_EQ(p.name.rfind("abuffer", 0), std::string::npos) << p.name;
  for (const auto& res : r.renderer.resources()) EXPECT_EQ(res.name.rfind("abuffer", 0), std::string::npos) << res.name;
}

} // namespace
} // namespace rtlab
