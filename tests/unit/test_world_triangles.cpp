// The CPU side of the GPU scene data (scene/world_triangles.h) and the light comparison behind
// SceneChange::lights (scene/scene_change.h), on small hand-made scenes.
#include "scene/scene_change.h"
#include "scene/world_triangles.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace rtlab {
namespace {

// One triangle in the xy plane with +z normals.
Mesh triangleMesh(int material) {
  Mesh m;
  m.name = "tri";
  m.vertices.resize(3);
  m.vertices[0].position = {0, 0, 0};
  m.vertices[1].position = {1, 0, 0};
  m.vertices[2].position = {0, 1, 0};
  for (auto& v : m.vertices) v.normal = {0, 0, 1};
  m.indices = {0, 1, 2};
  m.material = material;
  return m;
}

TEST(WorldTriangles, ConcatenatesInstancesWithOffsetIndicesAndMaterialWords) {
  Scene s;
  s.materials.resize(2);
  s.meshes = {triangleMesh(1), triangleMesh(-1)};
  Instance a;
  a.mesh = 0;
  a.transform = glm::translate(glm::mat4(1), glm::vec3(10, 0, 0));
  Instance b;
  b.mesh = 1;
  b.transparent = true;
  Instance c;
  c.mesh = 0;
  c.transform = glm::scale(glm::mat4(1), glm::vec3(2, 1, 1)) *
                glm::rotate(glm::mat4(1), glm::radians(90.0f), glm::vec3(1, 0, 0)); // normal +z -> -y
  s.instances = {a, b, c};
  const WorldTriangles w = flattenWorldTriangles(s);
  ASSERT_EQ(w.positions.size(), 9u);
  ASSERT_EQ(w.normals.size(), 9u);
  ASSERT_EQ(w.triangles.size(), 3u);
  EXPECT_EQ(w.triangles[0], glm::uvec4(0, 1, 2, 1));
  EXPECT_EQ(w.triangles[1], glm::uvec4(3, 4, 5, kTriangleDefaultMaterial | kTriangleTransparent));
  EXPECT_EQ(w.triangles[2], glm::uvec4(6, 7, 8, 1));
  EXPECT_EQ(w.positions[1], glm::vec4(11, 0, 0, 1));
  EXPECT_NEAR(w.positions[7].x, 2.0f, 1e-6f); // scaled along x
  EXPECT_NEAR(w.positions[8].z, 1.0f, 1e-6f); // +y turned to +z
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(w.normals[6][k], glm::vec3(0, -1, 0)[k], 1e-6f);
  EXPECT_EQ(w.normals[6].w, 0.0f);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(w.bounds.min[k], 0.0f, 1e-6f);
    EXPECT_NEAR(w.bounds.max[k], glm::vec3(11, 1, 1)[k], 1e-6f);
  }
}

TEST(WorldTriangles, NormalsUseTheInverseTransposeUnderNonUniformScale) {
  Scene s;
  Mesh m = triangleMesh(-1);
  for (auto& v : m.vertices) v.normal = glm::normalize(glm::vec3(1, 1, 0));
  s.meshes = {m};
  Instance inst;
  inst.transform = glm::scale(glm::mat4(1), glm::vec3(4, 1, 1));
  s.instances = {inst};
  const WorldTriangles w = flattenWorldTriangles(s);
  // A plane x + y = d scaled by 4 along x becomes x/4 + y = d: normal along (1/4, 1, 0).
  const glm::vec3 expected = glm::normalize(glm::vec3(0.25f, 1, 0));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(w.normals[0][k], expected[k], 1e-6f);
}

TEST(WorldTriangles, EmptySceneHasNoTrianglesAndInvalidBounds) {
  const WorldTriangles w = flattenWorldTriangles(Scene{});
  EXPECT_TRUE(w.triangles.empty());
  EXPECT_FALSE(w.bounds.valid());
}

TEST(WorldTriangles, ABrokenSceneIsAnInternalError) {
  Scene s;
  s.meshes = {triangleMesh(-1)};
  Instance bad;
  bad.mesh = 3;
  s.instances = {bad};
  EXPECT_THROW(flattenWorldTriangles(s), Error);
  s.instances[0].mesh = 0;
  s.meshes[0].indices = {0, 1, 7};
  EXPECT_THROW(flattenWorldTriangles(s), Error);
}

TEST(SceneChange, SameLightsComparesEveryFieldExactly) {
  Light l;
  l.type = LightType::Rect;
  std::vector<Light> a{l, l};
  EXPECT_TRUE(sameLights(a, a));
  EXPECT_FALSE(sameLights(a, {l}));
  auto changed = [&](auto edit) {
    std::vector<Light> b = a;
    edit(b[1]);
    return !sameLights(a, b);
  };
  EXPECT_TRUE(changed([](Light& x) { x.intensity += 1e-3f; }));
  EXPECT_TRUE(changed([](Light& x) { x.color.y = 0.5f; }));
  EXPECT_TRUE(changed([](Light& x) { x.position.z = 1.0f; }));
  EXPECT_TRUE(changed([](Light& x) { x.direction = glm::vec3(0, 0, -1); }));
  EXPECT_TRUE(changed([](Light& x) { x.radius = 0.1f; }));
  EXPECT_TRUE(changed([](Light& x) { x.angle = 2.0f; }));
  EXPECT_TRUE(changed([](Light& x) { x.width = 2.0f; }));
  EXPECT_TRUE(changed([](Light& x) { x.height = 2.0f; }));
  EXPECT_TRUE(changed([](Light& x) { x.right = glm::vec3(0, 1, 0); }));
  EXPECT_TRUE(changed([](Light& x) { x.up = glm::vec3(0, 1, 0); }));
  EXPECT_TRUE(changed([](Light& x) { x.twoSided = true; }));
  EXPECT_TRUE(changed([](Light& x) { x.range = 5.0f; }));
  EXPECT_TRUE(changed([](Light& x) { x.innerConeAngle = 0.1f; }));
  EXPECT_TRUE(changed([](Light& x) { x.outerConeAngle = 0.2f; }));
  EXPECT_TRUE(changed([](Light& x) { x.type = LightType::Point; }));
  EXPECT_TRUE(changed([](Light& x) { x.name = "other"; }));
}

TEST(SceneChange, MergesCategories) {
  SceneChange c;
  EXPECT_FALSE(c.any());
  c |= SceneChange{false, false, true};
  EXPECT_EQ(c, (SceneChange{false, false, true}));
  c |= SceneChange{true, false, false};
  EXPECT_EQ(c, (SceneChange{true, false, true}));
  EXPECT_EQ(SceneChange::everything(), (SceneChange{true, true, true}));
}

} // namespace
} // namespace rtlab
