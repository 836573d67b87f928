// scene/scene_params: light<N>.* keys exist only where they apply (docs/contract.md "Keys and values"),
// defaults come from the scene, applySceneParams writes values back (directions normalized), and
// degenerate directions / cameras are usage errors.
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "scene/builtin.h"
#include "scene/scene_params.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include "test_util.h"

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

using namespace rtlab;
using rtlab::test::catchError;
using rtlab::test::Caught;

namespace {


void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

// light0 directional, light1 point, light2 spot, light3 rectangular, over a 2x2x2 box.
Scene handScene() {
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
  d.direction = glm::normalize(glm::vec3(-0.3f, -1, -0.6f));
  d.angle = 0.5f;
  d.intensity = 3;
  Light p;
  p.type = LightType::Point;
  p.position = {0, 3, 0};
  p.radius = 0.1f;
  p.intensity = 50;
  p.color = {1, 0.9f, 0.8f};
  Light sp;
  sp.type = LightType::Spot;
  sp.position = {2, 3, 0};
  sp.direction = {0, -1, 0};
  sp.radius = 0.05f;
  Light r;
  r.type = LightType::Rect;
  r.position = {0, 2.5f, 0};
  r.direction = {0, -1, 0};
  r.right = {1, 0, 0};
  r.up = {0, 0, 1};
  r.width = 2;
  r.height = 1;
  s.lights = {d, p, sp, r};
  s.camera.position = {0, 1, 6};
  s.camera.target = {0, 0, 0};
  s.camera.fovY = 40;
  return s;
}

ParamSet sceneSet(const Scene& s) {
  ParamSet set;
  set.declare(sceneParamSpecs(s));
  return set;
}

} // namespace

TEST(SceneParamKeys, ExistOnlyWhereTheyApply) {
  const ParamSet set = sceneSet(handScene());
  const auto has = [&](const std::string& k) { return set.has(k); };
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(has("light" + std::to_string(i) + ".intensity")) << i;
    EXPECT_TRUE(has("light" + std::to_string(i) + ".color")) << i;
  }
  // directional
  EXPECT_TRUE(has("light0.angle"));
  EXPECT_TRUE(has("light0.direction"));
  for (const char* k : {"light0.position", "light0.radius", "light0.width", "light0.height"}) EXPECT_FALSE(has(k)) << k;
  // point
  EXPECT_TRUE(has("light1.position"));
  EXPECT_TRUE(has("light1.radius"));
  for (const char* k : {"light1.direction", "light1.angle", "light1.width", "light1.height"}) EXPECT_FALSE(has(k)) << k;
  // spot
  EXPECT_TRUE(has("light2.position"));
  EXPECT_TRUE(has("light2.direction"));
  EXPECT_TRUE(has("light2.radius"));
  for (const char* k : {"light2.angle", "light2.width", "light2.height"}) EXPECT_FALSE(has(k)) << k;
  // rectangular
  for (const char* k : {"light3.width", "light3.height", "light3.two_sided", "light3.position", "light3.direction"})
    EXPECT_TRUE(has(k)) << k;
  for (const char* k : {"light0.two_sided", "light1.two_sided", "light2.two_sided"}) EXPECT_FALSE(has(k)) << k;
  for (const char* k : {"light3.radius", "light3.angle"}) EXPECT_FALSE(has(k)) << k;
  // camera; nothing for lights that do not exist
  for (const char* k : {"camera.position", "camera.target", "camera.fov"}) EXPECT_TRUE(has(k)) << k;
  EXPECT_FALSE(has("light4.intensity"));
  EXPECT_FALSE(has("camera.up"));
}

TEST(SceneParamKeys, TypesAndDefaultsComeFromTheScene) {
  const Scene s = handScene();
  const ParamSet set = sceneSet(s);
  EXPECT_EQ(set.spec("light1.color").type, ParamType::Color);
  EXPECT_EQ(set.spec("light1.position").type, ParamType::Vec3);
  EXPECT_EQ(set.spec("light0.angle").type, ParamType::Float);
  EXPECT_EQ(set.spec("camera.target").type, ParamType::Vec3);
  EXPECT_EQ(set.getFloat("light0.angle"), 0.5f);
  EXPECT_EQ(set.getFloat("light0.intensity"), 3.0f);
  EXPECT_EQ(set.getFloat("light1.radius"), 0.1f);
  EXPECT_EQ(set.getVec3("light1.color"), glm::vec3(1, 0.9f, 0.8f));
  EXPECT_EQ(set.getVec3("light2.position"), glm::vec3(2, 3, 0));
  EXPECT_EQ(set.getFloat("light3.width"), 2.0f);
  EXPECT_EQ(set.getFloat("light3.height"), 1.0f);
  EXPECT_EQ(set.getVec3("camera.position"), glm::vec3(0, 1, 6));
  EXPECT_EQ(set.getFloat("camera.fov"), 40.0f);
}

TEST(SceneParamKeys, KeysThatDoNotApplyAreUnknownKeys) {
  ParamSet set = sceneSet(handScene());
  EXPECT_RTLAB_ERROR(set.setAssignment("light0.radius=0.1"), ExitCode::Usage, "unknown key 'light0.radius'");
  EXPECT_RTLAB_ERROR(set.setAssignment("light1.direction=0,-1,0"), ExitCode::Usage, "unknown key 'light1.direction'");
  EXPECT_RTLAB_ERROR(set.setAssignment("light1.angle=1"), ExitCode::Usage, "unknown key 'light1.angle'");
  EXPECT_RTLAB_ERROR(set.setAssignment("light2.width=1"), ExitCode::Usage, "unknown key 'light2.width'");
  EXPECT_RTLAB_ERROR(set.setAssignment("light9.intensity=1"), ExitCode::Usage, "unknown key 'light9.intensity'");
}

TEST(SceneParamKeys, OutOfRangeRejected) {
  ParamSet set = sceneSet(handScene());
  EXPECT_RTLAB_ERROR(set.setAssignment("light0.angle=-0.5"), ExitCode::Usage, "'light0.angle'", "[0, 45]");
  EXPECT_RTLAB_ERROR(set.setAssignment("light0.angle=45.000001"), ExitCode::Usage, "'light0.angle'", "[0, 45]");
  EXPECT_RTLAB_ERROR(set.setAssignment("light1.radius=-1"), ExitCode::Usage, "'light1.radius'");
  EXPECT_RTLAB_ERROR(set.setAssignment("light1.intensity=-1"), ExitCode::Usage, "'light1.intensity'");
  EXPECT_RTLAB_ERROR(set.setAssignment("light1.color=1,2,1"), ExitCode::Usage, "'light1.color'", "[0, 1]");
  EXPECT_RTLAB_ERROR(set.setAssignment("camera.fov=0"), ExitCode::Usage, "'camera.fov'", "[1, 170]");
  EXPECT_RTLAB_ERROR(set.setAssignment("camera.fov=171"), ExitCode::Usage, "'camera.fov'", "[1, 170]");
  set.setAssignment("light0.angle=45");
  set.setAssignment("light0.angle=0");
  set.setAssignment("camera.fov=170");
}

TEST(SceneParamApply, WritesValuesAndNormalizesDirections) {
  Scene s = handScene();
  ParamSet set = sceneSet(s);
  set.setAssignment("light0.direction=0,0,-0.5");
  set.setAssignment("light0.angle=2.5");
  set.setAssignment("light0.intensity=7");
  set.setAssignment("light1.position=1,4,-1");
  set.setAssignment("light1.radius=0.25");
  set.setAssignment("light1.color=0.5,0.25,1");
  set.setAssignment("light2.direction=1,-1,0");
  set.setAssignment("light2.radius=0");
  set.setAssignment("light3.width=3");
  set.setAssignment("light3.height=0.5");
  set.setAssignment("light3.two_sided=on");
  set.setAssignment("light3.position=0,2,1");
  set.setAssignment("camera.position=0,2,8");
  set.setAssignment("camera.target=0,0.5,0");
  set.setAssignment("camera.fov=60");
  applySceneParams(set, s);

  expectNear(s.lights[0].direction, {0, 0, -1});
  EXPECT_EQ(s.lights[0].angle, 2.5f);
  EXPECT_EQ(s.lights[0].intensity, 7.0f);
  expectNear(s.lights[1].position, {1, 4, -1});
  EXPECT_EQ(s.lights[1].radius, 0.25f);
  expectNear(s.lights[1].color, {0.5f, 0.25f, 1});
  expectNear(s.lights[2].direction, glm::normalize(glm::vec3(1, -1, 0)));
  EXPECT_EQ(s.lights[2].radius, 0.0f);
  EXPECT_NEAR(glm::length(s.lights[2].direction), 1.0f, 1e-6f);
  EXPECT_EQ(s.lights[3].width, 3.0f);
  EXPECT_EQ(s.lights[3].height, 0.5f);
  EXPECT_TRUE(s.lights[3].twoSided);
  expectNear(s.lights[3].position, {0, 2, 1});
  expectNear(s.camera.position, {0, 2, 8});
  expectNear(s.camera.target, {0, 0.5f, 0});
  EXPECT_EQ(s.camera.fovY, 60.0f);
  EXPECT_GT(s.camera.zfar, s.camera.znear);
}

TEST(SceneParamApply, DefaultsLeaveTheSceneAsItWas) {
  Scene s = handScene();
  const Scene before = s;
  applySceneParams(sceneSet(s), s);
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    SCOPED_TRACE(i);
    expectNear(s.lights[i].direction, before.lights[i].direction);
    expectNear(s.lights[i].position, before.lights[i].position);
    expectNear(s.lights[i].right, before.lights[i].right);
    expectNear(s.lights[i].up, before.lights[i].up);
    EXPECT_EQ(s.lights[i].radius, before.lights[i].radius);
    EXPECT_EQ(s.lights[i].intensity, before.lights[i].intensity);
  }
  expectNear(s.camera.position, before.camera.position);
  EXPECT_EQ(s.camera.fovY, before.camera.fovY);
}

TEST(SceneParamApply, RectFrameStaysOrthonormal) {
  Scene s = handScene();
  ParamSet set = sceneSet(s);
  set.setAssignment("light3.direction=1,-1,0.5");
  applySceneParams(set, s);
  const Light& r = s.lights[3];
  expectNear(r.direction, glm::normalize(glm::vec3(1, -1, 0.5f)));
  EXPECT_NEAR(glm::length(r.right), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::length(r.up), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(r.right, r.direction), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(r.up, r.direction), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(r.right, r.up), 0.0f, 1e-5f);
}

TEST(SceneParamApply, ZeroDirectionIsUsage) {
  for (const char* key : {"light0.direction", "light2.direction", "light3.direction"}) {
    Scene s = handScene();
    ParamSet set = sceneSet(s);
    set.setText(key, "0,0,0");
    EXPECT_RTLAB_ERROR(applySceneParams(set, s), ExitCode::Usage, std::string("'") + key + "'", "zero");
  }
}

TEST(SceneParamApply, CameraTargetAtPositionIsUsage) {
  Scene s = handScene();
  ParamSet set = sceneSet(s);
  set.setAssignment("camera.position=1,2,3");
  set.setAssignment("camera.target=1,2,3");
  EXPECT_RTLAB_ERROR(applySceneParams(set, s), ExitCode::Usage, "'camera.target'", "'camera.position'");
}

TEST(SceneParamApply, CameraLookingStraightDownKeepsAUsableUp) {
  Scene s = handScene();
  ParamSet set = sceneSet(s);
  set.setAssignment("camera.position=0,5,0");
  set.setAssignment("camera.target=0,0,0");
  applySceneParams(set, s);
  const glm::vec3 fwd = glm::normalize(s.camera.target - s.camera.position);
  EXPECT_LT(std::abs(glm::dot(fwd, glm::normalize(s.camera.up))), 0.999f);
}

TEST(SceneParamKeys, SceneValuesBeyondNominalRangesStillDeclare) {
  // A valid scene file may hold an angle up to 89 degrees, any intensity, far coordinates, a
  // narrow or wide fov: the catalog must not fail on it; the range widens to include the value.
  Scene s = handScene();
  s.lights[0].angle = 60.0f;
  s.lights[1].intensity = 5.0e6f;
  s.lights[1].position = {2.0e5f, 0, 0};
  s.lights[3].color = {2.0f, 1.0f, 1.0f};
  s.camera.fovY = 0.5f;
  s.camera.position = {0, 0, 3.0e5f};
  ParamSet set;
  ASSERT_NO_THROW(set.declare(sceneParamSpecs(s)));
  EXPECT_EQ(set.getFloat("light0.angle"), 60.0f);
  EXPECT_EQ(set.getFloat("light1.intensity"), 5.0e6f);
  EXPECT_EQ(set.getFloat("camera.fov"), 0.5f);
  EXPECT_RTLAB_ERROR(set.setAssignment("light0.angle=61"), ExitCode::Usage, "'light0.angle'", "[0, 60]");
  set.setAssignment("light0.angle=10"); // the nominal range is still there
  applySceneParams(set, s);
  EXPECT_EQ(s.lights[0].angle, 10.0f);
}

TEST(SceneParamKeys, EveryBuiltinSceneDeclaresAndRoundTrips) {
  const TechniqueRegistry empty;
  for (const auto& name : builtinSceneNames()) {
    SCOPED_TRACE(name);
    Scene s = makeBuiltinScene(name);
    ParamSet set;
    ASSERT_NO_THROW(set = makeParamSet(s, empty));
    EXPECT_TRUE(set.has("tonemap.exposure"));
    EXPECT_TRUE(set.has("light0.intensity"));
    EXPECT_TRUE(set.has("camera.fov"));
    const Scene before = s;
    ASSERT_NO_THROW(applySceneParams(set, s));
    ASSERT_EQ(s.lights.size(), before.lights.size());
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
      expectNear(s.lights[i].direction, before.lights[i].direction);
      expectNear(s.lights[i].position, before.lights[i].position);
    }
  }
}

TEST(SceneParamKeys, AmbientIsAColorKeyAppliedToTheScene) {
  // docs/contract.md: scene.ambient, the constant ambient radiance (RGB), default from the scene.
  Scene s = handScene();
  s.ambient = glm::vec3(0.2f, 0.3f, 0.4f);
  ParamSet set = sceneSet(s);
  ASSERT_TRUE(set.has("scene.ambient"));
  EXPECT_EQ(set.spec("scene.ambient").type, ParamType::Color);
  expectNear(set.getVec3("scene.ambient"), {0.2f, 0.3f, 0.4f});
  set.setAssignment("scene.ambient=0.5,0.25,1");
  applySceneParams(set, s);
  expectNear(s.ambient, {0.5f, 0.25f, 1.0f});
  EXPECT_RTLAB_ERROR(set.setAssignment("scene.ambient=-0.1,0,0"), ExitCode::Usage, "'scene.ambient'", "[0, 100]");
  EXPECT_RTLAB_ERROR(set.setAssignment("scene.ambient=0.5"), ExitCode::Usage, "'scene.ambient'", "x,y,z");
  EXPECT_RTLAB_ERROR(set.setAssignment("scene.ambient=1,1,101"), ExitCode::Usage, "'scene.ambient'");
}
