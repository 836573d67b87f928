// bloom (techniques/bloom/README.md): its PSF and energy against the exact convolution of the
// same input (bloom_model.h), the soft knee, HDR robustness (clamp and NaN, counted), its limits,
// and that it costs nothing when off. Inputs are synthetic images that a fake post technique,
// stacked before bloom, writes as the colour bloom reads.
#include "frame/frame_graph.h"
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "gl/debug.h"
#include "params/param_set.h"
#include "render_fixture.h"
#include "scene/builtin_scenes.h"
#include "scene/load.h"
#include "scene/mesh_builder.h"
#include "shading/base_passes.h"
#include "techniques/bloom/bloom_model.h"
#include "util/error.h"
#include "../support/fake_technique.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace rtlab {
namespace {

// The image the fake technique writes (rows top to bottom, 3 channels), set by each test.
std::shared_ptr<Image> g_input = std::make_shared<Image>();

// A post technique that replaces the colour by g_input (uploaded as float into the RGBA16F colour,
// as a pass that wrote it would store it).
class InputTechnique : public Technique {
public:
  explicit InputTechnique(TechniqueInfo info) : m_info(std::move(info)) {}
  const TechniqueInfo& info() const override { return m_info; }
  void setup(FrameGraph& frame) override {
    const std::string out = frame.colorOutput();
    frame.addPass("bloom_input.color", [&](PassBuilder& b) { b.write(out, frameTexture(frame, GL_RGBA16F)); },
        [out](PassContext& ctx) {
          const Image& img = *g_input;
          std::vector<float> rgba(img.pixelCount() * 4, 1.0f);
          for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
              for (int c = 0; c < 3; ++c) // GL rows run bottom to top
                rgba[(std::size_t(img.height - 1 - y) * img.width + x) * 4 + c] = img.at(x, y, c);
          glTextureSubImage2D(ctx.texture(out).id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_FLOAT, rgba.data());
        });
  }

private:
  TechniqueInfo m_info;
};

const TechniqueRegistry& bloomRegistry() {
  static const TechniqueRegistry registry = [] {
    TechniqueRegistry r;
    registerAllTechniques(r);
    TechniqueEntry e = test::fakeTechnique("bloom_input", "post");
    e.create = [info = e.info] { return std::make_unique<InputTechnique>(info); };
    r.add(e);
    return r;
  }();
  return registry;
}

struct BloomRenderer {
  Renderer renderer{bloomRegistry()};
  ParamSet params;
  explicit BloomRenderer(const Scene& scene) {
    testContext().makeCurrent();
    renderer.setScene(scene);
    params = makeParamSet(scene, bloomRegistry());
  }
  void set(const std::string& key, const std::string& value) { params.setText(key, value); }
  // Renders the frame with the given post stack; returns the AOVs asked for.
  void render(const std::vector<std::string>& techniques, const std::vector<std::string>& aovs, int w, int h,
              bool count = false) {
    FrameOutputs outputs;
    outputs.aovs = aovs;
    outputs.countHdrClamped = count;
    renderOwnFrame(renderer, params, techniques, outputs, w, h);
  }
  double counter(const std::string& name) const { return techniqueCounter(renderer, "bloom", name); }
};


// Mean of channel 0 over rings of width 1 pixel around (cx, cy), out to `radius`.
std::vector<double> radialProfile(const Image& img, int cx, int cy, int radius) {
  std::vector<double> sum(std::size_t(radius) + 1, 0.0), count(sum.size(), 0.0);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int r = int(std::lround(std::hypot(x - cx, y - cy)));
      if (r > radius) continue;
      sum[std::size_t(r)] += img.at(x, y, 0);
      count[std::size_t(r)] += 1;
    }
  for (std::size_t i = 0; i < sum.size(); ++i) sum[i] /= std::max(count[i], 1.0);
  return sum;
}

double channelSum(const Image& img, int c) {
  double s = 0;
  for (std::size_t i = 0; i < img.pixelCount(); ++i) s += img.pixels[i * std::size_t(img.channels) + std::size_t(c)];
  return s;
}

// The largest difference between two profiles, relative to the reference's peak.
double profileError(const std::vector<double>& got, const std::vector<double>& want) {
  double peak = 0, err = 0;
  for (double v : want) peak = std::max(peak, std::abs(v));
  for (std::size_t i = 0; i < want.size(); ++i) err = std::max(err, std::abs(got[i] - want[i]));
  return err / peak;
}

constexpr int kSize = 320;

Image impulseAt(int w, int h, int x, int y, float value) {
  Image img(w, h, 3);
  for (int c = 0; c < 3; ++c) img.at(x, y, c) = value;
  return img;
}

// An impulse of 1000 (luma 1000, bright ~999) in the middle of a 320x320 frame, at the four phases
// of the mip chain's 2x2 grid; the defaults (sigma 2 px, 5 octaves: the widest Gaussian has
// sigma 32 px, truncated at 128 px) keep the kernel inside the frame. The gaussian method is the
// definition up to fp16 storage: within 1% of the peak. The mip method approximates the PSF with
// six levels' fixed blurs (bloom_model.h planMipChain); measured at the four phases: at most 8% of
// the peak, lowest in the centre (the levels' PSFs are flatter-topped than Gaussians) and longer
// in the far tail — the bound 10% keeps that margin. Energy: intensity x the bright pass's energy
// within 1% for both (the chain's filters and weights sum to 1).
TEST(Bloom, SinglePixelFollowsTheDeclaredPsfAndKeepsItsEnergy) {
  BloomRenderer r(loadScene("contact"));
  r.set("bloom.karis", "false");
  const bloom::Definition d = bloom::definitionFrom(r.params);
  const int radius = bloom::gaussianRadius(bloom::octaveSigma(d, d.octaves - 1));
  ASSERT_LT(radius, kSize / 2 - 1); // the kernel stays inside the frame
  for (const int phase : {0, 1, 2, 3}) {
    const int cx = kSize / 2 + (phase & 1), cy = kSize / 2 + (phase >> 1);
    *g_input = impulseAt(kSize, kSize, cx, cy, 1000.0f);
    const Image bright = bloom::brightPass(*g_input, d);
    const std::vector<double> wantProfile = radialProfile(bloom::convolve(bright, d), cx, cy, radius);
    const double energy = d.intensity * channelSum(bright, 0);
    for (const char* method : {"gaussian", "mip"}) {
      r.set("bloom.method", method);
      r.render({"bloom_input", "bloom"}, {"bloom"}, kSize, kSize);
      const Image got = r.renderer.readAov("bloom");
      const double profile = profileError(radialProfile(got, cx, cy, radius), wantProfile);
      const double energyError = std::abs(channelSum(got, 0) / energy - 1.0);
      RecordProperty(std::string(method) + "_profile_error_phase" + std::to_string(phase), std::to_string(profile));
      EXPECT_LT(energyError, 0.01) << method << " phase " << phase;
      EXPECT_LT(profile, std::string(method) == "gaussian" ? 0.01 : 0.10) << method << " phase " << phase;
    }
  }
}

// Karis's average weights the first downsample's 2x2 groups by 1/(1 + luma): an isolated firefly's
// group weighs ~1/250 of its dark neighbours', so most of its energy never reaches the levels (what
// remains is the level-0 share and the small weight). An extended bright region, whose groups all
// weigh alike, keeps its energy.
TEST(Bloom, KarisAverageSuppressesIsolatedFirefliesOnly) {
  BloomRenderer r(loadScene("contact"));
  auto energyRatio = [&](const Image& input) {
    *g_input = input;
    r.set("bloom.karis", "false");
    r.render({"bloom_input", "bloom"}, {"bloom"}, kSize, kSize);
    const double off = channelSum(r.renderer.readAov("bloom"), 1);
    r.set("bloom.karis", "true");
    r.render({"bloom_input", "bloom"}, {"bloom"}, kSize, kSize);
    return channelSum(r.renderer.readAov("bloom"), 1) / off;
  };
  const double firefly = energyRatio(impulseAt(kSize, kSize, kSize / 2, kSize / 2, 1000.0f));
  Image square(kSize, kSize, 3);
  for (int y = kSize / 2 - 16; y < kSize / 2 + 16; ++y)
    for (int x = kSize / 2 - 16; x < kSize / 2 + 16; ++x)
      for (int c = 0; c < 3; ++c) square.at(x, y, c) = 4.0f;
  const double region = energyRatio(square);
  RecordProperty("karis_firefly_energy_ratio", std::to_string(firefly));
  RecordProperty("karis_square_energy_ratio", std::to_string(region));
  EXPECT_LT(firefly, 0.5);
  EXPECT_NEAR(region, 1.0, 0.03);
}

Image uniform(int w, int h, float luma) {
  Image img(w, h, 3);
  std::fill(img.pixels.begin(), img.pixels.end(), luma); // grey: luma = the value
  return img;
}

// A uniform grey frame whose luma crosses T = 1: away from the borders bloom = intensity x bright
// (the PSF sums to 1). With the soft knee (K = 0.5) the bright part grows continuously, with slope
// at most 1 per unit of luma near T; the hard cut jumps by intensity x luma at T.
TEST(Bloom, SoftKneeIsContinuousAtTheThresholdWhereTheHardCutPops) {
  BloomRenderer r(loadScene("contact"));
  constexpr int kN = 96;
  auto centre = [&](float luma, bool hardCut) {
    *g_input = uniform(kN, kN, luma);
    r.set("bloom.hard_cut", hardCut ? "true" : "false");
    r.set("bloom.sigma", "0.5");
    r.set("bloom.octaves", "3"); // widest sigma 2 px: the centre is far from the border
    r.render({"bloom_input", "bloom"}, {"bloom"}, kN, kN);
    return double(r.renderer.readAov("bloom").at(kN / 2, kN / 2, 0));
  };
  const double intensity = r.params.getFloat("bloom.intensity");
  const float lumas[] = {0.99f, 0.995f, 1.0f, 1.005f, 1.01f};
  double soft[5], hard[5];
  for (int i = 0; i < 5; ++i) {
    soft[i] = centre(lumas[i], false);
    hard[i] = centre(lumas[i], true);
  }
  for (int i = 1; i < 5; ++i) {
    const double step = double(lumas[i] - lumas[i - 1]);
    EXPECT_GE(soft[i], soft[i - 1]) << lumas[i];                     // monotonic
    EXPECT_LT(soft[i] - soft[i - 1], intensity * step * 1.05) << lumas[i]; // slope <= 1 (+ fp16)
  }
  EXPECT_GT(soft[0], 0.0); // the knee starts below T
  EXPECT_EQ(hard[0], 0.0);
  EXPECT_EQ(hard[2], 0.0); // luma > T, not >=
  EXPECT_NEAR(hard[3], intensity * 1.005, intensity * 0.01);
  EXPECT_LT(soft[4] - soft[0], 0.05 * (hard[4] - hard[0]));
}

// With the threshold above every pixel of the frame, bloom adds exactly nothing.
TEST(Bloom, ThresholdAboveEveryPixelAddsNothing) {
  BloomRenderer r(loadScene("contact"));
  r.set("bloom.threshold", "20");
  r.render({}, {"color"}, 160, 90);
  const Image plain = r.renderer.readAov("color");
  for (const char* method : {"gaussian", "mip"}) {
    r.set("bloom.method", method);
    r.render({"bloom"}, {"color", "bloom"}, 160, 90);
    const Image color = r.renderer.readAov("color"), added = r.renderer.readAov("bloom");
    EXPECT_EQ(color.pixels, plain.pixels) << method;
    EXPECT_EQ(*std::max_element(added.pixels.begin(), added.pixels.end()), 0.0f) << method;
  }
}

// A floor, and two emitters facing the camera: 1e5 (red) and 1e6 (green), far above what a
// 16-bit float holds.
Scene hugeEmitters() {
  builtin::SceneBuilder b("bloom_huge");
  const int floor = b.addMaterial(builtin::diffuseMaterial("floor", glm::vec3(0.3f)));
  Material e5 = builtin::diffuseMaterial("e5", {0, 0, 0});
  e5.emissive = {1e5f, 0, 0};
  Material e6 = builtin::diffuseMaterial("e6", {0, 0, 0});
  e6.emissive = {0, 1e6f, 0};
  const int m5 = b.addMaterial(e5), m6 = b.addMaterial(e6);
  b.addObject(makePlane("floor", 8.0f, 8.0f), floor);
  b.addObject(makeQuad("e5", {-0.8f, 1.0f, 0.0f}, {0.3f, 0, 0}, {0, 0.3f, 0}), m5);
  b.addObject(makeQuad("e6", {0.8f, 1.0f, 0.0f}, {0.3f, 0, 0}, {0, 0.3f, 0}), m6);
  b.addLight(builtin::directionalLight("key", {-0.3f, -1.0f, -0.5f}, 1.0f, 0.5f));
  return b.finish(builtin::camera({0, 1.2f, 4.0f}, {0, 0.9f, 0}, 45.0f));
}

// Emitters of 1e5 and 1e6 reach bloom at 65504 (the framework's HDR clamp); every storage format
// gives finite colour and bloom. R11G11B10F holds at most 65024 (64512 in blue), so bloom clamps
// the emitters' pixels before the blur and counts them; RGBA16F has nothing more to clamp.
TEST(Bloom, HugeEmittersStayFiniteAndAreCountedWhereClamped) {
  BloomRenderer r(hugeEmitters());
  for (const char* format : {"rgba16f", "r11g11b10f", "rgba32f"})
    for (const char* method : {"gaussian", "mip"}) {
      r.set("bloom.format", format);
      r.set("bloom.method", method);
      r.render({"bloom"}, {"color", "bloom"}, 160, 90, true);
      const Image color = r.renderer.readAov("color"), added = r.renderer.readAov("bloom");
      for (float v : color.pixels) ASSERT_TRUE(std::isfinite(v) && v <= 65504.0f) << format << " " << method;
      for (float v : added.pixels) ASSERT_TRUE(std::isfinite(v)) << format << " " << method;
      EXPECT_GT(*std::max_element(added.pixels.begin(), added.pixels.end()), 100.0f);
      const double clamped = r.counter("clamped_pixels");
      if (std::string(format) == "r11g11b10f") EXPECT_GT(clamped, 20.0) << method;
      else EXPECT_EQ(clamped, 0.0) << format << " " << method;
      EXPECT_EQ(r.counter("nonfinite_pixels"), 0.0);
    }
}

// A NaN and an infinity in the colour bloom reads (from a broken earlier pass) become 0, are
// counted, and do not spread: the result equals that of the same frame with zeros there.
TEST(Bloom, NonFiniteInputIsSanitisedCountedAndNotSpread) {
  BloomRenderer r(loadScene("contact"));
  Image input = impulseAt(kSize / 2, kSize / 2, kSize / 4, kSize / 4, 50.0f);
  Image clean = input;
  for (int c = 0; c < 3; ++c) {
    input.at(10, 20, c) = std::numeric_limits<float>::quiet_NaN();
    input.at(100, 60, c) = std::numeric_limits<float>::infinity();
  }
  for (const char* method : {"gaussian", "mip"}) {
    r.set("bloom.method", method);
    *g_input = clean;
    r.render({"bloom_input", "bloom"}, {"bloom", "color"}, kSize / 2, kSize / 2);
    const Image want = r.renderer.readAov("bloom");
    *g_input = input;
    r.render({"bloom_input", "bloom"}, {"bloom", "color"}, kSize / 2, kSize / 2, true);
    const Image got = r.renderer.readAov("bloom"), color = r.renderer.readAov("color");
    for (float v : got.pixels) ASSERT_TRUE(std::isfinite(v)) << method;
    for (float v : color.pixels) ASSERT_TRUE(std::isfinite(v)) << method;
    EXPECT_EQ(got.pixels, want.pixels) << method;
    EXPECT_EQ(r.counter("nonfinite_pixels"), 2.0) << method;
  }
}

// sigma and octaves at their largest on a small frame: the Gaussian taps stop at the frame's edge
// and the mip chain at the deepest level the frame allows (octaves beyond it are counted), so no
// resource is larger than the frame; the result is finite and keeps its energy inside the frame
// only partly (outside is black), never more than the bright pass's.
TEST(Bloom, WidestKernelsAllocateNothingLargerThanTheFrame) {
  BloomRenderer r(loadScene("contact"));
  constexpr int kW = 64, kH = 48;
  *g_input = impulseAt(kW, kH, kW / 2, kH / 2, 1000.0f);
  r.set("bloom.sigma", "64");
  r.set("bloom.octaves", "10");
  r.set("bloom.karis", "false");
  const bloom::Definition d = bloom::definitionFrom(r.params);
  const double energy = d.intensity * channelSum(bloom::brightPass(*g_input, d), 0);
  for (const char* method : {"gaussian", "mip"}) {
    r.set("bloom.method", method);
    r.render({"bloom_input", "bloom"}, {"bloom"}, kW, kH);
    const Image got = r.renderer.readAov("bloom");
    for (float v : got.pixels) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << method;
    EXPECT_LT(channelSum(got, 0), energy) << method;
    std::size_t bytes = 0;
    for (const auto& res : r.renderer.resources()) {
      if (res.name.rfind("bloom.", 0) != 0) continue;
      const gl::Texture* t = r.renderer.resource(res.name);
      ASSERT_NE(t, nullptr) << res.name;
      EXPECT_LE(t->desc().width, kW) << res.name;
      EXPECT_LE(t->desc().height, kH) << res.name;
      bytes += res.bytes;
    }
    // gaussian: the bright pass, one direction's blur and the sum; mip: the bright pass and two
    // chains of levels of at most a third of it each (RGBA16F, 8 bytes a pixel).
    EXPECT_LE(bytes, std::size_t(3 * 8 * kW * kH)) << method;
  }
  EXPECT_EQ(bloom::planMipChain(d, kW, kH).levels, bloom::maxMipLevels(kW, kH));
  EXPECT_GT(r.counter("capped_octaves"), 0.0);
}

// Without bloom the post stage adds no pass and holds no resource: hdr is pre_post itself.
TEST(Bloom, OffIsFree) {
  BloomRenderer r(loadScene("contact"));
  r.render({"bloom"}, {"color"}, 160, 90);
  r.render({}, {"color"}, 160, 90);
  for (const auto& p : r.renderer.lastPasses()) EXPECT_EQ(p.name.rfind("bloom", 0), std::string::npos) << p.name;
  for (const auto& res : r.renderer.resources()) EXPECT_EQ(res.name.rfind("bloom", 0), std::string::npos) << res.name;
  EXPECT_EQ(r.renderer.colorVersionResource("hdr"), r.renderer.colorVersionResource("pre_post"));
}

// The CPU definition: the knee's w stays in [0, 1], is 0 below T - K, continuous across T - K and
// T + K (where the quadratic meets 0 and the linear part), and equals (luma - T)/luma above T + K.
TEST(BloomModel, SoftKneeWeightIsContinuousAndBounded) {
  bloom::Definition d;
  d.threshold = 1.0f;
  d.knee = 0.5f;
  for (float luma = 0.0f; luma < 4.0f; luma += 0.001f) {
    const float w = bloom::brightWeight(luma, d);
    ASSERT_GE(w, 0.0f) << luma;
    ASSERT_LE(w, 1.0f) << luma;
    if (luma < 0.5f) {
      ASSERT_EQ(w, 0.0f) << luma;
    }
    if (luma > 1.5f) {
      ASSERT_NEAR(w, (luma - 1.0f) / luma, 1e-4f) << luma;
    }
    ASSERT_LT(std::abs(bloom::brightWeight(luma + 1e-4f, d) - w), 1e-3f) << luma;
  }
}

// The mip plan: weights >= 0 summing to 1 (energy kept) for every sigma, octave count and frame
// size in the keys' ranges, levels within what the frame allows, and capped octaves only where an
// octave is wider than the deepest level.
TEST(BloomModel, MipPlanWeightsAreAPartitionOfUnity) {
  for (float sigma : {0.5f, 1.0f, 2.0f, 3.3f, 8.0f, 64.0f})
    for (int octaves = 1; octaves <= 10; ++octaves)
      for (auto [w, h] : {std::pair{64, 48}, std::pair{320, 180}, std::pair{1280, 720}, std::pair{3, 2}}) {
        bloom::Definition d;
        d.sigma = sigma;
        d.octaves = octaves;
        const bloom::MipPlan plan = bloom::planMipChain(d, w, h);
        ASSERT_LE(plan.levels, bloom::maxMipLevels(w, h));
        ASSERT_EQ(plan.weights.size(), std::size_t(plan.levels) + 1);
        double sum = 0;
        for (float a : plan.weights) {
          EXPECT_GE(a, 0.0f);
          sum += a;
        }
        EXPECT_NEAR(sum, 1.0, 1e-5) << sigma << " " << octaves << " " << w << "x" << h;
        const bool widestFits = bloom::octaveSigma(d, octaves - 1) <= bloom::mipLevelSigma(bloom::maxMipLevels(w, h));
        EXPECT_EQ(plan.cappedOctaves == 0, widestFits) << sigma << " " << octaves << " " << w << "x" << h;
      }
}

// The reference's convolution stops when told to (the viewer restarts it on every change): with the
// flag set it throws Error(Interrupted) before finishing its first pass.
TEST(BloomModel, ConvolutionStopsWhenCancelled) {
  Image bright(256, 256, 3);
  bright.at(128, 128, 0) = 1.0f;
  bloom::Definition d;
  std::atomic<bool> cancel{true};
  try {
    bloom::convolve(bright, d, 2, &cancel);
    FAIL() << "not cancelled";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Interrupted);
  }
  cancel = false;
  EXPECT_GT(bloom::convolve(bright, d, 2, &cancel).at(128, 128, 0), 0.0f);
}

} // namespace
} // namespace rtlab
