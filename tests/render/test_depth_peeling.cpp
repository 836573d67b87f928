// depth_peeling (techniques/depth_peeling/README.md): exact Over of the front-most layers against a
// CPU computation on a scene of known camera-facing layers, what too few layers lose, independence
// from the draw order, the extremes (all alpha 0; 24 layers of alpha 1), the tail blend against the
// drop on `layers`, its debug views and counters, and that it costs nothing where it does not run.
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "gl/debug.h"
#include "known_layers.h"
#include "render_fixture.h"
#include "scene/load.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace rtlab {
namespace {

constexpr int kW = 160, kH = 90;
const glm::vec3 kOpaque(0.2f, 0.3f, 0.4f); // the backdrop's emission: C_opaque

// A known-layers scene (known_layers.h) whose layers are drawn in the order given. SceneGpu sorts
// transparent instances back to front by the distance of their bounds' centre from the eye, so
// shuffling the instances alone would not change the draw order; every layer's mesh gets the same
// bounds here, the sort ties, and its stable order is the scene's instance order.
Scene knownScene(const std::string& name, const std::vector<KnownLayer>& layers) {
  Scene s = makeKnownLayersScene(name, layers, kOpaque, float(kW) / float(kH));
  Bounds common;
  common.extend({-20, -20, -30});
  common.extend({20, 20, 0});
  for (const auto& inst : s.instances)
    if (inst.transparent) s.meshes[std::size_t(inst.mesh)].bounds = common;
  return s;
}

// Four layers at depths 2..5, nested so that NDC x in [-0.9 + 0.45 i, -0.45 + 0.45 i] is covered by
// layers 0..i: depth complexity 1 to 4 from left to right. HDR emissions, alphas from 0.3 to 0.8.
std::vector<KnownLayer> fourLayers() {
  auto layer = [](float depth, float x0, glm::vec3 emission, float alpha) {
    return KnownLayer{depth, {x0, -0.8f}, {1.2f, 0.8f}, emission, alpha};
  };
  return {layer(2.0f, -0.9f, {3.0f, 0.5f, 0.1f}, 0.3f), layer(3.0f, -0.45f, {0.1f, 2.0f, 0.3f}, 0.6f),
          layer(4.0f, 0.0f, {0.2f, 0.1f, 5.0f}, 0.45f), layer(5.0f, 0.45f, {1.0f, 1.0f, 0.2f}, 0.8f)};
}

std::vector<KnownLayer> inOrder(const std::vector<KnownLayer>& layers, const std::vector<int>& order) {
  std::vector<KnownLayer> out;
  for (int i : order) out.push_back(layers[std::size_t(i)]);
  return out;
}

// The centre of the region covered by layers 0..region (NDC), and its pixel.
glm::vec2 regionNdc(int region) { return {-0.9f + 0.45f * float(region) + 0.225f, 0.0f}; }
glm::ivec2 regionPixel(int region) { return pixelAt(regionNdc(region), kW, kH); }

// Exact Over (known_layers.h exactOver, double precision) at region `region` of the front-most
// `count` layers covering it.
glm::dvec3 cpuOver(const std::vector<KnownLayer>& layers, int region, int count) {
  std::vector<KnownLayer> front(layers.begin(), layers.begin() + std::min(region + 1, count));
  return exactOver(front, kOpaque, regionNdc(region));
}

// fp16 rounding: the opaque colour, each layer's a*C and the output are stored in RGBA16F
// (relative step 2^-11 = 4.9e-4 each); the accumulation is RGBA32F. Four roundings at most.
double fp16Tolerance(double value) { return 2e-3 * std::abs(value) + 1e-6; }

// One renderer for the whole file (the counting frame and colour versions need FrameOutputs the
// shared fixture does not pass): its program cache saves the shader JIT between tests and scenes.
// Released by the test environment's tear-down, before the context goes.
std::unique_ptr<Renderer>& sharedRenderer() {
  static std::unique_ptr<Renderer> renderer;
  return renderer;
}
class ReleaseSharedRenderer : public ::testing::Environment {
  void TearDown() override { sharedRenderer().reset(); }
};
[[maybe_unused]] ::testing::Environment* const kRelease = ::testing::AddGlobalTestEnvironment(new ReleaseSharedRenderer);

// The shared renderer with `scene` set and its default parameters.
struct PeelRenderer {
  Renderer& renderer;
  ParamSet params;
  explicit PeelRenderer(const Scene& scene) : renderer(shared()) {
    renderer.setScene(scene);
    params = makeParamSet(scene, TechniqueRegistry::instance());
  }
  static Renderer& shared() {
    testContext().makeCurrent();
    auto& r = sharedRenderer();
    if (!r) r = std::make_unique<Renderer>(TechniqueRegistry::instance());
    return *r;
  }
  void set(const std::string& key, const std::string& value) { params.setText(key, value); }
  void render(const std::vector<std::string>& aovs, int w = kW, int h = kH, bool count = false,
              const std::vector<std::string>& techniques = {"depth_peeling"}, const std::vector<std::string>& colors = {}) {
    FrameOutputs outputs;
    outputs.aovs = aovs;
    outputs.countHdrClamped = count;
    outputs.colors = colors;
    renderOwnFrame(renderer, params, techniques, outputs, w, h);
  }
  Image transparency(int layers, const std::string& tail = "drop", int w = kW, int h = kH) {
    set("depth_peeling.layers", std::to_string(layers));
    set("depth_peeling.tail", tail);
    render({"transparency"}, w, h);
    return renderer.readAov("transparency");
  }
  double counter(const std::string& name) const { return techniqueCounter(renderer, "depth_peeling", name); }
};

glm::dvec3 pixel(const Image& img, int x, int y) {
  return {img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2)};
}

void expectNear(const glm::dvec3& got, const glm::dvec3& want, const std::string& what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], fp16Tolerance(want[c])) << what << " channel " << c;
}

double rmse(const Image& a, const Image& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) s += std::pow(double(a.pixels[i]) - double(b.pixels[i]), 2);
  return std::sqrt(s / double(a.pixels.size()));
}

// With as many layers as the depth complexity (4) or more, every region is the exact Over of all
// its layers onto the opaque colour, within fp16 rounding; the debug views count the layers peeled
// (1..4 across the regions) and nothing left behind.
TEST(DepthPeeling, EnoughLayersGiveExactOver) {
  const auto layers = fourLayers();
  PeelRenderer r(knownScene("dp_known", layers));
  for (const int count : {4, 64}) {
    const Image img = r.transparency(count);
    r.render({"depth_peeling.layers", "depth_peeling.remaining"});
    const Image peeled = r.renderer.readAov("depth_peeling.layers");
    const Image remaining = r.renderer.readAov("depth_peeling.remaining");
    for (int region = 0; region < 4; ++region) {
      const auto [x, y] = regionPixel(region);
      expectNear(pixel(img, x, y), cpuOver(layers, region, 4), "layers " + std::to_string(count) + " region " + std::to_string(region));
      EXPECT_EQ(peeled.at(x, y, 0), float(region + 1)) << region;
      EXPECT_EQ(remaining.at(x, y, 0), 0.0f) << region;
    }
  }
}

// One layer: the front layer over the opaque colour, wherever layers overlap far from the exact
// result; where one layer covers the pixel it is exact.
TEST(DepthPeeling, OneLayerKeepsOnlyTheFrontLayer) {
  const auto layers = fourLayers();
  PeelRenderer r(knownScene("dp_known", layers));
  const Image img = r.transparency(1);
  for (int region = 0; region < 4; ++region) {
    const auto [x, y] = regionPixel(region);
    const glm::dvec3 got = pixel(img, x, y);
    expectNear(got, cpuOver(layers, region, 1), "region " + std::to_string(region));
    if (region == 0) continue;
    const glm::dvec3 exact = cpuOver(layers, region, 4);
    double diff = 0;
    for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(got[c] - exact[c]) / fp16Tolerance(exact[c]));
    EXPECT_GT(diff, 10.0) << "region " << region << " should differ from the exact Over by far more than fp16 rounding";
  }
}

// The draw order (the scene's instance order here, see knownScene) does not change the image: the
// depth test picks each layer whatever the order, and the compositing runs in depth order. The
// tail's blends are sums and products (commutative), equal up to float rounding.
TEST(DepthPeeling, DrawOrderDoesNotMatter) {
  const auto layers = fourLayers();
  const std::vector<std::vector<int>> orders = {{0, 1, 2, 3}, {3, 1, 0, 2}, {2, 3, 1, 0}};
  for (const char* tail : {"drop", "blend"}) {
    std::vector<Image> images;
    for (std::size_t o = 0; o < orders.size(); ++o) {
      PeelRenderer r(knownScene("dp_order" + std::to_string(o), inOrder(layers, orders[o])));
      images.push_back(r.transparency(std::string(tail) == "drop" ? 4 : 1, tail));
    }
    for (std::size_t o = 1; o < images.size(); ++o)
      for (std::size_t i = 0; i < images[0].pixels.size(); ++i)
        ASSERT_NEAR(images[o].pixels[i], images[0].pixels[i], 1e-5 * std::abs(images[0].pixels[i]))
            << tail << " order " << o << " value " << i;
  }
}

// All alpha 0 (on `layers`, lit, with HDR emitters): the colour is the opaque image exactly
// (C = 0, T = 1: the composite is the input's fp16 value itself).
TEST(DepthPeeling, AllAlphaZeroGivesTheOpaqueImageExactly) {
  Scene s = loadScene("layers");
  s.name = "dp_layers_alpha0";
  for (auto& m : s.materials)
    if (m.alphaMode == AlphaMode::Blend) m.baseColor.w = 0.0f;
  PeelRenderer r(s);
  r.set("depth_peeling.tail", "blend");
  r.render({"transparency"}, kW, kH, false, {"depth_peeling"}, {"lit"});
  const Image got = r.renderer.readAov("transparency");
  const Image lit = r.renderer.readColor("lit");
  ASSERT_EQ(got.pixels.size(), lit.pixels.size());
  for (std::size_t i = 0; i < got.pixels.size(); ++i) ASSERT_EQ(got.pixels[i], lit.pixels[i]) << i;
}

// 24 layers of C = 1 (and of C = 60000, near the fp16 limit), alpha 1: finite, and the front layer
// hides the others; the layer count reaches 24 with 24 layers peeled. 64x36: 24 full-frame layers
// drawn 24 times (and again for the tail) are the slowest frames of this file.
TEST(DepthPeeling, TwentyFourOpaqueLikeLayersStayFinite) {
  constexpr int w = 64, h = 36;
  for (const float c : {1.0f, 60000.0f}) {
    std::vector<KnownLayer> layers;
    for (int i = 0; i < 24; ++i) layers.push_back({1.0f + 0.25f * float(i), {-0.9f, -0.8f}, {1.2f, 0.8f}, glm::vec3(c), 1.0f});
    PeelRenderer r(knownScene("dp_opaque24_" + std::to_string(int(c)), layers));
    for (const char* tail : {"drop", "blend"}) {
      const Image img = r.transparency(24, tail, w, h);
      for (float v : img.pixels) ASSERT_TRUE(std::isfinite(v)) << tail;
      expectNear(pixel(img, w - 2, h / 2), glm::dvec3(c), tail);
    }
    r.render({"depth_peeling.layers"}, w, h);
    EXPECT_EQ(r.renderer.readAov("depth_peeling.layers").at(w - 2, h / 2, 0), 24.0f);
  }
}

// On `layers` (depth complexity up to 24) with 8 layers, the blended tail is closer to the exact
// result (64 layers: everything peeled) than dropping it, and no pixel gets worse. Measured at
// 160x90: RMSE 0.041 (blend) vs 0.076 (drop), ratio 0.54; the bound 0.75 keeps a margin. With 4
// or fewer layers the linear RMSE is not lower (techniques/depth_peeling/README.md "Tail": the
// average weighs the far HDR layer 14 by a / sum a instead of its transmittance).
TEST(DepthPeeling, TailBlendIsCloserThanDropWithFewLayers) {
  PeelRenderer r(loadScene("layers"));
  const Image exact = r.transparency(64);
  const Image drop = r.transparency(8, "drop");
  const Image blend = r.transparency(8, "blend");
  const double eDrop = rmse(drop, exact), eBlend = rmse(blend, exact);
  EXPECT_GT(eDrop, 0.01) << "8 layers must leave fragments behind on `layers`";
  EXPECT_LT(eBlend, 0.75 * eDrop) << "blend " << eBlend << " drop " << eDrop;
  int worse = 0;
  for (std::size_t p = 0; p < exact.pixelCount(); ++p) {
    double d = 0, b = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t i = p * 3 + c;
      d += std::pow(double(drop.pixels[i]) - exact.pixels[i], 2);
      b += std::pow(double(blend.pixels[i]) - exact.pixels[i], 2);
    }
    if (b > d * (1 + 1e-3) + 1e-8) ++worse;
  }
  EXPECT_EQ(worse, 0);
}

// The counting frame counts the fragments behind the last layer: with 2 layers of the known four,
// region 2 leaves one per pixel and region 3 two, as the remaining view shows pixel by pixel; the
// counter is that view's sum, whether the tail pass counts (the colour is requested) or the view's
// pass does (only the views are). Dropped with tail=drop, none dropped with tail=blend.
TEST(DepthPeeling, RemainingFragmentsAreCountedAndShown) {
  const auto layers = fourLayers();
  PeelRenderer r(knownScene("dp_known", layers));
  r.set("depth_peeling.layers", "2");
  for (const char* tail : {"drop", "blend"}) {
    r.set("depth_peeling.tail", tail);
    for (const bool withColor : {true, false}) {
      std::vector<std::string> aovs = {"depth_peeling.remaining", "depth_peeling.layers"};
      if (withColor) aovs.push_back("transparency");
      r.render(aovs, kW, kH, true);
      const Image remaining = r.renderer.readAov("depth_peeling.remaining");
      const Image peeled = r.renderer.readAov("depth_peeling.layers");
      for (int region = 0; region < 4; ++region) {
        const auto [x, y] = regionPixel(region);
        EXPECT_EQ(remaining.at(x, y, 0), float(std::max(0, region - 1))) << region;
        EXPECT_EQ(peeled.at(x, y, 0), float(std::min(2, region + 1))) << region;
      }
      double sum = 0;
      for (std::size_t p = 0; p < remaining.pixelCount(); ++p) sum += remaining.pixels[p * std::size_t(remaining.channels)];
      EXPECT_GT(sum, 0.0);
      EXPECT_EQ(r.counter("remaining_fragments"), sum) << tail << withColor;
      EXPECT_EQ(r.counter("dropped_fragments"), std::string(tail) == "drop" ? sum : 0.0) << tail << withColor;
    }
  }
  // A frame that does not count reports nothing.
  r.render({"transparency"});
  EXPECT_TRUE(r.renderer.counters().empty());
}

// Two coplanar layers (same depth, different colours) are peeled once: the depth test keeps the
// first drawn, the next layer discards both (at the previous depth). The pixel is the Over of one
// of them, never both; which one depends on the draw order (README "Coplanar layers").
TEST(DepthPeeling, CoplanarLayersArePeeledOnce) {
  const std::vector<KnownLayer> layers = {{3.0f, {-0.9f, -0.8f}, {1.2f, 0.8f}, {4.0f, 0.0f, 0.0f}, 0.5f},
                                          {3.0f, {-0.9f, -0.8f}, {1.2f, 0.8f}, {0.0f, 4.0f, 0.0f}, 0.5f}};
  for (const auto& order : std::vector<std::vector<int>>{{0, 1}, {1, 0}}) {
    PeelRenderer r(knownScene("dp_coplanar" + std::to_string(order[0]), inOrder(layers, order)));
    const Image img = r.transparency(8);
    const glm::dvec3 got = pixel(img, kW / 2, kH / 2);
    const KnownLayer& first = layers[std::size_t(order[0])];
    expectNear(got, exactOver({first}, kOpaque, {0.0f, 0.0f}), "first drawn " + std::to_string(order[0]));
    r.render({"depth_peeling.layers"});
    EXPECT_EQ(r.renderer.readAov("depth_peeling.layers").at(kW / 2, kH / 2, 0), 1.0f);
  }
}

// Where the transparency stage does not run (no transparent material), depth_peeling adds no pass
// and holds no resource.
TEST(DepthPeeling, OpaqueOnlySceneHasNoPeelingPassOrResource) {
  PeelRenderer r(loadScene("contact"));
  r.render({"color"});
  for (const auto& p : r.renderer.lastPasses()) EXPECT_EQ(p.name.rfind("depth_peeling", 0), std::string::npos) << p.name;
  for (const auto& res : r.renderer.resources())
    EXPECT_EQ(res.name.rfind("depth_peeling", 0), std::string::npos) << res.name;
}

// A debug view asked for where the stage does not run is a usage error naming the stage, not a
// frame graph without its producer (an internal error).
TEST(DepthPeeling, DebugViewOnAnOpaqueSceneIsAUsageError) {
  PeelRenderer r(loadScene("contact"));
  testContext().makeCurrent();
  r.renderer.setTechniques({"depth_peeling"});
  try {
    r.renderer.checkAov("depth_peeling.layers");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Usage);
    EXPECT_NE(std::string(e.what()).find("transparency"), std::string::npos) << e.what();
  }
  r.renderer.setScene(loadScene("panes"));
  EXPECT_NO_THROW(r.renderer.checkAov("depth_peeling.layers"));
}

// One geometry pass per layer (named depth_peeling.layer<k> in stats), two depth targets whatever
// the layer count, and the tail's targets only with tail=blend.
TEST(DepthPeeling, PassPerLayerAndTwoDepthTargets) {
  PeelRenderer r(loadScene("panes"));
  for (const int count : {1, 5}) {
    for (const char* tail : {"drop", "blend"}) {
      r.set("depth_peeling.layers", std::to_string(count));
      r.set("depth_peeling.tail", tail);
      r.render({"color"});
      int layerPasses = 0;
      for (const auto& p : r.renderer.lastPasses())
        if (p.kept && p.name.rfind("depth_peeling.layer", 0) == 0) ++layerPasses;
      EXPECT_EQ(layerPasses, count);
      int depthTargets = 0, tailTargets = 0;
      for (const auto& res : r.renderer.resources()) {
        if (res.name.rfind("depth_peeling.depth", 0) == 0) ++depthTargets;
        if (res.name.rfind("depth_peeling.tail", 0) == 0) ++tailTargets;
      }
      EXPECT_EQ(depthTargets, std::min(count, 2)) << count << tail;
      EXPECT_EQ(tailTargets, std::string(tail) == "blend" ? 2 : 0) << count << tail;
    }
  }
}

} // namespace
} // namespace rtlab
