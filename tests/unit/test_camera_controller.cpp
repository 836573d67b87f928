// viewer/camera_controller: orbit keeps the distance and never flips over a pole, pan moves
// position and target together so the point under the cursor follows the mouse, the wheel
// dollies without reaching the target, fly moves along the view axes, frame() puts every corner
// of a box inside the view, reset() and degenerate input.
#include "scene/builtin.h"
#include "viewer/camera_controller.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

using namespace rtlab;

namespace {

Camera testCamera() {
  Camera c;
  c.position = {1, 2, 6};
  c.target = {0.5f, 0.25f, -1};
  c.fovY = 50;
  return c;
}

float distanceOf(const Camera& c) {
  return glm::length(c.position - c.target);
}
glm::vec3 forwardOf(const Camera& c) {
  return glm::normalize(c.target - c.position);
}

// Window pixel (x right, y down) of a world point seen by the camera in a viewport.
glm::vec3 project(const Camera& c, const glm::ivec2& viewport, const glm::vec3& p) {
  const glm::mat4 view = glm::lookAt(c.position, c.target, c.up);
  const glm::mat4 proj = glm::perspective(glm::radians(c.fovY), float(viewport.x) / float(viewport.y), c.znear, c.zfar);
  const glm::vec4 clip = proj * view * glm::vec4(p, 1.0f);
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * float(viewport.x), (0.5f - ndc.y * 0.5f) * float(viewport.y), ndc.z};
}

CameraInput drag(glm::vec2 delta, bool orbit, glm::ivec2 viewport = {800, 600}) {
  CameraInput in;
  in.mouseDelta = delta;
  in.orbit = orbit;
  in.pan = !orbit;
  in.viewport = viewport;
  return in;
}

} // namespace

TEST(CameraController, NoInputDoesNotMove) {
  CameraController cc(testCamera());
  EXPECT_FALSE(cc.update(CameraInput{}));
  EXPECT_EQ(cc.camera().position, testCamera().position);
}

TEST(CameraController, OrbitKeepsDistanceAndTarget) {
  CameraController cc(testCamera());
  const float d0 = distanceOf(cc.camera());
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> px(-80.0f, 80.0f);
  for (int i = 0; i < 200; ++i) {
    cc.update(drag({px(rng), px(rng)}, true));
    ASSERT_NEAR(distanceOf(cc.camera()), d0, 1e-4f * d0) << "after drag " << i;
    ASSERT_EQ(cc.camera().target, testCamera().target);
  }
}

TEST(CameraController, HorizontalDragYawsAboutWorldUp) {
  CameraController cc(testCamera());
  const float height = cc.camera().position.y - cc.camera().target.y;
  EXPECT_TRUE(cc.update(drag({120, 0}, true)));
  EXPECT_NEAR(cc.camera().position.y - cc.camera().target.y, height, 1e-5f);
  // Dragging right by 120 px turns the camera by -120 * orbitSpeed radians about +y.
  const glm::vec3 a = testCamera().position - testCamera().target, b = cc.camera().position - cc.camera().target;
  const float turned = std::atan2(b.x, b.z) - std::atan2(a.x, a.z);
  EXPECT_NEAR(turned, -120 * cc.orbitSpeed, 1e-4f);
}

TEST(CameraController, PitchIsClampedShortOfThePoles) {
  for (float dy : {5000.0f, -5000.0f}) {
    CameraController cc(testCamera());
    const glm::vec3 horizontal0 = glm::normalize(glm::vec3(forwardOf(cc.camera()).x, 0, forwardOf(cc.camera()).z));
    for (int i = 0; i < 10; ++i)
      cc.update(drag({0, dy}, true));
    const glm::vec3 f = forwardOf(cc.camera());
    EXPECT_NEAR(std::abs(std::asin(f.y)), cc.maxPitch, 1e-3f) << "dy " << dy;
    // Still looking the same way horizontally: the view did not flip over the pole.
    EXPECT_GT(glm::dot(glm::normalize(glm::vec3(f.x, 0, f.z)), horizontal0), 0.999f) << "dy " << dy;
    // Up and forward stay independent, so lookAt stays well defined.
    EXPECT_GT(glm::length(glm::cross(f, cc.camera().up)), 0.01f);
    // At the clamp, a further drag the same way does not move the camera.
    EXPECT_FALSE(cc.update(drag({0, dy}, true)));
  }
}

TEST(CameraController, PanMovesPositionAndTargetTogetherAndFollowsTheMouse) {
  const glm::ivec2 viewport{800, 600};
  const Camera start = testCamera();
  CameraController cc(start);
  const glm::vec2 delta{37, -21};
  EXPECT_TRUE(cc.update(drag(delta, false, viewport)));
  const Camera& c = cc.camera();
  const glm::vec3 dp = c.position - start.position, dt = c.target - start.target;
  EXPECT_LT(glm::length(dp - dt), 1e-5f);
  EXPECT_GT(glm::length(dp), 0.0f);
  // The old target (the point that was under the cursor at the viewport's center) is now where
  // the mouse went.
  const glm::vec3 seen = project(c, viewport, start.target);
  EXPECT_NEAR(seen.x, 400 + delta.x, 0.05f);
  EXPECT_NEAR(seen.y, 300 + delta.y, 0.05f);
}

TEST(CameraController, ZoomStepsScaleTheDistanceAndReturn) {
  CameraController cc(testCamera());
  const float d0 = distanceOf(cc.camera());
  CameraInput in;
  in.wheel = 1;
  EXPECT_TRUE(cc.update(in));
  EXPECT_NEAR(distanceOf(cc.camera()), d0 * (1 - cc.zoomStep), 1e-5f);
  in.wheel = -1;
  cc.update(in);
  EXPECT_NEAR(distanceOf(cc.camera()), d0, 1e-4f);
  EXPECT_EQ(cc.camera().target, testCamera().target);
}

TEST(CameraController, ZoomNeverReachesOrPassesTheTarget) {
  CameraController cc(testCamera());
  const glm::vec3 dir0 = forwardOf(cc.camera());
  CameraInput in;
  in.wheel = 1e6f; // one huge step
  cc.update(in);
  EXPECT_GT(distanceOf(cc.camera()), 0.0f);
  in.wheel = 5;
  for (int i = 0; i < 2000; ++i)
    cc.update(in);
  EXPECT_GE(distanceOf(cc.camera()), cc.minDistance * 0.999f);
  EXPECT_GT(glm::dot(forwardOf(cc.camera()), dir0), 0.999f) << "passed the target";
  cc.zoomStep = 5.0f; // out of its range: used as 0.9, never a negative factor
  cc.update(in);
  EXPECT_GT(glm::dot(forwardOf(cc.camera()), dir0), 0.999f);
}

TEST(CameraController, ZoomingOutAndFlyingStayWithinTheKeysRange) {
  CameraController cc(testCamera());
  CameraInput in;
  in.wheel = -20;
  for (int i = 0; i < 500; ++i)
    cc.update(in);
  const float far = distanceOf(cc.camera());
  EXPECT_GT(far, 1000.0f) << "zooming out stopped early";
  EXPECT_LE(glm::length(cc.camera().position), std::sqrt(3.0f) * cc.maxCoordinate);
  EXPECT_LE(
      std::max({std::abs(cc.camera().position.x), std::abs(cc.camera().position.y), std::abs(cc.camera().position.z)}),
      cc.maxCoordinate);
  in = CameraInput{};
  in.fly = {0, 0, -1};
  in.dt = 1000;
  in.fast = true;
  for (int i = 0; i < 100; ++i)
    cc.update(in);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_LE(std::abs(cc.camera().position[axis]), cc.maxCoordinate);
    EXPECT_LE(std::abs(cc.camera().target[axis]), cc.maxCoordinate);
  }
}

TEST(CameraController, FlyMovesAlongTheViewAxes) {
  CameraController cc(testCamera());
  const glm::vec3 f = forwardOf(cc.camera());
  CameraInput in;
  in.fly = {0, 0, 1};
  in.dt = 0.5f;
  EXPECT_TRUE(cc.update(in));
  glm::vec3 moved = cc.camera().position - testCamera().position;
  EXPECT_LT(glm::length(moved - f * cc.flySpeed * 0.5f), 1e-4f);
  EXPECT_LT(glm::length((cc.camera().target - testCamera().target) - moved), 1e-4f);

  cc.reset();
  in.fast = true;
  in.fly = {1, 0, 0}; // strafe right: perpendicular to forward and to up
  cc.update(in);
  moved = cc.camera().position - testCamera().position;
  EXPECT_NEAR(glm::length(moved), cc.flySpeed * cc.fastFactor * 0.5f, 1e-4f);
  EXPECT_NEAR(glm::dot(moved, f), 0.0f, 1e-4f);
  EXPECT_NEAR(moved.y, 0.0f, 1e-4f);

  cc.reset();
  in.fast = false;
  in.fly = {1, 1, 1}; // diagonal: no faster than one axis
  cc.update(in);
  EXPECT_NEAR(glm::length(cc.camera().position - testCamera().position), cc.flySpeed * 0.5f, 1e-4f);
}

TEST(CameraController, FrameShowsEveryCornerOfTheBox) {
  struct Box {
    glm::vec3 lo, hi;
  };
  const Box boxes[] = {{{-1, -1, -1}, {1, 1, 1}},
                       {{-20, 0, -0.5f}, {20, 0.2f, 0.5f}},  // long and flat
                       {{3, 100, -2}, {3.01f, 140, -1.99f}}, // tall, thin, far from the origin
                       {{5, 5, 5}, {5, 5, 5}}};              // a point
  const glm::ivec2 viewports[] = {{800, 600}, {1920, 1080}, {300, 900}, {2000, 200}, {64, 64}};
  for (const Box& box : boxes) {
    for (const glm::ivec2& vp : viewports) {
      for (float fov : {20.0f, 45.0f, 90.0f}) {
        Camera start = testCamera();
        start.fovY = fov;
        CameraController cc(start);
        cc.setViewport(vp);
        cc.frame(box.lo, box.hi);
        const Camera& c = cc.camera();
        EXPECT_LT(glm::length(forwardOf(c) - forwardOf(start)), 1e-4f) << "view direction changed";
        float extent = 0;
        for (int i = 0; i < 8; ++i) {
          const glm::vec3 p((i & 1) ? box.hi.x : box.lo.x, (i & 2) ? box.hi.y : box.lo.y,
                            (i & 4) ? box.hi.z : box.lo.z);
          const glm::vec3 s = project(c, vp, p);
          SCOPED_TRACE(::testing::Message() << "box " << box.lo.x << ".." << box.hi.x << " viewport " << vp.x << "x"
                                            << vp.y << " fov " << fov << " corner " << i);
          EXPECT_GE(s.x, 0.0f);
          EXPECT_LE(s.x, float(vp.x));
          EXPECT_GE(s.y, 0.0f);
          EXPECT_LE(s.y, float(vp.y));
          EXPECT_GT(s.z, -1.0f); // between the near and far planes
          EXPECT_LT(s.z, 1.0f);
          extent = std::max({extent, std::abs(s.x / vp.x - 0.5f), std::abs(s.y / vp.y - 0.5f)});
        }
        // Framed, not lost in the distance. The bounding sphere fits the narrower fov, so a flat
        // 40-unit box in a 2000x200 window spans only about a tenth of the width (extent 0.05):
        // the bound allows that, and fails a camera left at, say, ten times the distance.
        if (box.lo != box.hi) {
          EXPECT_GT(extent, 0.03f);
        }
      }
    }
  }
}

TEST(CameraController, FrameOfAnEmptySceneLeavesTheCamera) {
  Scene empty;
  glm::vec3 lo, hi;
  sceneBounds(empty, lo, hi);
  EXPECT_GT(lo.x, hi.x);
  CameraController cc(testCamera());
  const float speed = cc.flySpeed;
  cc.frame(lo, hi);
  EXPECT_EQ(cc.camera().position, testCamera().position);
  EXPECT_EQ(cc.camera().target, testCamera().target);
  EXPECT_EQ(cc.flySpeed, speed);
}

TEST(CameraController, FrameScalesFlySpeedWithTheScene) {
  CameraController small(testCamera()), large(testCamera());
  small.frame(glm::vec3(-0.1f), glm::vec3(0.1f));
  large.frame(glm::vec3(-100), glm::vec3(100));
  EXPECT_NEAR(large.flySpeed / small.flySpeed, 1000.0f, 1.0f);
}

TEST(CameraController, SceneBoundsCoverTransformedInstances) {
  Scene s;
  Mesh m;
  m.bounds.extend(glm::vec3(-1));
  m.bounds.extend(glm::vec3(1));
  s.meshes.push_back(m);
  Instance a;
  a.transform = glm::translate(glm::mat4(1), glm::vec3(10, 0, 0));
  Instance b;
  b.transform = glm::scale(glm::rotate(glm::mat4(1), glm::radians(45.0f), glm::vec3(0, 1, 0)), glm::vec3(2));
  s.instances = {a, b};
  glm::vec3 lo, hi;
  sceneBounds(s, lo, hi);
  const float r = 2.0f * std::sqrt(2.0f); // the rotated, scaled cube's half-diagonal in x and z
  EXPECT_NEAR(lo.x, -r, 1e-4f);
  EXPECT_NEAR(hi.x, 11.0f, 1e-4f);
  EXPECT_NEAR(lo.y, -2.0f, 1e-4f);
  EXPECT_NEAR(hi.y, 2.0f, 1e-4f);
  EXPECT_NEAR(lo.z, -r, 1e-4f);
  EXPECT_NEAR(hi.z, r, 1e-4f);
}

TEST(CameraController, FramedBuiltinScenesAreWhollyInView) {
  ASSERT_GE(builtinSceneNames().size(), 5u);
  for (const auto& name : builtinSceneNames()) {
    const Scene scene = makeBuiltinScene(name);
    glm::vec3 lo, hi;
    sceneBounds(scene, lo, hi);
    const Bounds world = scene.worldBounds();
    EXPECT_EQ(lo, world.min);
    EXPECT_EQ(hi, world.max);
    CameraController cc(scene.camera);
    const glm::ivec2 vp{640, 360};
    cc.setViewport(vp);
    cc.frame(lo, hi);
    for (const Instance& inst : scene.instances) {
      const Bounds& b = scene.meshes[std::size_t(inst.mesh)].bounds;
      for (int i = 0; i < 8; ++i) {
        const glm::vec3 local((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        const glm::vec3 s = project(cc.camera(), vp, glm::vec3(inst.transform * glm::vec4(local, 1.0f)));
        EXPECT_TRUE(s.x >= 0 && s.x <= vp.x && s.y >= 0 && s.y <= vp.y && s.z > -1 && s.z < 1)
            << name << ": a corner of mesh " << inst.mesh << " projects to " << s.x << ", " << s.y << ", " << s.z;
      }
    }
  }
}

TEST(CameraController, ResetReturnsHome) {
  CameraController cc(testCamera());
  cc.update(drag({50, 30}, true));
  cc.update(drag({50, 30}, false));
  CameraInput in;
  in.wheel = 3;
  cc.update(in);
  ASSERT_NE(cc.camera().position, testCamera().position);
  cc.reset();
  EXPECT_EQ(cc.camera().position, testCamera().position);
  EXPECT_EQ(cc.camera().target, testCamera().target);
  Camera home = testCamera();
  home.position = {0, 10, 0.5f};
  cc.setHome(home);
  cc.reset();
  EXPECT_EQ(cc.camera().position, home.position);
}

TEST(CameraController, DegenerateInputIsIgnored) {
  CameraController cc(testCamera());
  EXPECT_FALSE(cc.update(drag({30, 30}, false, {0, 0}))); // minimized window: no pan
  CameraInput in;
  in.mouseDelta = {NAN, 1};
  in.orbit = in.pan = true;
  in.wheel = INFINITY;
  in.fly = {1, 0, 0};
  in.dt = NAN;
  EXPECT_FALSE(cc.update(in));
  // A camera sitting on its target cannot orbit or zoom, and pans and flies without NaNs.
  Camera on = testCamera();
  on.position = on.target;
  cc.setCamera(on);
  EXPECT_FALSE(cc.orbit(0.3f, 0.2f));
  in = drag({10, 5}, false);
  in.wheel = 2;
  in.fly = {0, 0, 1};
  in.dt = 0.1f;
  cc.update(in);
  EXPECT_TRUE(std::isfinite(cc.camera().position.x) && std::isfinite(cc.camera().target.z));
}
