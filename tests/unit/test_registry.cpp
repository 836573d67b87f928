// frame/{registry,selection,stages,param_catalog,aovs}: registration checks, technique selection
// (exclusive vs stack stages, `none`, stage order), the stage table, the parameter catalog and AOV
// names. Uses its own TechniqueRegistry with fake entries (the generated one is not in rtlab_core).
#include "frame/aovs.h"
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "frame/selection.h"
#include "frame/stages.h"
#include "scene/scene.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include "test_util.h"

#include <algorithm>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

using namespace rtlab;
using rtlab::test::catchError;
using rtlab::test::Caught;
using rtlab::test::checkCaught;

namespace {


TechniqueEntry fake(const std::string& id, const std::string& stage, std::vector<ParamSpec> params = {},
                    std::vector<DebugView> views = {}) {
  TechniqueEntry e;
  e.info.id = id;
  e.info.stage = stage;
  e.info.title = "Fake " + id;
  e.info.params = std::move(params);
  e.info.debugViews = std::move(views);
  e.create = [] { return std::unique_ptr<Technique>(); }; // never called by these tests
  return e;
}

// shadow: sh_a, sh_b; ao: ao_a; indirect: ind_a; post (stack): post_a, post_b.
TechniqueRegistry fakeRegistry() {
  TechniqueRegistry r;
  r.add(fake("sh_a", "shadow", {ParamSpec::integer("sh_a.samples", "Samples", 16, 1, 64)},
             {{"sh_a.kernel", 1, "kernel weights"}}));
  r.add(fake("sh_b", "shadow", {ParamSpec::real("sh_b.radius", "Radius", 1.0, 0.0, 8.0)},
             {{"sh_b.blocker", 3, "blocker depth"}}));
  r.add(fake("ao_a", "ao", {ParamSpec::integer("ao_a.samples", "Samples", 8, 1, 32)}));
  r.add(fake("ind_a", "indirect"));
  r.add(fake("post_a", "post", {ParamSpec::real("post_a.strength", "Strength", 0.1, 0.0, 1.0)}));
  r.add(fake("post_b", "post"));
  return r;
}

class FakeTechnique : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo i;
    i.id = "fake_type";
    i.stage = "transparency";
    i.title = "Fake type";
    return i;
  }
  const TechniqueInfo& info() const override {
    static const TechniqueInfo i = staticInfo();
    return i;
  }
  void setup(FrameGraph&) override {}
};

// One light of each type over a unit box.
Scene fourLightScene() {
  Scene s;
  s.name = "hand";
  Mesh m;
  m.name = "box";
  m.bounds.extend(glm::vec3(-1));
  m.bounds.extend(glm::vec3(1));
  s.meshes.push_back(m);
  s.instances.push_back(Instance{0, glm::mat4(1), false});
  Light d;
  d.type = LightType::Directional;
  d.direction = {0, -1, 0};
  d.angle = 0.5f;
  Light p;
  p.type = LightType::Point;
  p.position = {0, 3, 0};
  p.radius = 0.1f;
  Light sp;
  sp.type = LightType::Spot;
  sp.position = {2, 3, 0};
  sp.direction = {0, -1, 0};
  sp.radius = 0.05f;
  Light r;
  r.type = LightType::Rect;
  r.position = {0, 2.5f, 0};
  r.direction = {0, -1, 0};
  r.width = 2;
  r.height = 1;
  s.lights = {d, p, sp, r};
  s.camera.position = {0, 1, 6};
  s.camera.target = {0, 0, 0};
  return s;
}

} // namespace

// ---- registry ----------------------------------------------------------------------------------

TEST(Registry, AddAndFind) {
  const TechniqueRegistry r = fakeRegistry();
  EXPECT_EQ(r.entries().size(), 6u);
  ASSERT_NE(r.find("sh_b"), nullptr);
  EXPECT_EQ(r.find("sh_b")->info.stage, "shadow");
  EXPECT_EQ(r.find("nope"), nullptr);
  EXPECT_EQ(&r.get("ao_a"), r.find("ao_a"));
  EXPECT_EQ(r.entries()[0].info.id, "sh_a"); // registration order
}

TEST(Registry, GetUnknownIsUsageListingKnownIds) {
  const TechniqueRegistry r = fakeRegistry();
  EXPECT_RTLAB_ERROR(r.get("pcss"), ExitCode::Usage, "unknown technique 'pcss'", "sh_a", "sh_b", "ao_a", "post_b",
                     "none");
  const TechniqueRegistry empty;
  const Caught c = catchError([&] { empty.get("x"); });
  checkCaught(c, ExitCode::Usage, {"unknown technique 'x'", "none"});
  EXPECT_EQ(c.message.find("(known: ,"), std::string::npos) << c.message;
}

TEST(Registry, BadRegistrationsAreInternal) {
  TechniqueRegistry r = fakeRegistry();
  EXPECT_RTLAB_ERROR(r.add(fake("sh_a", "ao")), ExitCode::Internal, "'sh_a'");
  EXPECT_RTLAB_ERROR(r.add(fake("x_a", "shadows")), ExitCode::Internal, "'x_a'", "'shadows'");
  EXPECT_RTLAB_ERROR(r.add(fake("x_b", "shadow", {ParamSpec::real("other.radius", "R", 1, 0, 2)})), ExitCode::Internal,
                     "'x_b'", "'other.radius'");
  EXPECT_RTLAB_ERROR(r.add(fake("x_c", "shadow", {ParamSpec::real("x_cc.radius", "R", 1, 0, 2)})), ExitCode::Internal,
                     "'x_cc.radius'");
  EXPECT_RTLAB_ERROR(r.add(fake("x_d", "shadow", {ParamSpec::real("x_d", "R", 1, 0, 2)})), ExitCode::Internal, "'x_d'");
  EXPECT_RTLAB_ERROR(r.add(fake("x_e", "shadow", {}, {{"depth", 1, ""}})), ExitCode::Internal, "'x_e'", "'depth'");
  EXPECT_RTLAB_ERROR(r.add(fake("x_f", "shadow", {}, {{"sh_a.kernel", 1, ""}})), ExitCode::Internal, "'sh_a.kernel'");
  EXPECT_EQ(r.entries().size(), 6u); // nothing half-added
  EXPECT_EQ(r.find("x_b"), nullptr);
}

TEST(Registry, DebugViewMayBeNamedExactlyItsTechnique) {
  // The technique's own output (bloom's AOV `bloom`) is a debug view named exactly the id; every
  // other view stays under `<id>.`, and no view shadows a built-in AOV.
  TechniqueRegistry r = fakeRegistry();
  r.add(fake("glow", "post", {}, {{"glow", 3, "the glow added to the colour"}, {"glow.bright", 3, "bright part"}}));
  EXPECT_NO_THROW(checkAovName("glow", {"glow"}, r));
  EXPECT_EQ(aovChannels("glow", r), 3);
  EXPECT_RTLAB_ERROR(checkAovName("glow", {}, r), ExitCode::Usage, "'glow'", "not active");
  const auto names = knownAovNames(r);
  EXPECT_NE(std::find(names.begin(), names.end(), "glow"), names.end());
  EXPECT_RTLAB_ERROR(r.add(fake("glo", "post", {}, {{"glow", 3, ""}})), ExitCode::Internal, "'glo'", "'glow'");
  EXPECT_RTLAB_ERROR(r.add(fake("glowing", "post", {}, {{"glow", 3, ""}})), ExitCode::Internal, "'glowing'", "'glow'");
  EXPECT_RTLAB_ERROR(r.add(fake("depth", "post", {}, {{"depth", 1, ""}})), ExitCode::Internal, "'depth'", "built-in");
  EXPECT_RTLAB_ERROR(r.add(fake("x_g", "post", {}, {{"x_g_", 1, ""}})), ExitCode::Internal, "'x_g_'");
  EXPECT_EQ(r.entries().size(), 7u); // nothing half-added
}

TEST(Registry, ReservedOrMalformedIdsAreInternal) {
  TechniqueRegistry r;
  // "none" is the -t keyword; stage ids, tonemap, camera and light<N> are key prefixes the frame
  // owns; ',' and '.' would break "-t a,b" and "<id>.<name>" keys.
  for (const char* id : {"none", "shadow", "ao", "post", "tonemap", "camera", "light0", "light12", "", "a,b", "a.b",
                         "Pcf", "pcf "})
    EXPECT_RTLAB_ERROR(r.add(fake(id, "post")), ExitCode::Internal, std::string("'") + id + "'");
  EXPECT_TRUE(r.entries().empty());
  r.add(fake("lightcuts", "post")); // "light" followed by letters is not a light<N> prefix
  r.add(fake("ssao2", "ao"));
  EXPECT_EQ(r.entries().size(), 2u);
}

TEST(Registry, RegisterTechniqueTypeCreates) {
  TechniqueRegistry r;
  registerTechniqueType<FakeTechnique>(r);
  const TechniqueEntry& e = r.get("fake_type");
  EXPECT_EQ(e.info.stage, "transparency");
  const auto t = e.create();
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->info().id, "fake_type");
  EXPECT_EQ(t->ownedBytes(), 0u);
}

// ---- selection ---------------------------------------------------------------------------------

TEST(Selection, ExclusiveStageReplaces) {
  const TechniqueRegistry r = fakeRegistry();
  TechniqueSelection s(r);
  s.activate("sh_a");
  EXPECT_EQ(s.ordered(), std::vector<std::string>{"sh_a"});
  s.activate("sh_b");
  EXPECT_EQ(s.ordered(), std::vector<std::string>{"sh_b"});
  EXPECT_FALSE(s.isActive("sh_a"));
  EXPECT_TRUE(s.isActive("sh_b"));
  s.activate("sh_b"); // again: still one
  EXPECT_EQ(s.ordered(), std::vector<std::string>{"sh_b"});
  s.activate("ao_a"); // another stage: kept beside
  EXPECT_EQ(s.ordered(), (std::vector<std::string>{"sh_b", "ao_a"}));
  s.activate("sh_a");
  EXPECT_EQ(s.ordered(), (std::vector<std::string>{"sh_a", "ao_a"}));
}

TEST(Selection, StackStageKeepsSeveral) {
  const TechniqueRegistry r = fakeRegistry();
  TechniqueSelection s(r);
  s.activate("post_a");
  s.activate("post_b");
  EXPECT_EQ(s.ordered(), (std::vector<std::string>{"post_a", "post_b"}));
  s.activate("post_a"); // no duplicate
  const auto o = s.ordered();
  EXPECT_EQ(o.size(), 2u);
  EXPECT_EQ(std::count(o.begin(), o.end(), "post_a"), 1);
  EXPECT_EQ(s.activeIn("post"), o.front());
}

TEST(Selection, NoneClears) {
  const TechniqueRegistry r = fakeRegistry();
  TechniqueSelection s(r);
  s.activateList("sh_a,ao_a,post_a,post_b");
  EXPECT_EQ(s.ordered().size(), 4u);
  s.activate("none");
  EXPECT_TRUE(s.ordered().empty());
  s.activateList("sh_a,none,post_b");
  EXPECT_EQ(s.ordered(), std::vector<std::string>{"post_b"});
  s.clear();
  EXPECT_TRUE(s.ordered().empty());
}

TEST(Selection, OrderedFollowsStageOrder) {
  const TechniqueRegistry r = fakeRegistry();
  TechniqueSelection s(r);
  s.activate("post_b");
  s.activate("ind_a");
  s.activate("ao_a");
  s.activate("post_a");
  s.activate("sh_b");
  EXPECT_EQ(s.ordered(), (std::vector<std::string>{"sh_b", "ao_a", "ind_a", "post_b", "post_a"}));
  EXPECT_EQ(s.activeIn("shadow"), "sh_b");
  EXPECT_EQ(s.activeIn("ao"), "ao_a");
  EXPECT_EQ(s.activeIn("post"), "post_b");
  EXPECT_EQ(s.activeIn("arealight"), "");
  s.deactivate("ao_a");
  s.deactivate("not_active"); // harmless
  EXPECT_EQ(s.ordered(), (std::vector<std::string>{"sh_b", "ind_a", "post_b", "post_a"}));
}

TEST(Selection, ActivateList) {
  const TechniqueRegistry r = fakeRegistry();
  TechniqueSelection s(r);
  s.activateList("sh_a,ao_a");
  EXPECT_EQ(s.ordered(), (std::vector<std::string>{"sh_a", "ao_a"}));
  s.activateList("sh_b"); // a later -t replaces within the exclusive stage
  EXPECT_EQ(s.ordered(), (std::vector<std::string>{"sh_b", "ao_a"}));
  TechniqueSelection t(r);
  t.activateList("post_a,sh_a,sh_b");
  EXPECT_EQ(t.ordered(), (std::vector<std::string>{"sh_b", "post_a"}));
}

TEST(Selection, EmptyEntriesAndUnknownIdsRejected) {
  const TechniqueRegistry r = fakeRegistry();
  for (const char* list : {"", ",", "sh_a,,ao_a", ",sh_a", "sh_a,", "sh_a,ao_a,"}) {
    TechniqueSelection s(r);
    EXPECT_RTLAB_ERROR(s.activateList(list), ExitCode::Usage, "empty technique");
  }
  TechniqueSelection s(r);
  EXPECT_RTLAB_ERROR(s.activateList("sh_a,pcss"), ExitCode::Usage, "unknown technique 'pcss'", "sh_a");
  EXPECT_RTLAB_ERROR(s.activate("sh_a "), ExitCode::Usage, "'sh_a '");
  EXPECT_RTLAB_ERROR(s.activate("NONE"), ExitCode::Usage, "'NONE'");
}

// ---- stages ------------------------------------------------------------------------------------

TEST(StageTable, ExactlyTheContractStagesInOrder) {
  std::vector<std::string> ids;
  for (const auto& s : stages()) ids.push_back(s.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"shadow", "ao", "indirect", "arealight", "transparency", "post"}));
  for (const auto& s : stages()) EXPECT_EQ(s.exclusive, s.id != "post") << s.id;
  EXPECT_EQ(findStage("shadow")->output, "visibility");
  EXPECT_EQ(findStage("ao")->output, "ao");
  EXPECT_EQ(findStage("indirect")->output, "indirect");
  EXPECT_EQ(findStage("post")->output, "color");
  EXPECT_EQ(findStage("tonemap"), nullptr);
  EXPECT_EQ(findStage(""), nullptr);
  EXPECT_EQ(findStage("Shadow"), nullptr);
}

TEST(StageParams, ShadowAndAoParamsWithDesignRanges) {
  ParamSet set;
  for (const auto& s : stages()) {
    set.declare(s.params); // every default inside its range
    for (const auto& p : s.params) EXPECT_EQ(p.key.rfind(s.id + ".", 0), 0u) << p.key;
  }
  const ParamSpec& res = set.spec("shadow.resolution");
  EXPECT_EQ(res.type, ParamType::Int);
  EXPECT_EQ(res.min, 256.0);
  EXPECT_EQ(res.max, 4096.0);
  EXPECT_TRUE(res.flags & kParamRealloc);
  EXPECT_EQ(set.spec("shadow.depth_format").type, ParamType::Enum);
  EXPECT_EQ(set.spec("shadow.constant_bias").type, ParamType::Float);
  EXPECT_EQ(set.spec("shadow.slope_bias").type, ParamType::Float);
  EXPECT_EQ(set.spec("shadow.normal_bias").type, ParamType::Float);
  EXPECT_EQ(set.spec("shadow.cull_front").type, ParamType::Bool);
  const ParamSpec& radius = set.spec("ao.radius");
  EXPECT_EQ(radius.type, ParamType::Float);
  EXPECT_GT(radius.min, 0.0);
  EXPECT_GT(radius.max, radius.min);
  set.setAssignment("shadow.resolution=256");
  set.setAssignment("shadow.resolution=4096");
  EXPECT_RTLAB_ERROR(set.setAssignment("shadow.resolution=255"), ExitCode::Usage, "'shadow.resolution'", "[256, 4096]");
  EXPECT_RTLAB_ERROR(set.setAssignment("shadow.resolution=4097"), ExitCode::Usage, "'shadow.resolution'", "[256, 4096]");
  EXPECT_EQ(set.getInt("shadow.resolution"), 4096);
  EXPECT_EQ(findStage("indirect")->params.size(), 0u);
}

TEST(StageParams, TonemapAndBuiltinAovs) {
  ParamSet set;
  set.declare(tonemapParams());
  EXPECT_EQ(set.spec("tonemap.exposure").type, ParamType::Float);
  EXPECT_EQ(set.spec("tonemap.operator").type, ParamType::Enum);
  std::vector<std::pair<std::string, int>> aovs;
  for (const auto& a : builtinAovs()) aovs.emplace_back(a.name, a.channels);
  EXPECT_EQ(aovs, (std::vector<std::pair<std::string, int>>{{"color", 3}, {"visibility", 1}, {"ao", 1}, {"indirect", 3},
                                                             {"arealight", 3}, {"transparency", 3}, {"depth", 1},
                                                             {"normal", 3}, {"albedo", 3}}));
}

TEST(StageParams, StageAovsComeFromTheStageTable) {
  // Each stage AOV is declared by its stage (docs/stages.md "Stage AOVs"); post defines none (the
  // AOV bloom is the bloom technique's own debug view).
  EXPECT_EQ(stageWithAov("visibility"), findStage("shadow"));
  EXPECT_EQ(stageWithAov("ao"), findStage("ao"));
  EXPECT_EQ(stageWithAov("indirect"), findStage("indirect"));
  EXPECT_EQ(stageWithAov("arealight"), findStage("arealight"));
  EXPECT_EQ(stageWithAov("transparency"), findStage("transparency"));
  EXPECT_EQ(stageWithAov("color"), nullptr);
  EXPECT_EQ(stageWithAov("bloom"), nullptr);
  EXPECT_TRUE(findStage("post")->aov.name.empty());
  EXPECT_EQ(findStage("arealight")->aov.rule, AovRule::TechniqueResource);
  EXPECT_EQ(findStage("arealight")->aov.neutral, 0.0f);
  EXPECT_EQ(findStage("transparency")->aov.rule, AovRule::ColorVersionCoverage);
  EXPECT_EQ(findStage("shadow")->aov.rule, AovRule::OutputOrNeutral);
  for (const auto& s : stages())
    if (!s.aov.name.empty()) {
      EXPECT_TRUE(isBuiltinAov(s.aov.name)) << s.id;
      EXPECT_FALSE(s.aov.help.empty()) << s.id;
    }
}

// ---- param catalog -----------------------------------------------------------------------------

TEST(Catalog, MakeParamSetHasEveryKind) {
  const TechniqueRegistry r = fakeRegistry();
  const Scene scene = fourLightScene();
  const ParamSet set = makeParamSet(scene, r);
  for (const char* k : {"tonemap.exposure", "tonemap.operator", "shadow.resolution", "shadow.depth_format",
                        "shadow.constant_bias", "shadow.slope_bias", "shadow.normal_bias", "shadow.cull_front",
                        "ao.radius", "sh_a.samples", "sh_b.radius", "ao_a.samples", "post_a.strength",
                        "light0.angle", "light0.direction", "light1.radius", "light1.position", "light2.direction",
                        "light3.width", "light3.height", "camera.position", "camera.target", "camera.fov"})
    EXPECT_TRUE(set.has(k)) << k;
  EXPECT_FALSE(set.has("light4.intensity"));
  EXPECT_FALSE(set.has("light0.radius"));
  EXPECT_EQ(set.getInt("sh_a.samples"), 16);           // inactive techniques' keys exist with defaults
  EXPECT_EQ(set.getVec3("light1.position"), glm::vec3(0, 3, 0)); // scene keys default to the scene
  EXPECT_EQ(set.specs().front().key, "tonemap.exposure"); // tonemap, stages, techniques, scene
  EXPECT_EQ(set.specs().back().key, "camera.fov");
}

TEST(Catalog, CollidingTechniqueKeysAreInternal) {
  TechniqueRegistry r;
  // A technique may not redeclare one key twice; the catalog reports it as a programming error.
  r.add(fake("dup", "post", {ParamSpec::real("dup.x", "X", 0, 0, 1), ParamSpec::real("dup.x", "X", 0, 0, 1)}));
  EXPECT_RTLAB_ERROR(makeParamSet(fourLightScene(), r), ExitCode::Internal, "'dup.x'");
}

// ---- AOVs --------------------------------------------------------------------------------------

TEST(Aov, BuiltinsAccepted) {
  const TechniqueRegistry r = fakeRegistry();
  for (const char* a : {"color", "visibility", "ao", "indirect", "arealight", "transparency", "depth", "normal", "albedo"}) {
    EXPECT_NO_THROW(checkAovName(a, {}, r)) << a;
    EXPECT_TRUE(isBuiltinAov(a)) << a;
  }
  EXPECT_FALSE(isBuiltinAov("sh_a.kernel"));
}

TEST(Aov, UnknownRejected) {
  const TechniqueRegistry r = fakeRegistry();
  for (const char* a : {"colour", "", "Color", "sh_a.nothing", "sh_a"})
    EXPECT_RTLAB_ERROR(checkAovName(a, {"sh_a"}, r), ExitCode::Usage, std::string("unknown AOV '") + a + "'", "color");
}

TEST(Aov, DebugViewNeedsItsTechniqueActive) {
  const TechniqueRegistry r = fakeRegistry();
  EXPECT_RTLAB_ERROR(checkAovName("sh_a.kernel", {}, r), ExitCode::Usage, "'sh_a.kernel'", "'sh_a'", "not active");
  EXPECT_RTLAB_ERROR(checkAovName("sh_b.blocker", {"sh_a", "ao_a"}, r), ExitCode::Usage, "'sh_b'");
  EXPECT_NO_THROW(checkAovName("sh_a.kernel", {"ao_a", "sh_a"}, r));
  EXPECT_EQ(aovChannels("sh_a.kernel", r), 1);
  EXPECT_EQ(aovChannels("sh_b.blocker", r), 3);
  EXPECT_EQ(aovChannels("normal", r), 3);
  EXPECT_EQ(aovChannels("depth", r), 1);
  EXPECT_RTLAB_ERROR(aovChannels("nope", r), ExitCode::Internal, "'nope'");
}

TEST(Aov, PngEncodingFollowsTheContract) {
  // docs/contract.md: color tone-mapped sRGB; normal n*0.5+0.5; depth normalized; the rest linear.
  EXPECT_EQ(pngEncodingForAov("color"), PngEncoding::Srgb);
  EXPECT_EQ(pngEncodingForAov("normal"), PngEncoding::Normal);
  EXPECT_EQ(pngEncodingForAov("depth"), PngEncoding::NormalizeRange);
  for (const char* a : {"visibility", "ao", "albedo", "indirect", "sh_a.kernel"})
    EXPECT_EQ(pngEncodingForAov(a), PngEncoding::Linear01) << a;
}
