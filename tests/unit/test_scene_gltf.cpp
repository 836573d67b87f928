// glTF loading of valid files: hierarchy, materials, textures, lights, camera, generated
// attributes and defaults, for embedded, external-buffer and binary files.
#include "scene/gltf_loader.h"
#include "scene/load.h"
#include "test_scene_gltf_writer.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace rtlab {
namespace {

using test::GltfWriter;
using Json = nlohmann::json;
constexpr float kEps = 1e-5f;

void expectVec(const glm::vec3& a, const glm::vec3& b, float eps = kEps) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

// The scene described in the Hierarchy test: DFS order of nodes is 0, 1, 3, 2, 4, 5.
GltfWriter hierarchyFile() {
  GltfWriter w;
  w.push("materials", {{"name", "red"},
                       {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1.0, 1.0}},
                                                 {"metallicFactor", 0.3}, {"roughnessFactor", 0.6}}},
                       {"emissiveFactor", {1.0, 0.5, 0.0}},
                       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}}}});
  w.push("materials", {{"name", "glass"}, {"alphaMode", "BLEND"}});
  w.addQuadMesh("quad", true, true, 0);
  w.addQuadMesh("pane", true, true, 1);
  Json lights = Json::array();
  lights.push_back({{"type", "spot"}, {"color", {1.0, 0.0, 0.0}}, {"intensity", 50.0}, {"range", 10.0},
                    {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}, {"extras", {{"radius", 0.25}}}});
  lights.push_back({{"type", "directional"}, {"intensity", 2.0}, {"extras", {{"angle", 1.5}}}});
  lights.push_back({{"type", "point"}, {"intensity", 7.0}, {"name", "bulb"}});
  w.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", lights}}}};
  w.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  w.push("cameras", {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}});
  const double s = std::sqrt(0.5);
  auto light = [](int i) { return Json{{"KHR_lights_punctual", {{"light", i}}}}; };
  Json area = {{"width", 2.0}, {"height", 1.0}, {"intensity", 5.0}, {"color", {1.0, 1.0, 0.5}}};
  w.addNode({{"name", "root"}, {"translation", {1, 0, 0}}, {"children", {1, 2, 4}}, {"extensions", light(1)}});
  w.addNode({{"name", "child"}, {"scale", {2, 2, 2}}, {"mesh", 0}, {"children", {3}}});
  w.addNode({{"name", "cam"}, {"translation", {0, 1, 10}}, {"camera", 0}});
  w.addNode({{"name", "grandchild"}, {"translation", {0, 0, 1}}, {"rotation", {-s, 0, 0, s}},
             {"extensions", light(0)}, {"extras", {{"rtlab_area_light", area}}}});
  w.addNode({{"name", "paneNode"}, {"translation", {0, 0, -1}}, {"mesh", 1}});
  w.addNode({{"name", "second"}, {"translation", {0, 3, 0}}, {"extensions", light(2)},
             {"extras", {{"rtlab_area_light", {{"width", 0.5}, {"height", 0.25}}}}}});
  w.setScene({0, 5});
  return w;
}

class SceneGltfModes : public ::testing::TestWithParam<GltfWriter::Mode> {};

TEST_P(SceneGltfModes, HierarchyMaterialsLightsAndCamera) {
  const char* names[] = {"embedded", "external", "binary"};
  const std::string stem = std::string("hier_") + names[static_cast<int>(GetParam())];
  GltfWriter w = hierarchyFile();
  Scene s = loadScene(w.write(test::sceneTmpDir("valid"), stem, GetParam()));
  EXPECT_EQ(s.name, stem);

  ASSERT_EQ(s.meshes.size(), 2u);
  ASSERT_EQ(s.instances.size(), 2u);
  const Instance& quad = s.instances[0];
  EXPECT_EQ(s.meshes[static_cast<size_t>(quad.mesh)].name, "quad");
  expectVec(glm::vec3(quad.transform * glm::vec4(1, 1, 0, 1)), {3, 2, 0});
  EXPECT_FALSE(quad.transparent);
  const Instance& pane = s.instances[1];
  EXPECT_EQ(s.meshes[static_cast<size_t>(pane.mesh)].name, "pane");
  EXPECT_TRUE(pane.transparent);
  EXPECT_TRUE(s.hasTransparency());

  ASSERT_EQ(s.materials.size(), 2u);
  const Material& red = s.materials[0];
  EXPECT_EQ(red.name, "red");
  EXPECT_NEAR(red.baseColor.y, 0.25f, kEps);
  EXPECT_NEAR(red.metallic, 0.3f, kEps);
  EXPECT_NEAR(red.roughness, 0.6f, kEps);
  expectVec(red.emissive, {2.0f, 1.0f, 0.0f});
  EXPECT_EQ(s.materials[1].alphaMode, AlphaMode::Blend);

  // Punctual lights in DFS node order (nodes 0, 3, 5), then the area lights (nodes 3, 5).
  ASSERT_EQ(s.lights.size(), 5u);
  EXPECT_TRUE(s.hasFileLights);
  EXPECT_EQ(s.lights[0].type, LightType::Directional);
  EXPECT_NEAR(s.lights[0].angle, 1.5f, kEps);
  EXPECT_NEAR(s.lights[0].intensity, 2.0f, kEps);
  expectVec(s.lights[0].direction, {0, 0, -1});
  const Light& spot = s.lights[1];
  EXPECT_EQ(spot.type, LightType::Spot);
  expectVec(spot.color, {1, 0, 0});
  EXPECT_NEAR(spot.intensity, 50.0f, kEps);
  EXPECT_NEAR(spot.radius, 0.25f, kEps);
  EXPECT_NEAR(spot.innerConeAngle, 0.2f, kEps);
  EXPECT_NEAR(spot.outerConeAngle, 0.5f, kEps);
  EXPECT_NEAR(spot.range, 10.0f, kEps);
  expectVec(spot.position, {1, 0, 2});
  expectVec(spot.direction, {0, -1, 0});
  EXPECT_EQ(s.lights[2].type, LightType::Point);
  EXPECT_EQ(s.lights[2].name, "bulb");
  expectVec(s.lights[2].position, {0, 3, 0});
  const Light& rect = s.lights[3];
  EXPECT_EQ(rect.type, LightType::Rect);
  expectVec(rect.position, {1, 0, 2});
  expectVec(rect.direction, {0, -1, 0});
  expectVec(rect.right, {1, 0, 0});
  expectVec(rect.up, {0, 0, -1});
  EXPECT_NEAR(rect.width, 2.0f, kEps);
  EXPECT_NEAR(rect.height, 1.0f, kEps);
  EXPECT_NEAR(rect.intensity, 5.0f, kEps);
  expectVec(rect.color, {1, 1, 0.5f});
  EXPECT_EQ(s.lights[4].type, LightType::Rect);
  expectVec(s.lights[4].direction, {0, 0, -1});
  EXPECT_NEAR(s.lights[4].width, 0.5f, kEps);
  EXPECT_TRUE(s.hasAreaLight());

  EXPECT_TRUE(s.hasFileCamera);
  expectVec(s.camera.position, {1, 1, 10});
  EXPECT_NEAR(s.camera.fovY, glm::degrees(0.8f), 1e-3f);
  glm::vec3 forward = glm::normalize(s.camera.target - s.camera.position);
  expectVec(forward, {0, 0, -1});
  expectVec(s.camera.up, {0, 1, 0});
  EXPECT_GT(s.camera.zfar, s.camera.znear);
}

INSTANTIATE_TEST_SUITE_P(SceneGltf, SceneGltfModes,
                         ::testing::Values(GltfWriter::Mode::Embedded, GltfWriter::Mode::External,
                                           GltfWriter::Mode::Glb));

TEST(SceneGltf, MissingNormalsBecomeFlatUnitNormals) {
  GltfWriter w;
  int mesh = w.addQuadMesh("bare", false, false);
  w.setScene({w.addNode({{"mesh", mesh}})});
  Scene s = loadGltf(w.write(test::sceneTmpDir("valid"), "no_normals", GltfWriter::Mode::Embedded));
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].indices.size(), 6u);
  for (const Vertex& v : s.meshes[0].vertices) expectVec(v.normal, {0, 0, 1});
}

TEST(SceneGltf, NormalMapWithoutTangentsGetsTangentsAndTexturesKeepColorSpace) {
  for (GltfWriter::Mode mode : {GltfWriter::Mode::External, GltfWriter::Mode::Glb}) {
    GltfWriter w;
    const auto bmp = test::solidBmp(2, 2, 255, 128, 0);
    if (mode == GltfWriter::Mode::Glb) {
      w.push("images", {{"bufferView", w.addView(bmp.data(), bmp.size())}, {"mimeType", "image/bmp"}});
    } else {
      GltfWriter::writeBytes(test::sceneTmpDir("valid") + "/orange.bmp", bmp);
      w.push("images", {{"uri", "orange.bmp"}});
    }
    w.push("textures", {{"source", 0}});
    // The same image as colour (sRGB) and as data (linear): stored twice.
    w.push("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                         {"normalTexture", {{"index", 0}, {"scale", 0.5}}}});
    int mesh = w.addQuadMesh("bumpy", true, true, 0);
    w.setScene({w.addNode({{"mesh", mesh}})});
    Scene s = loadGltf(w.write(test::sceneTmpDir("valid"), "normal_mapped", mode));
    ASSERT_EQ(s.textures.size(), 2u);
    const Material& m = s.materials[0];
    ASSERT_GE(m.baseColorTexture, 0);
    ASSERT_GE(m.normalTexture, 0);
    EXPECT_NE(m.baseColorTexture, m.normalTexture);
    EXPECT_TRUE(s.textures[static_cast<size_t>(m.baseColorTexture)].srgb);
    EXPECT_FALSE(s.textures[static_cast<size_t>(m.normalTexture)].srgb);
    EXPECT_NEAR(m.normalScale, 0.5f, kEps);
    const TextureImage& t = s.textures[0];
    EXPECT_EQ(t.width, 2);
    EXPECT_EQ(t.height, 2);
    ASSERT_EQ(t.rgba8.size(), 16u);
    EXPECT_EQ(t.rgba8[0], 255);
    EXPECT_EQ(t.rgba8[1], 128);
    EXPECT_EQ(t.rgba8[2], 0);
    EXPECT_EQ(t.rgba8[3], 255);
    // u runs along +x, v decreases along +y: tangent +x, bitangent cross(n, t) * w = +y.
    for (const Vertex& v : s.meshes[0].vertices) {
      EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, kEps);
      expectVec(glm::vec3(v.tangent), {1, 0, 0});
      EXPECT_EQ(v.tangent.w, 1.0f);
    }
  }
}

TEST(SceneGltf, NoLightsNoCameraGetDefaults) {
  GltfWriter w;
  int mesh = w.addQuadMesh("alone", true, false);
  w.setScene({w.addNode({{"mesh", mesh}, {"translation", {5, 0, 0}}})});
  Scene s = loadGltf(w.write(test::sceneTmpDir("valid"), "bare", GltfWriter::Mode::Embedded));
  EXPECT_FALSE(s.hasFileLights);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, LightType::Directional);
  EXPECT_FALSE(s.hasFileCamera);
  expectVec(s.camera.target, {5, 0, 0});
  EXPECT_GT(s.camera.position.z, 0.0f);
  EXPECT_GT(s.camera.znear, 0.0f);
}

TEST(SceneGltf, AmbientFromTheDefaultScenesExtras) {
  // docs/scene-format.md: scenes[scene].extras.ambient, RGB radiance; without it the default.
  GltfWriter w;
  int mesh = w.addQuadMesh("quad", true, false);
  w.setScene({w.addNode({{"mesh", mesh}})});
  const Scene plain = loadGltf(w.write(test::sceneTmpDir("valid"), "no_ambient", GltfWriter::Mode::Embedded));
  expectVec(plain.ambient, Scene{}.ambient);
  w.doc["scenes"][0]["extras"] = {{"ambient", {0.25, 0.5, 0.125}}};
  const Scene lit = loadGltf(w.write(test::sceneTmpDir("valid"), "ambient", GltfWriter::Mode::Embedded));
  expectVec(lit.ambient, {0.25f, 0.5f, 0.125f});
}

TEST(SceneGltf, StripsFansMatricesAndSkippedLines) {
  GltfWriter w;
  int pos = w.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3", 3);
  Json strip = {{"attributes", {{"POSITION", pos}}}, {"mode", 5}};
  Json fan = {{"attributes", {{"POSITION", pos}}}, {"mode", 6}, {"indices", w.addIndices({0, 1, 3, 2})}};
  Json lines = {{"attributes", {{"POSITION", pos}}}, {"mode", 1}};
  w.push("meshes", {{"name", "mixed"}, {"primitives", {strip, fan, lines}}});
  Json matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 7, 8, 9, 1}; // column-major translation
  w.setScene({w.addNode({{"mesh", 0}, {"matrix", matrix}})});
  Scene s = loadGltf(w.write(test::sceneTmpDir("valid"), "strips", GltfWriter::Mode::Embedded));
  ASSERT_EQ(s.meshes.size(), 2u); // the line primitive is skipped
  EXPECT_EQ(s.meshes[0].name, "mixed_0");
  EXPECT_EQ(s.meshes[0].indices.size(), 6u);
  EXPECT_EQ(s.meshes[1].indices.size(), 6u);
  for (const Mesh& m : s.meshes)
    for (const Vertex& v : m.vertices) expectVec(v.normal, {0, 0, 1}); // both wind counter-clockwise
  expectVec(glm::vec3(s.instances[0].transform[3]), {7, 8, 9});
}

TEST(SceneGltf, NormalizedByteTexcoordsAndOrthographicCameraIgnored) {
  GltfWriter w;
  const std::uint8_t uv[16] = {0, 255, 9, 9, 255, 255, 9, 9, 255, 0, 9, 9, 0, 0, 9, 9}; // stride 4
  int uvAccessor = w.addAccessor(w.addView(uv, 16, 4), 5121, "VEC2", 4, 0, true);
  int pos = w.addFloats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3);
  Json prim = {{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uvAccessor}}}, {"indices", w.addIndices({0, 1, 2, 0, 2, 3})}};
  w.push("meshes", {{"primitives", {prim}}});
  w.push("cameras", {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}});
  w.setScene({w.addNode({{"mesh", 0}, {"camera", 0}})});
  Scene s = loadGltf(w.write(test::sceneTmpDir("valid"), "bytes", GltfWriter::Mode::Embedded));
  EXPECT_FALSE(s.hasFileCamera);
  EXPECT_EQ(s.meshes[0].name, "mesh0");
  // Flat normals de-index; the first triangle's corners keep their UVs.
  EXPECT_NEAR(s.meshes[0].vertices[0].uv.y, 1.0f, kEps);
  EXPECT_NEAR(s.meshes[0].vertices[1].uv.x, 1.0f, kEps);
}

} // namespace
} // namespace rtlab
