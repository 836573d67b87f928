// wboit (techniques/wboit/README.md) against the contract's formula (docs/contract.md
// "Transparency") computed on the CPU in double precision for the same fragments, and its
// properties: independence of the draw order, the extremes of the technique (every α = 0, 24
// opaque layers, 100 faint layers with an R8 or R16F revealage, HDR layers), negative view z, the
// complexity view, and that it costs nothing when off.
//
// The scenes are built here: camera-facing quads covering the whole frame at known view depths,
// with black base colour, emission E, ambient 0 and a light of intensity 0, so that each layer's
// radiance is C = E exactly, every pixel sees the same fragments, and the opaque colour is the
// backdrop's emission.
#include "frame/frame_view.h"
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "gl/debug.h"
#include "params/param_set.h"
#include "render_fixture.h"
#include "scene/builtin_scenes.h"
#include "scene/load.h"
#include "scene/mesh_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace rtlab {
namespace {

constexpr int kW = 32, kH = 18; // 16:9, as the quads' extent assumes
constexpr float kFovY = 50.0f;
constexpr float kBackdropDepth = 500.0f;

struct Layer {
  float depth;         // view depth, scene units
  float alpha;         // coverage
  glm::vec3 emission;  // C = E (black base colour, no light)
};

// Quads at the layers' depths covering the whole view (with margin), in `layers` order as scene
// instances, over an opaque black backdrop of emission `backdrop`. `mirrored`: the same view
// looking along +z instead of -z (world z of every layer positive). `equalSortKeys`: every layer's
// mesh gets the same bounds, so SceneGpu's back-to-front sort ties and keeps the instances' order
// (the draw order is then the scene's order).
Scene layerScene(const std::vector<Layer>& layers, const glm::vec3& backdrop, bool mirrored = false,
                 bool equalSortKeys = false) {
  builtin::SceneBuilder b("wboit_layers");
  const float s = mirrored ? 1.0f : -1.0f; // world z of the point at view depth 1
  const float halfH = std::tan(glm::radians(kFovY * 0.5f)) * 1.5f, halfW = halfH * 16.0f / 9.0f;
  auto quad = [&](const std::string& name, float depth) {
    return makeQuad(name, {0, 0, s * depth}, {halfW * depth, 0, 0}, {0, halfH * depth, 0});
  };
  Material back = builtin::diffuseMaterial("backdrop", glm::vec3(0.0f));
  back.emissive = backdrop;
  back.doubleSided = true;
  b.addObject(quad("backdrop", kBackdropDepth), b.addMaterial(back));
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const std::string name = "layer_" + std::to_string(i);
    Material m = builtin::diffuseMaterial(name, glm::vec3(0.0f));
    m.baseColor.w = layers[i].alpha;
    m.emissive = layers[i].emission;
    m.alphaMode = AlphaMode::Blend;
    m.doubleSided = true;
    b.addObject(quad(name, layers[i].depth), b.addMaterial(m));
  }
  b.addLight(builtin::directionalLight("off", {0.2f, -1.0f, -0.3f}, 0.0f, 0.5f));
  Scene scene = b.finish(builtin::camera({0, 0, 0}, {0, 0, s}, kFovY));
  scene.ambient = glm::vec3(0.0f);
  if (equalSortKeys)
    for (auto& mesh : scene.meshes)
      if (mesh.name.rfind("layer_", 0) == 0) mesh.bounds = scene.meshes.back().bounds;
  return scene;
}

// The projection the renderer uses: it fits the clip planes to the scene's bounds every frame
// (scene/scene_params.h), here about 0.106 to 1057.
glm::mat4 renderedProjection(const Scene& scene) {
  Camera camera = scene.camera;
  fitClipPlanes(camera, scene.worldBounds());
  return makeFrameView(camera, kW, kH).proj;
}

// The contract's weight for one fragment (docs/contract.md "Transparency"), in double precision.
struct WeightSetting {
  std::string function = "color9";
  double depthScale = 200, exponent = 4;
};

double weight(const WeightSetting& s, const Layer& l, double windowDepth) {
  const double z = std::abs(double(l.depth));
  double f;
  if (s.function == "eq7") f = 10.0 / (1e-5 + std::pow(z / 5.0, 2.0) + std::pow(z / 200.0, 6.0));
  else if (s.function == "eq8") f = 10.0 / (1e-5 + std::pow(z / 10.0, 3.0) + std::pow(z / 200.0, 6.0));
  else if (s.function == "eq10") f = 3e3 * std::pow(1.0 - windowDepth, 3.0);
  else f = 0.03 / (1e-5 + std::pow(z / s.depthScale, s.exponent));
  f = std::clamp(f, 1e-2, 3e3);
  double a = l.alpha;
  if (s.function == "color9") {
    const double peak = std::max({l.emission.x, l.emission.y, l.emission.z});
    a = std::max(std::min(1.0, peak * l.alpha), double(l.alpha));
  }
  return a * f;
}

struct Expected {
  glm::dvec3 color;
  double weightSum = 0, reveal = 1;
};

// R = (1 - reveal) accum.rgb / clamp(accum.w, 1e-4, 5e4) + reveal C_opaque, accum = Σ (α C w, α w).
Expected contractFormula(const std::vector<Layer>& layers, const glm::vec3& opaque, const WeightSetting& s,
                         const glm::mat4& proj) {
  glm::dvec4 accum(0.0);
  Expected e;
  for (const auto& l : layers) {
    const glm::vec4 clip = proj * glm::vec4(0, 0, -l.depth, 1);
    const double windowDepth = 0.5 * double(clip.z) / double(clip.w) + 0.5;
    const double w = weight(s, l, windowDepth);
    accum += glm::dvec4(glm::dvec3(l.emission) * double(l.alpha) * w, double(l.alpha) * w);
    e.reveal *= 1.0 - double(l.alpha);
  }
  e.weightSum = accum.w;
  e.color = (1.0 - e.reveal) * glm::dvec3(accum) / std::clamp(accum.w, 1e-4, 5e4) + e.reveal * glm::dvec3(opaque);
  return e;
}

struct WboitRenderer {
  Renderer renderer{TechniqueRegistry::instance()};
  ParamSet params;
  explicit WboitRenderer(const Scene& scene) {
    testContext().makeCurrent();
    renderer.setScene(scene);
    params = makeParamSet(scene, TechniqueRegistry::instance());
  }
  void set(const std::string& key, const std::string& value) { params.setText(key, value); }
  void render(const std::vector<std::string>& techniques, const std::vector<std::string>& aovs, bool count = false,
              int w = kW, int h = kH) {
    FrameOutputs outputs;
    outputs.aovs = aovs;
    outputs.colors = {"lit"};
    outputs.countHdrClamped = count;
    renderOwnFrame(renderer, params, techniques, outputs, w, h);
  }
  double counter(const std::string& name) const { return techniqueCounter(renderer, "wboit", name); }
};

// The largest difference of any channel of any pixel from `want` (the same for every pixel),
// relative to max(1, |want|).
double worstRelative(const Image& got, const glm::dvec3& want) {
  double worst = 0;
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double g = got.at(x, y, std::min(c, got.channels - 1));
        const double err = std::isfinite(g) ? std::abs(g - want[c]) / std::max(1.0, std::abs(want[c])) : 1e30;
        worst = std::max(worst, err);
      }
  return worst;
}

// Six layers over the weights' whole depth range (0.3 to 450), saturated and HDR colours, so that
// each equation weighs them differently and a wrong weight moves the average.
const std::vector<Layer> kSix = {
    {0.3f, 0.3f, {2.0f, 0.1f, 0.1f}},  {2.0f, 0.5f, {0.1f, 1.5f, 0.1f}}, {9.0f, 0.4f, {0.1f, 0.1f, 3.0f}},
    {40.0f, 0.6f, {4.0f, 4.0f, 0.2f}}, {180.0f, 0.7f, {0.2f, 3.0f, 3.0f}}, {450.0f, 0.8f, {0.5f, 0.2f, 0.5f}},
};
const glm::vec3 kBackdrop(0.25f, 0.5f, 0.75f);

std::vector<WeightSetting> everyWeight() {
  return {{"eq7"}, {"eq8"}, {"eq9"}, {"eq10"}, {"color9"}, {"eq9", 50.0, 3.0}, {"color9", 800.0, 1.5}};
}

void setWeight(WboitRenderer& r, const WeightSetting& s) {
  r.set("wboit.weight", s.function);
  r.set("wboit.depth_scale", std::to_string(s.depthScale));
  r.set("wboit.exponent", std::to_string(s.exponent));
}

// Every weight function (and eq9/color9 off their defaults, one with the odd exponent 3 where
// pow() of the negative view z would be negative or NaN) against the formula. With an RGBA32F
// accumulation the accumulated weight (view wboit.weight) is the CPU's Σ α w to fp32 precision
// (measured below 1e-6 relative; bound 1e-5) and the colour is it up to the RGBA16F output and the
// R16F revealage (measured at most 5.7e-4; bound 2e-3). With the defaults RGBA16F / R8 the sums
// round to fp16 and the revealage to 1/255 per layer (measured: weight 1.0e-3, colour 1.1e-3;
// bounds 3e-3 and 5e-3). A wrong equation, clamp or sign moves these by far more (a wrong weight
// shifts the average between colours that differ by 1 or more).
TEST(Wboit, EqualsTheContractFormulaForEveryWeight) {
  const Scene scene = layerScene(kSix, kBackdrop);
  const glm::mat4 proj = renderedProjection(scene);
  WboitRenderer r(scene);
  int index = 0;
  for (const auto& s : everyWeight()) {
    const std::string name = s.function + "_" + std::to_string(index++);
    const Expected want = contractFormula(kSix, kBackdrop, s, proj);
    setWeight(r, s);
    for (const bool exact : {true, false}) {
      r.set("wboit.accum_format", exact ? "rgba32f" : "rgba16f");
      r.set("wboit.reveal_format", exact ? "r16f" : "r8");
      r.render({"wboit"}, {"transparency", "wboit.weight"});
      const double colorError = worstRelative(r.renderer.readAov("transparency"), want.color);
      const double weightError = worstRelative(r.renderer.readAov("wboit.weight"), glm::dvec3(want.weightSum)) *
                                 std::max(1.0, want.weightSum) / want.weightSum;
      RecordProperty(name + (exact ? "_32f" : "_16f") + "_color_error", std::to_string(colorError));
      RecordProperty(name + (exact ? "_32f" : "_16f") + "_weight_error", std::to_string(weightError));
      EXPECT_LT(colorError, exact ? 2e-3 : 5e-3) << s.function << " " << s.depthScale << " " << s.exponent;
      EXPECT_LT(weightError, exact ? 1e-5 : 3e-3) << s.function << " " << s.depthScale << " " << s.exponent;
    }
  }
}

// Negative view z: with the camera looking along +z (every layer at positive world z) the image is
// the same as looking along -z, and both match the formula evaluated at |z| (GL view space z is
// negative in front of the camera either way; a weight that used the world z or the signed view
// z would differ). eq9 with the odd exponent 3 and with 2.5, where pow() of a negative base is
// negative or undefined.
TEST(Wboit, NegativeViewZGivesTheSameAsPositive) {
  const Scene forward = layerScene(kSix, kBackdrop), mirrored = layerScene(kSix, kBackdrop, true);
  const glm::mat4 proj = renderedProjection(forward);
  WboitRenderer a(forward), b(mirrored);
  for (const WeightSetting& s : {WeightSetting{"eq9", 200.0, 3.0}, WeightSetting{"color9", 100.0, 2.5}}) {
    const Expected want = contractFormula(kSix, kBackdrop, s, proj);
    for (WboitRenderer* r : {&a, &b}) {
      setWeight(*r, s);
      r->set("wboit.accum_format", "rgba32f");
      r->set("wboit.reveal_format", "r16f");
      r->render({"wboit"}, {"transparency"});
    }
    const Image ia = a.renderer.readAov("transparency"), ib = b.renderer.readAov("transparency");
    EXPECT_LT(worstRelative(ia, want.color), 2e-3) << s.function;
    EXPECT_LT(worstRelative(ib, want.color), 2e-3) << s.function;
    double diff = 0;
    for (std::size_t i = 0; i < ia.pixels.size(); ++i) diff = std::max(diff, double(std::abs(ia.pixels[i] - ib.pixels[i])));
    EXPECT_LT(diff, 1e-3) << s.function;
  }
}

// Draw order: the same layers as scene instances in three orders (SceneGpu then draws them in
// that order, their sort keys being equal). Over (the framework's fallback, no technique) depends
// on the order, so the orders really differ (by more than 0.05 here); wboit's sums commute, and
// what remains is the rounding of each blend: RGBA16F sums and an R16F revealage round in another
// order (measured at most 4.9e-4 relative: one fp16 step of the output; bound 2e-3), an R8
// revealage in 1/255 steps (measured at most 9.8e-4; bound 5e-3).
TEST(Wboit, InvariantToTheDrawOrder) {
  std::vector<std::vector<Layer>> orders = {kSix, kSix, kSix};
  std::reverse(orders[1].begin(), orders[1].end());
  std::mt19937 rng(7);
  std::shuffle(orders[2].begin(), orders[2].end(), rng);
  struct Result {
    Image over, r16, r8;
  };
  std::vector<Result> results;
  for (const auto& order : orders) {
    WboitRenderer r(layerScene(order, kBackdrop, false, true));
    Result res;
    r.render({}, {"transparency"});
    res.over = r.renderer.readAov("transparency");
    r.set("wboit.reveal_format", "r16f");
    r.render({"wboit"}, {"transparency"});
    res.r16 = r.renderer.readAov("transparency");
    r.set("wboit.reveal_format", "r8");
    r.render({"wboit"}, {"transparency"});
    res.r8 = r.renderer.readAov("transparency");
    results.push_back(std::move(res));
  }
  auto maxRelative = [](const Image& a, const Image& b) {
    double m = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
      m = std::max(m, double(std::abs(a.pixels[i] - b.pixels[i])) / std::max(1.0, double(std::abs(b.pixels[i]))));
    return m;
  };
  for (std::size_t k = 1; k < results.size(); ++k) {
    EXPECT_GT(maxRelative(results[k].over, results[0].over), 0.05) << "order " << k << " did not change the draw order";
    const double r16 = maxRelative(results[k].r16, results[0].r16), r8 = maxRelative(results[k].r8, results[0].r8);
    RecordProperty("order" + std::to_string(k) + "_r16f", std::to_string(r16));
    RecordProperty("order" + std::to_string(k) + "_r8", std::to_string(r8));
    EXPECT_LT(r16, 2e-3) << "order " << k;
    EXPECT_LT(r8, 5e-3) << "order " << k;
  }
}

// Every α = 0: reveal stays exactly 1 and accum 0, so the composite returns the opaque colour
// exactly (bit for bit), for every weight and format.
TEST(Wboit, AllAlphaZeroGivesTheOpaqueImageExactly) {
  std::vector<Layer> clear = kSix;
  for (auto& l : clear) l.alpha = 0.0f;
  WboitRenderer r(layerScene(clear, kBackdrop));
  for (const char* weight : {"eq7", "eq10", "color9"})
    for (const char* accum : {"rgba16f", "rgba32f"})
      for (const char* reveal : {"r8", "r16f"}) {
        r.set("wboit.weight", weight);
        r.set("wboit.accum_format", accum);
        r.set("wboit.reveal_format", reveal);
        r.render({"wboit"}, {"transparency"});
        const Image got = r.renderer.readAov("transparency"), opaque = r.renderer.readColor("lit");
        ASSERT_EQ(got.pixels.size(), opaque.pixels.size());
        EXPECT_EQ(got.pixels, opaque.pixels) << weight << " " << accum << " " << reveal;
        EXPECT_FLOAT_EQ(opaque.at(kW / 2, kH / 2, 2), kBackdrop.z);
      }
}

// 24 layers with C = 1 and α = 1 near the camera, where every weight is the largest (about 3e3):
// the RGBA16F sums would reach 24 x 3e3 = 72000 > 65504 without the guard (README "Numerical
// guards": stored x 1/16). Both formats stay finite and equal the formula, which here is 1.44,
// not 1: Σ α w = 72000 is above the divisor's upper clamp 5e4. The same layers with C = 60000: the
// formula gives 86400, which RGBA32F computes and the HDR clamp writes as 65504; with RGBA16F one
// fragment's α C w alone overflows fp16, so each fragment's share is capped (all counted), which
// lowers its weight and keeps its colour: every layer has C = 60000, so the result is 60000.
// RGBA32F matches to 2e-3 (the output's fp16); RGBA16F's 24 sums of about 187 (3e3 / 16) round to
// fp16 steps of 2 to 4 (measured: Σ α w 0.6% low, the colour 1.44 x that since the clamp divides
// by 5e4 regardless; bound 1.5%).
TEST(Wboit, TwentyFourOpaqueLayersStayFinite) {
  for (const float c : {1.0f, 60000.0f}) {
    std::vector<Layer> layers;
    for (int k = 0; k < 24; ++k) layers.push_back({0.5f + 0.05f * float(k), 1.0f, glm::vec3(c)});
    const Scene scene = layerScene(layers, kBackdrop);
    const Expected formula = contractFormula(layers, kBackdrop, {}, renderedProjection(scene));
    WboitRenderer r(scene);
    for (const char* accum : {"rgba16f", "rgba32f"}) {
      r.set("wboit.accum_format", accum);
      r.render({"wboit"}, {"transparency", "wboit.weight"}, true);
      const Image got = r.renderer.readAov("transparency");
      for (float v : got.pixels) ASSERT_TRUE(std::isfinite(v)) << accum << " C " << c;
      const bool fp16Sums = std::string(accum) == "rgba16f", capped = c > 1.0f && fp16Sums;
      const glm::dvec3 want = c == 1.0f ? formula.color : capped ? glm::dvec3(c) : glm::dvec3(65504.0);
      if (c == 1.0f) {
        EXPECT_NEAR(formula.color.x, 1.44, 0.01);
      }
      EXPECT_LT(worstRelative(got, want), fp16Sums ? 1.5e-2 : 2e-3) << accum << " C " << c;
      const Image w = r.renderer.readAov("wboit.weight");
      EXPECT_TRUE(std::isfinite(w.at(0, 0, 0))) << accum;
      if (!capped) {
        EXPECT_NEAR(w.at(kW / 2, kH / 2, 0), formula.weightSum, formula.weightSum * (fp16Sums ? 1.5e-2 : 2e-3))
            << accum << " C " << c;
      }
      EXPECT_EQ(r.counter("capped_fragments"), capped ? 24.0 * kW * kH : 0.0) << accum << " C " << c;
      EXPECT_EQ(r.counter("overflowed_pixels"), 0.0) << accum;
    }
  }
}

// Beyond the guard: 80 layers of C = 60000, α = 1 each add the cap 65504/64 to the RGBA16F sums,
// 80 x 1023.5 > 65504, so the colour sum saturates (65504 on llvmpipe, +inf on hardware; the
// composite reads either as 65504). The result stays finite, is counted in every pixel, and is too
// dark (65504 x 16 / Σ α w instead of 60000); RGBA32F has no such limit.
TEST(Wboit, SumsBeyondTheGuardStayFiniteAndAreCounted) {
  std::vector<Layer> layers;
  for (int k = 0; k < 80; ++k) layers.push_back({0.5f + 0.02f * float(k), 1.0f, glm::vec3(60000.0f)});
  WboitRenderer r(layerScene(layers, kBackdrop));
  r.render({"wboit"}, {"transparency"}, true);
  const Image got = r.renderer.readAov("transparency");
  for (float v : got.pixels) ASSERT_TRUE(std::isfinite(v));
  EXPECT_LT(got.at(kW / 2, kH / 2, 0), 0.9f * 60000.0f);
  EXPECT_EQ(r.counter("overflowed_pixels"), double(kW * kH));
  r.set("wboit.accum_format", "rgba32f");
  r.render({"wboit"}, {"transparency"}, true);
  EXPECT_EQ(r.counter("overflowed_pixels"), 0.0);
  EXPECT_EQ(r.renderer.readAov("transparency").at(kW / 2, kH / 2, 0), 65504.0f); // the formula, HDR-clamped
}

// 100 layers at α = 0.001 over a black backdrop (C = 1): the revealage should be 0.999^100 =
// 0.905 and the colour 1 - 0.905. R8 rounds 1 x 0.999 back to 1 (α < 1/510), so the layers
// vanish: revealage exactly 1 and the opaque colour exactly (wrong, documented). R16F keeps them,
// 1.1% low (measured 0.8945): each product dst x 0.999 falls about 1.8 fp16 steps below dst (steps
// of 2^-11 between 0.5 and 1) and rounds to 2, a bias that adds up over 100 layers; bound 0.015.
TEST(Wboit, HundredFaintLayersVanishWithR8AndNotWithR16f) {
  std::vector<Layer> layers;
  for (int k = 0; k < 100; ++k) layers.push_back({1.0f + 0.1f * float(k), 0.001f, glm::vec3(1.0f)});
  WboitRenderer r(layerScene(layers, glm::vec3(0.0f)));
  const double want = std::pow(0.999, 100.0);
  r.set("wboit.reveal_format", "r8");
  r.render({"wboit"}, {"transparency", "wboit.revealage"});
  EXPECT_EQ(r.renderer.readAov("wboit.revealage").at(kW / 2, kH / 2, 0), 1.0f);
  EXPECT_EQ(r.renderer.readAov("transparency").at(kW / 2, kH / 2, 0), 0.0f);
  r.set("wboit.reveal_format", "r16f");
  r.render({"wboit"}, {"transparency", "wboit.revealage"});
  const double reveal = r.renderer.readAov("wboit.revealage").at(kW / 2, kH / 2, 0);
  RecordProperty("r16f_revealage", std::to_string(reveal));
  EXPECT_NEAR(reveal, want, 0.015);
  EXPECT_NEAR(r.renderer.readAov("transparency").at(kW / 2, kH / 2, 0), 1.0 - want, 0.015);
}

// The complexity view counts the transparent fragments in front of the opaque depth: the six
// layers in every pixel. Its pass runs only when the view is requested.
TEST(Wboit, ComplexityCountsFragmentsAndRunsOnlyWhenRequested) {
  WboitRenderer r(layerScene(kSix, kBackdrop));
  r.render({"wboit"}, {"wboit.complexity"});
  const Image count = r.renderer.readAov("wboit.complexity");
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) ASSERT_EQ(count.at(x, y, 0), 6.0f) << x << "," << y;
  r.render({"wboit"}, {"color"});
  for (const auto& p : r.renderer.lastPasses())
    if (p.name == "wboit.count") {
      EXPECT_FALSE(p.kept);
    }
  for (const auto& res : r.renderer.resources()) EXPECT_NE(res.name, "wboit.count");
}

// Off is free: without wboit the transparency stage's passes are the fallback's; on a scene
// without a transparent material (contact) wboit adds no pass and holds no resource even when
// active (the stage does not apply).
TEST(Wboit, OffIsFree) {
  WboitRenderer panes(loadScene("panes"));
  panes.render({"wboit"}, {"color"});
  bool ran = false;
  for (const auto& p : panes.renderer.lastPasses()) ran = ran || (p.name == "wboit.accumulate" && p.kept);
  EXPECT_TRUE(ran);
  panes.render({}, {"color"});
  for (const auto& p : panes.renderer.lastPasses()) EXPECT_EQ(p.name.rfind("wboit", 0), std::string::npos) << p.name;
  for (const auto& res : panes.renderer.resources()) EXPECT_EQ(res.name.rfind("wboit", 0), std::string::npos) << res.name;

  WboitRenderer contact(loadScene("contact"));
  contact.render({"wboit"}, {"color"});
  for (const auto& p : contact.renderer.lastPasses()) EXPECT_EQ(p.name.rfind("wboit", 0), std::string::npos) << p.name;
  for (const auto& res : contact.renderer.resources()) EXPECT_EQ(res.name.rfind("wboit", 0), std::string::npos) << res.name;
  EXPECT_EQ(contact.renderer.colorVersionResource("pre_post"), contact.renderer.colorVersionResource("lit"));
}

} // namespace
} // namespace rtlab
