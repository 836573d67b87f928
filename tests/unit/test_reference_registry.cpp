// References per stage (reference/reference_registry.h, docs/measuring.md "References per stage"):
// the three built-in references with their stages, inputs and keys; which keys define a reference
// and so enter the sweep's reference hash; a reference reading the colour before post depending on
// every key before post; registration errors; a reference reading only what it declared.
#include "fake_technique.h"
#include "frame/param_catalog.h"
#include "reference/reference_registry.h"
#include "scene/builtin.h"
#include "test_util.h"
#include "util/hash.h"

#include <gtest/gtest.h>

using namespace rtlab;

namespace {

using Strings = std::vector<std::string>;

ReferenceRegistry builtins() {
  ReferenceRegistry r;
  registerBuiltinReferences(r);
  return r;
}

ReferenceEntry testEntry(const std::string& aov, const std::string& stage, Strings keys = {},
                         FrameInputs inputs = {}) {
  ReferenceEntry e;
  e.aov = aov;
  e.stage = stage;
  e.keys = std::move(keys);
  e.inputs = inputs;
  e.compute = [](const ReferenceFrame&, ReferenceStats&) { return Image(1, 1, 1); };
  return e;
}

// Techniques of two stages, so that keys of both kinds exist in the parameter set.
TechniqueRegistry testTechniques() {
  TechniqueRegistry t;
  t.add(test::fakeTechnique("tq", "shadow", {ParamSpec::integer("tq.samples", "Samples", 16, 1, 64)}));
  t.add(test::fakeTechnique("bl", "post", {ParamSpec::real("bl.sigma", "Sigma", 2, 0.5, 32)}));
  t.add(test::fakeTechnique("bx", "post", {ParamSpec::real("bx.gain", "Gain", 1, 0, 4)}));
  return t;
}

std::string keyHash(const ReferenceEntry& e, const ParamSet& params, const TechniqueRegistry& techniques) {
  Fnv1a64 h;
  hashReferenceKeys(e, params, techniques, h);
  return h.hex();
}

} // namespace

// The three of the Embree ray caster, and the transparency stage's (which belongs to no technique).
TEST(ReferenceRegistry, ListsTheBuiltinsWithTheirStagesAndKeys) {
  const ReferenceRegistry r = builtins();
  ASSERT_EQ(r.entries().size(), 4u);
  EXPECT_EQ(r.choices(), "visibility, ao, indirect, transparency");
  const Strings lightCamera = {"light<N>.", "camera."};
  const Strings withRadius = {"light<N>.", "camera.", "ao.radius"};
  EXPECT_EQ(r.get("visibility").stage, "shadow");
  EXPECT_EQ(r.get("visibility").keys, lightCamera);
  EXPECT_EQ(r.get("ao").stage, "ao");
  EXPECT_EQ(r.get("ao").keys, withRadius);
  EXPECT_EQ(r.get("indirect").stage, "indirect");
  EXPECT_EQ(r.get("indirect").keys, lightCamera);
  EXPECT_EQ(r.get("indirect").channels, 3);
  const ReferenceEntry& transparency = r.get("transparency");
  EXPECT_EQ(transparency.stage, "transparency");
  EXPECT_EQ(transparency.keys, lightCamera);
  EXPECT_EQ(transparency.channels, 3);
  EXPECT_TRUE(transparency.inputs.has(FrameInput::TransparentFragments));
  EXPECT_FALSE(transparency.inputs.has(FrameInput::SurfacePoints));
  EXPECT_FALSE(transparency.samples());
  for (const auto& e : r.entries()) {
    if (&e == &transparency) continue;
    SCOPED_TRACE(e.aov);
    EXPECT_EQ(r.findStage(e.stage), &e);
    EXPECT_TRUE(e.inputs.has(FrameInput::SurfacePoints));
    EXPECT_TRUE(e.inputs.has(FrameInput::Materials));
    EXPECT_FALSE(e.inputs.has(FrameInput::PrePostColor));
    EXPECT_EQ(e.minSpp, 1);
    EXPECT_EQ(e.maxSpp, 65536);
    EXPECT_EQ(e.defaultSpp, 64);
  }
  EXPECT_EQ(r.findStage("post"), nullptr);
}

TEST(ReferenceRegistry, DefiningKeys) {
  const ReferenceRegistry r = builtins();
  const ReferenceEntry& shadow = *r.findStage("shadow");
  const ReferenceEntry& ao = *r.findStage("ao");
  EXPECT_TRUE(shadow.definesKey("light0.radius"));
  EXPECT_TRUE(shadow.definesKey("light12.color"));
  EXPECT_TRUE(shadow.definesKey("camera.position"));
  EXPECT_TRUE(ao.definesKey("ao.radius"));
  EXPECT_FALSE(shadow.definesKey("ao.radius"));
  EXPECT_FALSE(shadow.definesKey("shadow.resolution"));
  EXPECT_FALSE(shadow.definesKey("pcf.samples"));
  EXPECT_FALSE(shadow.definesKey("tonemap.exposure"));
  EXPECT_FALSE(shadow.definesKey("lightx.radius"));
  EXPECT_FALSE(shadow.definesKey("light.radius"));
  EXPECT_FALSE(ao.definesKey("ao.radius_scale")); // an exact key is not a prefix
}

TEST(ReferenceRegistry, KeyHashChangesWithADeclaredKeyOnly) {
  const ReferenceRegistry r = builtins();
  const TechniqueRegistry techniques = testTechniques();
  const ParamSet base = makeParamSet(makeBuiltinScene("contact"), techniques);
  const ReferenceEntry& shadow = *r.findStage("shadow");
  const ReferenceEntry& ao = *r.findStage("ao");

  auto changed = [&](const ReferenceEntry& e, const std::string& key, const std::string& text) {
    ParamSet p = base;
    p.setText(key, text);
    EXPECT_FALSE(p.value(key) == base.value(key)) << key; // the edit itself took
    return keyHash(e, p, techniques) != keyHash(e, base, techniques);
  };
  EXPECT_TRUE(changed(shadow, "light0.radius", "0.25"));
  EXPECT_TRUE(changed(shadow, "camera.fov", "30"));
  EXPECT_TRUE(changed(ao, "ao.radius", "1.5"));
  EXPECT_FALSE(changed(shadow, "ao.radius", "1.5"));
  EXPECT_FALSE(changed(shadow, "tq.samples", "4"));
  EXPECT_FALSE(changed(shadow, "shadow.resolution", "512"));
  EXPECT_FALSE(changed(ao, "tonemap.exposure", "2"));
  EXPECT_FALSE(changed(ao, "bl.sigma", "4"));
}

TEST(ReferenceRegistry, ColourBeforePostDependsOnEveryKeyBeforePost) {
  const TechniqueRegistry techniques = testTechniques();
  const ReferenceEntry bloom = testEntry("bloomref", "post", {"bl.sigma"}, {FrameInput::PrePostColor});
  EXPECT_TRUE(referenceDependsOnKey(bloom, "bl.sigma", techniques));          // declared
  EXPECT_TRUE(referenceDependsOnKey(bloom, "light0.radius", techniques));     // changes the colour before post
  EXPECT_TRUE(referenceDependsOnKey(bloom, "shadow.resolution", techniques)); // an earlier stage's key
  EXPECT_TRUE(referenceDependsOnKey(bloom, "tq.samples", techniques));        // an earlier stage's technique
  EXPECT_FALSE(referenceDependsOnKey(bloom, "bx.gain", techniques));          // another post technique
  EXPECT_FALSE(referenceDependsOnKey(bloom, "tonemap.exposure", techniques)); // after post
  // Without the input, only the declared keys count.
  const ReferenceEntry plain = testEntry("plainref", "post", {"bl.sigma"});
  EXPECT_FALSE(referenceDependsOnKey(plain, "light0.radius", techniques));
  EXPECT_FALSE(referenceDependsOnKey(plain, "tq.samples", techniques));
  // The opaque colour under the transparent fragments: the same rule, for the transparency stage.
  const ReferenceEntry over = testEntry("overref", "transparency", {"light<N>."}, {FrameInput::TransparentFragments});
  EXPECT_TRUE(referenceDependsOnKey(over, "shadow.resolution", techniques));
  EXPECT_TRUE(referenceDependsOnKey(over, "tq.samples", techniques));
  EXPECT_FALSE(referenceDependsOnKey(over, "bx.gain", techniques));
  EXPECT_FALSE(referenceDependsOnKey(over, "tonemap.exposure", techniques));
}

TEST(ReferenceRegistry, UnknownAovIsAUsageErrorNamingTheChoices) {
  const ReferenceRegistry r = builtins();
  EXPECT_RTLAB_ERROR(r.get("bogus"), ExitCode::Usage, "unknown reference AOV 'bogus'", "visibility, ao, indirect");
  EXPECT_RTLAB_ERROR(r.get("visibilty"), ExitCode::Usage, "did you mean 'visibility'");
}

TEST(ReferenceRegistry, RefusesInconsistentRegistrations) {
  ReferenceRegistry r = builtins();
  EXPECT_RTLAB_ERROR(r.add(testEntry("ao", "post")), ExitCode::Internal, "'ao' registered twice");
  EXPECT_RTLAB_ERROR(r.add(testEntry("other", "shadow")), ExitCode::Internal, "already has reference 'visibility'");
  EXPECT_RTLAB_ERROR(r.add(testEntry("other", "nostage")), ExitCode::Internal, "unknown stage 'nostage'");
  EXPECT_RTLAB_ERROR(r.add(testEntry("other", "post", {"Bad Key"})), ExitCode::Internal, "malformed key 'Bad Key'");
  EXPECT_RTLAB_ERROR(r.add(testEntry("", "post")), ExitCode::Internal, "non-empty");
  ReferenceEntry noCompute = testEntry("other", "post");
  noCompute.compute = nullptr;
  EXPECT_RTLAB_ERROR(r.add(noCompute), ExitCode::Internal, "no compute function");
  ReferenceEntry badSpp = testEntry("other", "post");
  badSpp.maxSpp = 16;
  badSpp.defaultSpp = 32;
  EXPECT_RTLAB_ERROR(r.add(badSpp), ExitCode::Internal, "minSpp <= defaultSpp <= maxSpp");
  EXPECT_EQ(r.entries().size(), 4u);
  r.add(testEntry("other", "post", {"bl.sigma"}, {FrameInput::PrePostColor}));
  EXPECT_EQ(r.choices("|"), "visibility|ao|indirect|transparency|other");
}

TEST(ReferenceRegistry, AReferenceReadsOnlyWhatItDeclares) {
  const ReferenceRegistry r = builtins();
  const TechniqueRegistry techniques = testTechniques();
  const Scene scene = makeBuiltinScene("contact");
  const ParamSet params = makeParamSet(scene, techniques);
  const ReferenceEntry& shadow = *r.findStage("shadow");
  const ReferenceEntry& ao = *r.findStage("ao");
  ReferenceFrame frame(shadow, scene, params, 4, 1, false);
  EXPECT_RTLAB_ERROR(frame.getFloat("ao.radius"), ExitCode::Internal, "does not declare");
  EXPECT_RTLAB_ERROR(frame.surfaces(), ExitCode::Internal, "surface points");     // declared, not provided
  EXPECT_RTLAB_ERROR(frame.prePostColor(), ExitCode::Internal, "colour before post"); // not declared
  ReferenceFrame aoFrame(ao, scene, params, 4, 1, false);
  EXPECT_EQ(aoFrame.getFloat("ao.radius"), params.getFloat("ao.radius"));
  SurfaceData surfaces;
  surfaces.width = 2;
  aoFrame.setSurfaces(&surfaces);
  EXPECT_EQ(aoFrame.surfaces().width, 2);
}
