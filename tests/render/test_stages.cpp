// The stage table as data, the colour versions and the HDR clamp (docs/stages.md):
// - an active arealight technique takes the rectangular lights away from the lighting pass;
// - the colour versions lit, pre_post and hdr are readable, alias each other when no pass changes
//   the colour in between, and each colour-stage technique reads and writes the versions the
//   renderer names (FrameGraph::colorInput/colorOutput);
// - an emitter of 1e5 stays finite (65504) and the clamped pixels are counted per pass.
// Fake colour-stage techniques without shaders (copy, constant fill, nothing) stand in for the
// second-wave techniques; they are registered in a registry of the test's own.
#include "render_fixture.h"

#include "../support/fake_technique.h"
#include "../support/test_util.h"
#include "frame/frame_graph.h"
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "frame/stages.h"
#include "gl/debug.h"
#include "scene/builtin_scenes.h"
#include "scene/load.h"
#include "scene/mesh_builder.h"
#include "techniques/common/arealight/arealight_composite.h"
#include "frame/frame_view.h"
#include "shading/base_passes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace rtlab {
namespace {

constexpr int kW = 160, kH = 96;

// What a fake colour-stage technique does with the colour.
enum class FakeColor { Copy, Fill, Nothing };

class FakeColorTechnique : public Technique {
public:
  FakeColorTechnique(TechniqueInfo info, FakeColor mode, glm::vec4 fill) : m_info(std::move(info)), m_mode(mode), m_fill(fill) {}
  const TechniqueInfo& info() const override { return m_info; }
  void setup(FrameGraph& frame) override {
    if (m_mode == FakeColor::Nothing) return;
    const std::string in = frame.colorInput(), out = frame.colorOutput();
    ASSERT_FALSE(in.empty());
    ASSERT_FALSE(out.empty());
    ASSERT_NE(in, out);
    const FakeColor mode = m_mode;
    const glm::vec4 fill = m_fill;
    frame.addPass(m_info.id + ".color",
        [&](PassBuilder& b) {
          b.read(in);
          b.write(out, frameTexture(frame, GL_RGBA16F));
        },
        [in, out, mode, fill](PassContext& ctx) {
          const gl::Texture& src = ctx.texture(in);
          if (mode == FakeColor::Fill) glClearTexImage(ctx.texture(out).id(), 0, GL_RGBA, GL_FLOAT, &fill.x);
          else
            glCopyImageSubData(src.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.texture(out).id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                               src.desc().width, src.desc().height, 1);
        });
  }

private:
  TechniqueInfo m_info;
  FakeColor m_mode;
  glm::vec4 m_fill;
};

TechniqueEntry fakeColor(const std::string& id, const std::string& stage, FakeColor mode, glm::vec4 fill = glm::vec4(0)) {
  TechniqueEntry e = test::fakeTechnique(id, stage);
  e.create = [info = e.info, mode, fill] { return std::make_unique<FakeColorTechnique>(info, mode, fill); };
  return e;
}

// A fake arealight technique: writes the frame resource `arealight` (the stage's AOV, docs/stages.md
// "Stage AOVs") as a constant radiance and adds it to the colour it is handed.
constexpr glm::vec4 kFakeAreaRadiance(0.25f, 0.5f, 0.75f, 1.0f);

class FakeAreaAovTechnique : public Technique {
public:
  explicit FakeAreaAovTechnique(TechniqueInfo info) : m_info(std::move(info)) {}
  const TechniqueInfo& info() const override { return m_info; }
  void setup(FrameGraph& frame) override {
    const std::string in = frame.colorInput(), out = frame.colorOutput();
    frame.addPass(m_info.id + ".radiance", [&](PassBuilder& b) { b.write("arealight", frameTexture(frame, GL_RGBA16F)); },
        [](PassContext& ctx) { glClearTexImage(ctx.texture("arealight").id(), 0, GL_RGBA, GL_FLOAT, &kFakeAreaRadiance.x); });
    frame.addPass(m_info.id + ".color",
        [&](PassBuilder& b) {
          b.read(in);
          b.read("arealight");
          b.write(out, frameTexture(frame, GL_RGBA16F));
        },
        [in, out](PassContext& ctx) {
          const gl::Texture& src = ctx.texture(in);
          glCopyImageSubData(src.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.texture(out).id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                             src.desc().width, src.desc().height, 1);
        });
  }

private:
  TechniqueInfo m_info;
};

// A fake arealight technique that ends as the real ones do: a constant `arealight` and the
// family's composite (techniques/common/arealight/arealight_composite.h).
class FakeAreaCompositeTechnique : public Technique {
public:
  explicit FakeAreaCompositeTechnique(TechniqueInfo info) : m_info(std::move(info)) {}
  const TechniqueInfo& info() const override { return m_info; }
  void setup(FrameGraph& frame) override {
    frame.addPass(m_info.id + ".radiance", [&](PassBuilder& b) { b.write(kArealightResource, frameTexture(frame, GL_RGBA16F)); },
        [](PassContext& ctx) { glClearTexImage(ctx.texture(kArealightResource).id(), 0, GL_RGBA, GL_FLOAT, &kFakeAreaRadiance.x); });
    addArealightComposite(frame, m_info.id);
  }

private:
  TechniqueInfo m_info;
};

// The built-in techniques plus the fakes.
const TechniqueRegistry& testRegistry() {
  static const TechniqueRegistry registry = [] {
    TechniqueRegistry r;
    registerAllTechniques(r);
    r.add(fakeColor("fake_area", "arealight", FakeColor::Copy));
    TechniqueEntry areaAov = test::fakeTechnique("fake_area_aov", "arealight");
    areaAov.create = [info = areaAov.info] { return std::make_unique<FakeAreaAovTechnique>(info); };
    r.add(areaAov);
    TechniqueEntry areaComposite = test::fakeTechnique("fake_area_composite", "arealight");
    areaComposite.create = [info = areaComposite.info] { return std::make_unique<FakeAreaCompositeTechnique>(info); };
    r.add(areaComposite);
    r.add(fakeColor("fake_copy", "post", FakeColor::Copy));
    r.add(fakeColor("fake_fill", "post", FakeColor::Fill, glm::vec4(1, 2, 3, 1)));
    r.add(fakeColor("fake_none", "post", FakeColor::Nothing));
    return r;
  }();
  return registry;
}

// One renderer per test: renders frames of a scene with the given techniques and colour versions.
struct StageRenderer {
  Renderer renderer{testRegistry()};
  ParamSet params;

  explicit StageRenderer(const Scene& scene) { setScene(scene); }
  void setScene(const Scene& scene) {
    renderer.setScene(scene);
    params = makeParamSet(scene, testRegistry());
  }
  void render(const std::vector<std::string>& techniques, const std::vector<std::string>& aovs,
              const std::vector<std::string>& colors = {}, bool countHdrClamped = false) {
    FrameOutputs outputs;
    outputs.aovs = aovs;
    outputs.colors = colors;
    outputs.countHdrClamped = countHdrClamped;
    renderOwnFrame(renderer, params, techniques, outputs, kW, kH);
  }
  bool ran(const std::string& pass) const {
    const auto& passes = renderer.lastPasses();
    return std::any_of(passes.begin(), passes.end(), [&](const Renderer::PassInfo& p) { return p.name == pass && p.kept; });
  }
  bool hasResource(const std::string& name) const {
    const auto list = renderer.resources();
    return std::any_of(list.begin(), list.end(), [&](const ResourceUse& r) { return r.name == name; });
  }
};

int differingPixels(const Image& a, const Image& b, float tolerance = 0.0f) {
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  int n = 0;
  for (std::size_t i = 0; i < a.pixelCount(); ++i) {
    bool differs = false;
    for (int c = 0; c < a.channels; ++c)
      differs |= std::abs(a.pixels[i * a.channels + c] - b.pixels[i * b.channels + c]) > tolerance;
    n += differs ? 1 : 0;
  }
  return n;
}

float luminanceSum(const Image& img) {
  double sum = 0.0;
  for (float v : img.pixels) sum += v;
  return float(sum);
}

// ---- the stage table --------------------------------------------------------------------------

TEST(StageDeclarations, OrderPredicatesNeutralsAndLightingEffects) {
  const auto& table = stages();
  for (std::size_t i = 0; i < table.size(); ++i) EXPECT_EQ(table[i].order, int(i)) << table[i].id;
  EXPECT_EQ(findStage("shadow")->neutral, 1.0f);
  EXPECT_EQ(findStage("ao")->neutral, 1.0f);
  EXPECT_EQ(findStage("indirect")->neutral, 0.0f);
  EXPECT_EQ(findStage("shadow")->lighting, LightingEffect::MultiplyLight0Direct);
  EXPECT_EQ(findStage("ao")->lighting, LightingEffect::MultiplyAmbientIndirect);
  EXPECT_EQ(findStage("indirect")->lighting, LightingEffect::AddIndirect);
  EXPECT_EQ(findStage("arealight")->lighting, LightingEffect::ReplaceRectLights);
  EXPECT_EQ(findStage("transparency")->lighting, LightingEffect::TransformColor);
  EXPECT_EQ(findStage("post")->lighting, LightingEffect::TransformColor);
  EXPECT_EQ(findStage("arealight")->predicate, StagePredicate::RectLight);
  EXPECT_EQ(findStage("transparency")->predicate, StagePredicate::TransparentMaterial);
  EXPECT_EQ(findStage("transparency")->fallback, "transparent");
  // The stages that feed the lighting pass come before every colour stage.
  bool colorSeen = false;
  for (const auto& s : table) {
    if (s.feedsLighting()) EXPECT_FALSE(colorSeen) << s.id;
    else colorSeen = true;
    EXPECT_EQ(s.feedsLighting(), s.colorVersion.empty()) << s.id;
  }
  EXPECT_EQ(colorVersions(), (std::vector<std::string>{"lighting", "lit", "pre_post", "hdr"}));
  const Scene arealight = loadScene("arealight"), cornell = loadScene("cornell"), panes = loadScene("panes");
  EXPECT_TRUE(findStage("arealight")->appliesTo(arealight));
  EXPECT_FALSE(findStage("arealight")->appliesTo(cornell));
  EXPECT_TRUE(findStage("transparency")->appliesTo(panes));
  EXPECT_FALSE(findStage("transparency")->appliesTo(cornell));
  EXPECT_TRUE(findStage("post")->appliesTo(cornell));
}

// ---- arealight: rectangular lights are no longer added as points -------------------------------

TEST(ArealightStage, ActiveTechniqueTakesRectLightsAwayFromLighting) {
  const Scene scene = loadScene("arealight");
  ASSERT_TRUE(scene.hasAreaLight());
  Scene withoutRect = scene;
  withoutRect.name = "arealight_without_rect";
  std::erase_if(withoutRect.lights, [](const Light& l) { return l.type == LightType::Rect; });
  ASSERT_EQ(withoutRect.lights.size() + 1, scene.lights.size());

  StageRenderer r(scene);
  r.render({}, {"color"});
  EXPECT_FALSE(r.ran("fake_area.color"));
  const Image off = r.renderer.readAov("color");
  r.render({"fake_area"}, {"color"}, {"lighting", "lit"});
  ASSERT_TRUE(r.ran("fake_area.color"));
  const Image on = r.renderer.readAov("color");
  // The technique reads the lighting pass's own version and writes lit (which is also the final colour).
  EXPECT_EQ(r.renderer.colorVersionResource("lighting"), "color.lighting");
  EXPECT_EQ(r.renderer.colorVersionResource("lit"), "color.hdr");
  EXPECT_EQ(differingPixels(r.renderer.readColor("lighting"), r.renderer.readColor("lit")), 0); // a copy

  r.setScene(withoutRect);
  r.render({}, {"color"});
  const Image noRect = r.renderer.readAov("color");

  // On: the lighting pass added every light but the rectangle (the fake adds nothing back).
  EXPECT_EQ(differingPixels(on, noRect), 0);
  // Off: the rectangle is added as a point, so where it shines the frame is brighter.
  const int lit = differingPixels(off, on, 1e-3f);
  EXPECT_GT(lit, kW * kH / 10) << "the rectangle lights the floor below it";
  for (std::size_t i = 0; i < off.pixels.size(); ++i) ASSERT_GE(off.pixels[i], on.pixels[i] - 1e-6f) << i;
  EXPECT_GT(luminanceSum(off), luminanceSum(on));
}

// The window pixel (x right, y down) where the camera sees world point p.
glm::ivec2 pixelOf(const Scene& scene, const glm::vec3& p) {
  const FrameView view = makeFrameView(scene.camera, kW, kH);
  const glm::vec4 clip = view.viewProj * glm::vec4(p, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {int((ndc.x * 0.5f + 0.5f) * kW), int((0.5f - ndc.y * 0.5f) * kH)};
}

// docs/contract.md "Area lights": the emitting face is drawn into `color` only. In `arealight` the
// camera is below the downward-facing rectangle, so it sees the emitting face against the
// background: there `color` is L_e (10 nits), data AOVs see the background behind it (A = 0). With
// an arealight technique the family's composite draws the face (not the lighting pass), adds the
// technique's radiance on surfaces and nothing on the background.
TEST(ArealightStage, EmittingFaceIsInColorOnly) {
  const Scene scene = loadScene("arealight");
  const Light& rect = scene.lights.at(1);
  ASSERT_EQ(rect.type, LightType::Rect);
  const glm::ivec2 face = pixelOf(scene, rect.position);
  const glm::ivec2 beside = pixelOf(scene, rect.position + rect.right * (0.5f * rect.width + 0.3f));
  const glm::vec3 le = rect.color * rect.intensity;

  StageRenderer r(scene);
  for (const std::vector<std::string>& techniques : {std::vector<std::string>{}, std::vector<std::string>{"fake_area_composite"}}) {
    r.render(techniques, {"color", "depth"}, {"lighting"});
    const Image color = r.renderer.readAov("color");
    const Image depth = r.renderer.readAov("depth");
    for (int c = 0; c < 3; ++c) EXPECT_EQ(color.at(face.x, face.y, c), le[c]) << "face pixel, channel " << c;
    EXPECT_EQ(depth.mask[std::size_t(face.y) * kW + face.x], 0.0f) << "the face is not in the G-buffer";
    for (int c = 0; c < 3; ++c) EXPECT_EQ(color.at(beside.x, beside.y, c), 0.0f) << "background beside the face";
    if (techniques.empty()) continue;
    ASSERT_TRUE(r.ran("fake_area_composite.composite"));
    // The lighting pass drew no face (SKIP_RECT_LIGHTS) and the composite added the constant on
    // surfaces only.
    const Image lighting = r.renderer.readColor("lighting");
    EXPECT_EQ(lighting.at(face.x, face.y, 0), 0.0f);
    int surfaces = 0;
    for (std::size_t i = 0; i < color.pixelCount(); ++i) {
      const int x = int(i % kW), y = int(i / kW);
      const bool onSurface = depth.mask[i] > 0.5f;
      if (!onSurface && color.at(x, y, 0) > 0.0f) continue; // the face
      surfaces += onSurface ? 1 : 0;
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(color.at(x, y, c), lighting.at(x, y, c) + (onSurface ? kFakeAreaRadiance[c] : 0.0f),
                    2e-3f * (1.0f + lighting.at(x, y, c)))
            << x << "," << y << " channel " << c;
    }
    EXPECT_GT(surfaces, kW * kH / 3); // the floor, the sphere and the box: about half the frame
  }
}

TEST(ArealightStage, NoRectLightNoStage) {
  StageRenderer r(loadScene("cornell"));
  r.render({}, {"color"});
  const Image off = r.renderer.readAov("color");
  r.render({"fake_area"}, {"color"});
  EXPECT_FALSE(r.ran("fake_area.color")); // predicate: the scene has no rectangular light
  EXPECT_EQ(differingPixels(off, r.renderer.readAov("color")), 0);
}

// ---- stage AOVs (docs/stages.md "Stage AOVs") ---------------------------------------------------

// The G-buffer's surface mask of the last frame (any data AOV carries it; depth is the cheapest).
std::vector<float> surfaceMask(StageRenderer& r, const std::string& aov) {
  r.render(r.renderer.techniques(), {aov, "depth"});
  return r.renderer.readAov("depth").mask;
}

int count(const std::vector<float>& mask, float value) { return int(std::count(mask.begin(), mask.end(), value)); }

TEST(StageAovs, ArealightIsZeroWithoutRectLight) {
  StageRenderer r(loadScene("cornell"));
  for (const std::vector<std::string>& techniques : {std::vector<std::string>{}, std::vector<std::string>{"fake_area_aov"}}) {
    r.renderer.setTechniques(techniques);
    const std::vector<float> mask = surfaceMask(r, "arealight");
    const Image area = r.renderer.readAov("arealight");
    EXPECT_FALSE(r.ran("fake_area_aov.radiance")); // the stage does not apply to cornell
    ASSERT_EQ(area.channels, 3);
    for (float v : area.pixels) ASSERT_EQ(v, 0.0f);
    EXPECT_EQ(area.mask, mask);
    EXPECT_GT(count(mask, 1.0f), kW * kH / 2);
  }
}

TEST(StageAovs, ArealightOnARectLightSceneNeedsATechnique) {
  // The lighting pass's point approximation of the rectangle is in the colour: the frame holds no
  // arealight value, so asking for it is a usage error naming the registered arealight techniques.
  StageRenderer r(loadScene("arealight"));
  r.renderer.setTechniques({});
  EXPECT_RTLAB_ERROR(r.renderer.checkAov("arealight"), ExitCode::Usage, "'arealight'", "arealight technique",
                     "-t fake_area_aov");
  FrameOutputs outputs;
  outputs.aovs = {"arealight"};
  PassTimer timer(TimingMethod::CpuFinish);
  EXPECT_RTLAB_ERROR(r.renderer.render(r.params, kW, kH, outputs, timer), ExitCode::Usage, "'arealight'");
}

TEST(StageAovs, ArealightIsTheTechniquesResource) {
  StageRenderer r(loadScene("arealight"));
  r.renderer.setTechniques({"fake_area_aov"});
  EXPECT_NO_THROW(r.renderer.checkAov("arealight"));
  const std::vector<float> mask = surfaceMask(r, "arealight");
  ASSERT_TRUE(r.ran("fake_area_aov.radiance"));
  const Image area = r.renderer.readAov("arealight");
  EXPECT_EQ(area.mask, mask);
  for (std::size_t i = 0; i < area.pixelCount(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(area.pixels[i * 3 + c], mask[i] * kFakeAreaRadiance[c]) << i;
  // A technique of the stage that does not write the resource is the technique's bug: the graph
  // refuses the read instead of writing a neutral value.
  r.renderer.setTechniques({"fake_area"});
  EXPECT_NO_THROW(r.renderer.checkAov("arealight"));
  FrameOutputs outputs;
  outputs.aovs = {"arealight"};
  PassTimer timer(TimingMethod::CpuFinish);
  EXPECT_THROW(r.renderer.render(r.params, kW, kH, outputs, timer), Error);
}

TEST(StageAovs, TransparencyIsPrePostWithLayerCoverage) {
  // panes as shipped (no pane lies over the background there) and panes without its opaque
  // instances (every pane lies over the background).
  const Scene panes = loadScene("panes");
  Scene layersOnly = panes;
  layersOnly.name = "panes_layers_only";
  std::erase_if(layersOnly.instances, [](const Instance& i) { return !i.transparent; });
  ASSERT_TRUE(layersOnly.hasTransparency());
  int layerOverBackground = 0, empty = 0, surfaces = 0;
  StageRenderer r(panes);
  for (const Scene* scene : std::initializer_list<const Scene*>{&panes, &layersOnly}) {
    r.setScene(*scene);
    r.render({}, {"transparency", "depth"}, {"lit", "pre_post"});
    ASSERT_TRUE(r.ran("transparent"));
    const Image trans = r.renderer.readAov("transparency"), prePost = r.renderer.readColor("pre_post");
    const Image lit = r.renderer.readColor("lit");
    const std::vector<float> surface = r.renderer.readAov("depth").mask;
    EXPECT_EQ(differingPixels(trans, prePost), 0) << scene->name;
    EXPECT_GT(differingPixels(trans, lit, 1e-3f), kW * kH / 20) << "the panes are in it";
    for (std::size_t i = 0; i < trans.pixelCount(); ++i) {
      if (surface[i] == 1.0f) {
        ASSERT_EQ(trans.mask[i], 1.0f) << i; // an opaque surface covers it
        ++surfaces;
        continue;
      }
      // Background: covered exactly where a layer changed the colour (lit there is the background).
      bool layer = false;
      for (int c = 0; c < 3; ++c) layer |= trans.pixels[i * 3 + c] != lit.pixels[i * 3 + c];
      ASSERT_EQ(trans.mask[i], layer ? 1.0f : 0.0f) << scene->name << " pixel " << i;
      (layer ? layerOverBackground : empty) += 1;
    }
  }
  RecordProperty("layer_over_background_pixels", layerOverBackground); // docs/stages.md quotes them
  RecordProperty("empty_background_pixels", empty);
  RecordProperty("surface_pixels", surfaces);
  EXPECT_GT(layerOverBackground, 0);
  EXPECT_GT(empty, 0);
  EXPECT_GT(surfaces, 0);
}

TEST(StageAovs, TransparencyWithoutTransparentMaterialIsColor) {
  StageRenderer r(loadScene("contact"));
  r.render({}, {"transparency", "color"});
  const Image trans = r.renderer.readAov("transparency"), color = r.renderer.readAov("color");
  EXPECT_EQ(differingPixels(trans, color), 0);
  EXPECT_EQ(trans.mask, color.mask);
}

// ---- colour versions ---------------------------------------------------------------------------

TEST(ColorVersions, TransparencyWritesPrePostAndLitStaysTheOpaqueFrame) {
  const Scene panes = loadScene("panes");
  StageRenderer r(panes);
  r.render({}, {"color"}, {"lighting", "lit", "pre_post", "hdr"});
  ASSERT_TRUE(r.ran("transparent"));
  const Image lit = r.renderer.readColor("lit"), prePost = r.renderer.readColor("pre_post");
  const Image hdr = r.renderer.readColor("hdr"), color = r.renderer.readAov("color");
  EXPECT_EQ(r.renderer.colorVersionResource("lit"), "color.lit");
  EXPECT_EQ(r.renderer.colorVersionResource("pre_post"), "color.hdr"); // no post technique: an alias
  EXPECT_GT(differingPixels(lit, prePost, 1e-3f), kW * kH / 20) << "the panes cover part of the frame";
  // No post technique: pre_post is the final colour, which the AOV copies exactly.
  EXPECT_EQ(differingPixels(prePost, hdr), 0);
  EXPECT_EQ(differingPixels(hdr, color), 0);
  EXPECT_EQ(hdr.mask, color.mask);

  // lit is the opaque frame: the same scene without its transparent instances.
  Scene opaque = panes;
  opaque.name = "panes_opaque";
  std::erase_if(opaque.instances, [](const Instance& i) { return i.transparent; });
  ASSERT_FALSE(opaque.hasTransparency());
  r.setScene(opaque);
  r.render({}, {"color"});
  EXPECT_FALSE(r.ran("transparent"));
  EXPECT_EQ(differingPixels(lit, r.renderer.readAov("color")), 0);
}

TEST(ColorVersions, WithoutColorStagesEveryVersionIsOneTextureNoCopy) {
  StageRenderer r(loadScene("contact"));
  r.render({}, {"color"}, {"lit", "pre_post", "hdr"});
  for (const auto& v : colorVersions()) EXPECT_EQ(r.renderer.colorVersionResource(v), "color.hdr") << v;
  EXPECT_TRUE(r.hasResource("color.hdr"));
  for (const char* name : {"color.lighting", "color.lit", "color.pre_post"}) EXPECT_FALSE(r.hasResource(name)) << name;
  EXPECT_EQ(differingPixels(r.renderer.readColor("lit"), r.renderer.readAov("color")), 0);
}

TEST(ColorVersions, PostStackReadsPrePostAndWritesHdr) {
  StageRenderer r(loadScene("contact"));
  r.render({}, {"color"});
  const Image plain = r.renderer.readAov("color");

  // Two stacked post techniques: the first writes an intermediate, the last writes hdr.
  r.render({"fake_copy", "fake_fill"}, {"color"}, {"pre_post", "hdr"});
  ASSERT_TRUE(r.ran("fake_copy.color"));
  ASSERT_TRUE(r.ran("fake_fill.color"));
  EXPECT_EQ(r.renderer.colorVersionResource("pre_post"), "color.pre_post");
  EXPECT_EQ(r.renderer.colorVersionResource("hdr"), "color.hdr");
  EXPECT_TRUE(r.hasResource("color.after_fake_copy"));
  EXPECT_EQ(differingPixels(r.renderer.readColor("pre_post"), plain), 0);
  const Image hdr = r.renderer.readColor("hdr");
  for (std::size_t i = 0; i < hdr.pixelCount(); ++i)
    ASSERT_TRUE(hdr.pixels[i * 3] == 1.0f && hdr.pixels[i * 3 + 1] == 2.0f && hdr.pixels[i * 3 + 2] == 3.0f) << i;
  EXPECT_EQ(differingPixels(hdr, r.renderer.readAov("color")), 0); // AOV color reads the final version

  // A post technique that adds no pass leaves the colour as it was: hdr aliases pre_post.
  r.render({"fake_none"}, {"color"}, {"pre_post", "hdr"});
  EXPECT_EQ(r.renderer.colorVersionResource("hdr"), r.renderer.colorVersionResource("pre_post"));
  EXPECT_EQ(differingPixels(r.renderer.readColor("hdr"), plain), 0);
}

// ---- the HDR clamp -----------------------------------------------------------------------------

// A grey floor, an opaque red emitter of 1e5 facing the camera and, beside it, a transparent blue
// pane emitting 1e5 (alpha 0.5); one directional light.
Scene hdrScene() {
  builtin::SceneBuilder b("hdr_emitters");
  const int floor = b.addMaterial(builtin::diffuseMaterial("floor", glm::vec3(0.5f)));
  Material emitter = builtin::diffuseMaterial("emitter", {1.0f, 0.0f, 0.0f});
  emitter.emissive = glm::vec3(1e5f);
  const int emitterMat = b.addMaterial(emitter);
  Material pane = builtin::diffuseMaterial("pane", {0.0f, 0.0f, 1.0f});
  pane.emissive = glm::vec3(1e5f);
  pane.baseColor.w = 0.5f;
  pane.alphaMode = AlphaMode::Blend;
  pane.doubleSided = true;
  const int paneMat = b.addMaterial(pane);
  b.addObject(makePlane("floor", 8.0f, 8.0f), floor);
  b.addObject(makeQuad("emitter", {-0.8f, 1.0f, 0.0f}, {0.5f, 0, 0}, {0, 0.5f, 0}), emitterMat);
  b.addObject(makeQuad("pane", {0.8f, 1.0f, 0.0f}, {0.5f, 0, 0}, {0, 0.5f, 0}), paneMat);
  b.addLight(builtin::directionalLight("key", {-0.3f, -1.0f, -0.5f}, 3.0f, 0.5f));
  return b.finish(builtin::camera({0, 1.2f, 4.0f}, {0, 0.9f, 0}, 45.0f));
}

std::uint64_t clampedPixels(const std::vector<HdrClampCount>& counts, const std::string& pass) {
  for (const auto& c : counts)
    if (c.pass == pass) return c.pixels;
  ADD_FAILURE() << "no HDR clamp count for pass '" << pass << "'";
  return 0;
}

// Where a driver rounds a float above 65504 to +inf when it writes a 16-bit target (the hardware
// behaviour the clamp exists for), the finite checks fail without the clamp. llvmpipe saturates the
// conversion to 65504 by itself (measured: with the clamp removed from hdr.glsl and gbuffer.frag
// these checks still pass there), so on llvmpipe it is the counts that fail without the change.
TEST(HdrClamp, EmitterOf1e5IsFiniteAndCountedPerPass) {
  StageRenderer r(hdrScene());
  r.render({}, {"color", "albedo"}, {"lit", "pre_post"}, true);
  const Image color = r.renderer.readAov("color"), albedo = r.renderer.readAov("albedo");
  const Image lit = r.renderer.readColor("lit"), prePost = r.renderer.readColor("pre_post");

  // The opaque emitter's pixels, from the G-buffer: red albedo.
  std::uint64_t emitterPixels = 0;
  for (std::size_t i = 0; i < albedo.pixelCount(); ++i) {
    const bool emitter = albedo.mask[i] > 0.5f && albedo.pixels[i * 3] > 0.99f && albedo.pixels[i * 3 + 1] < 0.01f;
    if (!emitter) continue;
    ++emitterPixels;
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(std::isfinite(lit.pixels[i * 3 + c])) << "pixel " << i << ": without the clamp the emitter is +inf";
      EXPECT_EQ(lit.pixels[i * 3 + c], 65504.0f) << i;
    }
  }
  EXPECT_GT(emitterPixels, 200u);
  // The transparent pane's pixels: where the transparent pass changed the colour.
  const std::uint64_t panePixels = std::uint64_t(differingPixels(lit, prePost, 1.0f));
  EXPECT_GT(panePixels, 200u);
  for (float v : color.pixels) ASSERT_TRUE(std::isfinite(v));

  const auto counts = r.renderer.readHdrClamped();
  EXPECT_EQ(clampedPixels(counts, "gbuffer"), emitterPixels);
  EXPECT_EQ(clampedPixels(counts, "lighting"), emitterPixels);
  EXPECT_EQ(clampedPixels(counts, "transparent"), panePixels);

  // Counters start from zero every counted frame; a frame that does not count leaves them.
  r.render({}, {"color"}, {}, true);
  EXPECT_EQ(clampedPixels(r.renderer.readHdrClamped(), "lighting"), emitterPixels);
  r.render({}, {"color"});
  EXPECT_EQ(clampedPixels(r.renderer.readHdrClamped(), "lighting"), emitterPixels);
  // Without counting the clamp still holds.
  for (float v : r.renderer.readAov("color").pixels) ASSERT_TRUE(std::isfinite(v) && v <= 65504.0f);
}

TEST(HdrClamp, NothingClampedInAnOrdinaryFrame) {
  StageRenderer r(loadScene("cornell"));
  r.render({}, {"color"}, {}, true);
  const auto counts = r.renderer.readHdrClamped();
  EXPECT_EQ(clampedPixels(counts, "gbuffer"), 0u);
  EXPECT_EQ(clampedPixels(counts, "lighting"), 0u);
  for (const auto& c : counts) EXPECT_NE(c.pass, "transparent") << "cornell has no transparent surface";
}

} // namespace
} // namespace rtlab
