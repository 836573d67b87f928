// Built-in scenes, procedural meshes, framing and scene-spec resolution.
#include "scene/builtin.h"
#include "scene/load.h"
#include "scene/mesh_builder.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace rtlab {
namespace {

const Mesh* findMesh(const Scene& s, const std::string& name, int* instance = nullptr) {
  for (size_t i = 0; i < s.instances.size(); ++i) {
    const Mesh& m = s.meshes[static_cast<size_t>(s.instances[i].mesh)];
    if (m.name == name) {
      if (instance) *instance = static_cast<int>(i);
      return &m;
    }
  }
  return nullptr;
}

Bounds instanceBounds(const Scene& s, const std::string& name) {
  int i = -1;
  EXPECT_NE(findMesh(s, name, &i), nullptr) << name;
  Scene one;
  one.meshes = s.meshes;
  if (i >= 0) one.instances = {s.instances[static_cast<size_t>(i)]};
  return one.worldBounds();
}

// Slab test: does the segment a->b (excluding its last 1%) pass through the box?
bool segmentHitsBox(const glm::vec3& a, const glm::vec3& b, const Bounds& box) {
  float t0 = 0.0f, t1 = 0.99f;
  for (int k = 0; k < 3; ++k) {
    float d = b[k] - a[k];
    if (std::fabs(d) < 1e-12f) {
      if (a[k] < box.min[k] || a[k] > box.max[k]) return false;
      continue;
    }
    float u = (box.min[k] - a[k]) / d, v = (box.max[k] - a[k]) / d;
    t0 = std::max(t0, std::min(u, v));
    t1 = std::min(t1, std::max(u, v));
  }
  return t0 <= t1;
}

// Every triangle is counter-clockwise seen from the side its vertex normals point to.
void expectConsistentMesh(const Mesh& m) {
  ASSERT_FALSE(m.indices.empty()) << m.name;
  ASSERT_EQ(m.indices.size() % 3, 0u) << m.name;
  for (std::uint32_t i : m.indices) ASSERT_LT(i, m.vertices.size()) << m.name;
  for (const Vertex& v : m.vertices) {
    ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f) << m.name;
    ASSERT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-4f) << m.name;
    ASSERT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-4f) << m.name;
    ASSERT_EQ(std::fabs(v.tangent.w), 1.0f) << m.name;
  }
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const Vertex& a = m.vertices[m.indices[t]];
    const Vertex& b = m.vertices[m.indices[t + 1]];
    const Vertex& c = m.vertices[m.indices[t + 2]];
    glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
    ASSERT_GT(glm::length(face), 0.0f) << m.name << " degenerate triangle " << t / 3;
    ASSERT_GT(glm::dot(face, a.normal + b.normal + c.normal), 0.0f) << m.name << " triangle " << t / 3;
  }
}

TEST(SceneBuiltin, NamesInListOrder) {
  EXPECT_EQ(builtinSceneNames(), (std::vector<std::string>{"contact", "stacked", "cornell", "panes", "arealight", "glow", "layers", "arealight_ramp", "gi_wall"}));
  EXPECT_TRUE(isBuiltinScene("cornell"));
  EXPECT_FALSE(isBuiltinScene("Cornell"));
}

TEST(SceneBuiltin, EveryBuiltinSceneIsWellFormed) {
  for (const std::string& name : builtinSceneNames()) {
    SCOPED_TRACE(name);
    Scene s = makeBuiltinScene(name);
    EXPECT_EQ(s.name, name);
    EXPECT_GE(s.lights.size(), 1u);
    EXPECT_TRUE(s.hasFileCamera);
    EXPECT_TRUE(s.hasFileLights);
    Bounds b = s.worldBounds();
    ASSERT_TRUE(b.valid());
    EXPECT_TRUE(std::isfinite(b.radius()) && b.radius() > 0.0f);
    EXPECT_GT(s.camera.znear, 0.0f);
    EXPECT_GT(s.camera.zfar, s.camera.znear);
    EXPECT_GE(s.camera.znear, s.camera.zfar / 10000.0f);
    // A dim ambient, except on the AO showcase scene, where AO must show in color (issue 12).
    EXPECT_GE(s.ambient.x, 0.03f);
    EXPECT_LE(s.ambient.x, name == "cornell" ? 0.2f : 0.05f);
    for (const Instance& inst : s.instances) {
      ASSERT_GE(inst.mesh, 0);
      ASSERT_LT(static_cast<size_t>(inst.mesh), s.meshes.size());
    }
    for (const Mesh& m : s.meshes) {
      EXPECT_FALSE(m.name.empty());
      ASSERT_GE(m.material, 0);
      ASSERT_LT(static_cast<size_t>(m.material), s.materials.size());
      expectConsistentMesh(m);
    }
    for (const Light& l : s.lights) {
      EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-5f);
      EXPECT_GT(l.intensity, 0.0f);
    }
    // Light 0 casts shadows: the shadow stage handles directional, spot and point lights.
    EXPECT_NE(s.lights[0].type, LightType::Rect);
  }
}

TEST(SceneBuiltin, ContactHasGroundAndFloatingBoxAboveIt) {
  Scene s = makeBuiltinScene("contact");
  Bounds ground = instanceBounds(s, "ground");
  Bounds floating = instanceBounds(s, "floating");
  EXPECT_NEAR(ground.max.y, 0.0f, 1e-5f);
  EXPECT_NEAR(ground.max.x - ground.min.x, 12.0f, 1e-4f);
  EXPECT_NEAR(floating.min.y, 1.2f, 1e-4f);
  EXPECT_GT(floating.min.y, ground.max.y + 1.0f);
  // Box and sphere rest on the ground.
  EXPECT_NEAR(instanceBounds(s, "box").min.y, 0.0f, 1e-4f);
  EXPECT_NEAR(instanceBounds(s, "sphere").min.y, 0.0f, 1e-3f);
  EXPECT_NEAR(instanceBounds(s, "wall").min.y, 0.0f, 1e-4f);
  EXPECT_EQ(s.lights[0].type, LightType::Spot);
  EXPECT_NEAR(s.lights[0].radius, 0.1f, 1e-6f);

  // The floating box's shadow centre, projected from light 0, lands on the ground inside it
  // and in front of the camera, under no other object's bounds.
  const glm::vec3 L = s.lights[0].position, c = floating.center();
  const glm::vec3 shadow = L + (c - L) * (L.y / (L.y - c.y));
  EXPECT_LT(std::fabs(shadow.x), 5.0f);
  EXPECT_LT(std::fabs(shadow.z), 5.0f);
  for (const char* other : {"box", "sphere", "wall"}) {
    Bounds o = instanceBounds(s, other);
    bool inside = shadow.x > o.min.x && shadow.x < o.max.x && shadow.z > o.min.z && shadow.z < o.max.z;
    EXPECT_FALSE(inside) << other;
  }
  // Nothing (not even the floating box) hides the shadow centre from the camera.
  for (const char* other : {"box", "sphere", "wall", "floating"}) {
    Bounds o = instanceBounds(s, other);
    EXPECT_FALSE(segmentHitsBox(s.camera.position, shadow, o)) << other;
  }
  const glm::vec3 toShadow = glm::normalize(shadow - s.camera.position);
  const glm::vec3 forward = glm::normalize(s.camera.target - s.camera.position);
  EXPECT_GT(glm::dot(toShadow, forward), std::cos(glm::radians(s.camera.fovY * 0.5f)));
}

TEST(SceneBuiltin, StackedHasTwoPlatesAndAnAngularLight) {
  Scene s = makeBuiltinScene("stacked");
  EXPECT_NEAR(instanceBounds(s, "plate_low").center().y, 0.8f, 1e-4f);
  EXPECT_NEAR(instanceBounds(s, "plate_high").center().y, 2.2f, 1e-4f);
  EXPECT_EQ(s.lights[0].type, LightType::Directional);
  EXPECT_NEAR(s.lights[0].angle, 1.5f, 1e-6f);
}

TEST(SceneBuiltin, CornellWallsFaceInward) {
  Scene s = makeBuiltinScene("cornell");
  const glm::vec3 inside(0.0f, 2.75f, 0.0f);
  for (const char* wall : {"floor", "ceiling", "back", "left", "right"}) {
    int i = -1;
    const Mesh* m = findMesh(s, wall, &i);
    ASSERT_NE(m, nullptr) << wall;
    const glm::mat4& t = s.instances[static_cast<size_t>(i)].transform;
    for (const Vertex& v : m->vertices) {
      glm::vec3 p(t * glm::vec4(v.position, 1.0f));
      glm::vec3 n = glm::normalize(glm::vec3(t * glm::vec4(v.normal, 0.0f)));
      EXPECT_GT(glm::dot(n, inside - p), 0.0f) << wall;
    }
  }
  for (const char* name : {"tall_block", "short_block", "light_panel"}) EXPECT_NE(findMesh(s, name), nullptr) << name;
  const Material& left = s.materials[static_cast<size_t>(findMesh(s, "left")->material)];
  const Material& right = s.materials[static_cast<size_t>(findMesh(s, "right")->material)];
  EXPECT_GT(left.baseColor.x, left.baseColor.y);   // red
  EXPECT_GT(right.baseColor.y, right.baseColor.x); // green
  EXPECT_EQ(s.lights.size(), 1u); // the panel is geometry only
  EXPECT_EQ(s.lights[0].type, LightType::Spot);
  EXPECT_NEAR(s.lights[0].direction.y, -1.0f, 1e-6f);
  EXPECT_LT(s.lights[0].position.y + s.lights[0].radius, 5.5f);
}

TEST(SceneBuiltin, PanesHaveTransparentInstances) {
  Scene s = makeBuiltinScene("panes");
  EXPECT_TRUE(s.hasTransparency());
  int transparent = 0;
  for (const Instance& i : s.instances) transparent += i.transparent ? 1 : 0;
  EXPECT_GE(transparent, 3);
  for (const char* name : {"pane_red", "pane_green", "pane_blue"}) {
    const Mesh* m = findMesh(s, name);
    ASSERT_NE(m, nullptr) << name;
    const Material& mat = s.materials[static_cast<size_t>(m->material)];
    EXPECT_EQ(mat.alphaMode, AlphaMode::Blend);
    EXPECT_GE(mat.baseColor.w, 0.4f);
    EXPECT_LE(mat.baseColor.w, 0.6f);
  }
  EXPECT_NE(findMesh(s, "backdrop"), nullptr);
  EXPECT_FALSE(makeBuiltinScene("contact").hasTransparency());
}

// layers (docs/scene-format.md): what the transparency extremes need — 24 transparent layers whose
// view depths span 0.1 to 500 (the range the WBOIT weights assume), a high-alpha layer in front of
// low-alpha ones, two layers that cut through each other, and an opaque backdrop inside the far plane.
TEST(SceneBuiltin, LayersSpanTheWeightsDepthRange) {
  Scene s = makeBuiltinScene("layers");
  auto depthOf = [&](const std::string& name) { return -instanceBounds(s, name).center().z; };
  float nearest = 1e9f, farthest = 0.0f;
  for (int k = 0; k < 24; ++k) {
    const std::string name = std::string("stack_") + (k < 10 ? "0" : "") + std::to_string(k);
    const Mesh* m = findMesh(s, name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_EQ(s.materials[static_cast<size_t>(m->material)].alphaMode, AlphaMode::Blend) << name;
    nearest = std::min(nearest, depthOf(name));
    farthest = std::max(farthest, depthOf(name));
  }
  EXPECT_NEAR(nearest, 0.1f, 1e-4f);
  EXPECT_NEAR(farthest, 500.0f, 0.05f);
  EXPECT_LT(s.camera.znear, nearest);
  EXPECT_GT(s.camera.zfar, depthOf("backdrop"));
  auto alphaOf = [&](const std::string& name) { return s.materials[size_t(findMesh(s, name)->material)].baseColor.w; };
  EXPECT_GE(alphaOf("front_high"), 0.9f);
  for (const char* back : {"back_low_0", "back_low_1", "back_low_2"}) {
    EXPECT_LE(alphaOf(back), 0.2f);
    EXPECT_GT(depthOf(back), depthOf("front_high"));
  }
  // The crossing pair: same centre, so each has parts in front of and behind the other.
  EXPECT_NEAR(glm::length(instanceBounds(s, "cross_a").center() - instanceBounds(s, "cross_b").center()), 0.0f, 1e-4f);
  EXPECT_FALSE(s.materials[size_t(findMesh(s, "backdrop")->material)].alphaMode == AlphaMode::Blend);
}

TEST(SceneBuiltin, AreaLightSceneHasARectLightAfterTheSpot) {
  Scene s = makeBuiltinScene("arealight");
  EXPECT_TRUE(s.hasAreaLight());
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].type, LightType::Spot);
  const Light& r = s.lights[1];
  EXPECT_EQ(r.type, LightType::Rect);
  EXPECT_GT(r.width, 0.0f);
  EXPECT_GT(r.height, 0.0f);
  // It emits along -cross(right, up), like a glTF node's -Z.
  EXPECT_NEAR(glm::dot(-glm::cross(r.right, r.up), r.direction), 1.0f, 1e-5f);
  const Material& floor = s.materials[static_cast<size_t>(findMesh(s, "floor")->material)];
  EXPECT_NEAR(floor.roughness, 0.2f, 1e-6f);
  EXPECT_EQ(floor.metallic, 0.0f);
  EXPECT_FALSE(makeBuiltinScene("contact").hasAreaLight());
}

TEST(SceneBuiltin, DeterministicGeneration) {
  Scene a = makeBuiltinScene("contact"), b = makeBuiltinScene("contact");
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (size_t i = 0; i < a.meshes.size(); ++i)
    ASSERT_EQ(0, std::memcmp(a.meshes[i].vertices.data(), b.meshes[i].vertices.data(),
                             a.meshes[i].vertices.size() * sizeof(Vertex)));
}

TEST(SceneBuiltin, ProceduralMeshesAreConsistent) {
  expectConsistentMesh(makeBox("b", {1, 2, 3}));
  expectConsistentMesh(makeSphere("s", 2.0f, 12, 6));
  expectConsistentMesh(makePlane("p", 4, 4, 3));
  expectConsistentMesh(makeCylinder("c", 0.5f, 2.0f, 16));
  Mesh box = makeBox("b", {1, 2, 3});
  EXPECT_EQ(box.bounds.min, glm::vec3(-0.5f, -1.0f, -1.5f));
  EXPECT_EQ(box.bounds.max, glm::vec3(0.5f, 1.0f, 1.5f));
}

TEST(SceneBuiltin, GeneratedTangentsMatchAnalyticOnes) {
  Mesh quad = makeQuad("q", glm::vec3(0), {1, 0, 0}, {0, 1, 0});
  Mesh regenerated = quad;
  generateTangents(regenerated);
  for (size_t i = 0; i < quad.vertices.size(); ++i)
    EXPECT_LT(glm::length(quad.vertices[i].tangent - regenerated.vertices[i].tangent), 1e-5f);
  // Mirrored UVs flip the handedness.
  for (Vertex& v : regenerated.vertices) v.uv.x = 1.0f - v.uv.x;
  generateTangents(regenerated);
  for (const Vertex& v : regenerated.vertices) {
    EXPECT_NEAR(v.tangent.x, -1.0f, 1e-5f);
    EXPECT_EQ(v.tangent.w, -1.0f);
  }
}

TEST(SceneBuiltin, FrameBoundsFitsTheBoundingSphere) {
  Bounds b;
  b.extend(glm::vec3(-1, 0, -2));
  b.extend(glm::vec3(3, 2, 2));
  Camera c = frameBounds(b, 45.0f);
  EXPECT_EQ(c.target, b.center());
  const float d = glm::length(c.position - b.center());
  EXPECT_GE(std::asin(b.radius() / d), 0.0f);
  EXPECT_LE(std::asin(b.radius() / d), glm::radians(22.5f));
  glm::vec3 dir = glm::normalize(c.position - b.center());
  EXPECT_NEAR(dir.y / dir.z, 0.35f, 1e-4f);
  EXPECT_LE(c.znear, d - b.radius());
  EXPECT_GE(c.zfar, d + b.radius());
  EXPECT_GE(c.znear, 0.01f);
}

TEST(SceneBuiltin, DefaultLightIsDirectional) {
  Bounds b;
  b.extend(glm::vec3(-1));
  b.extend(glm::vec3(1));
  Light l = defaultLight(b);
  EXPECT_EQ(l.type, LightType::Directional);
  EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-6f);
  EXPECT_LT(l.direction.y, 0.0f);
  EXPECT_GT(l.intensity, 0.0f);
}

TEST(SceneLoad, BuiltinNamesAndUnknownNames) {
  EXPECT_EQ(loadScene("stacked").name, "stacked");
  try {
    loadScene("nosuchscene");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Usage);
    EXPECT_EQ(std::string(e.what()),
              "unknown scene 'nosuchscene' (built-in scenes: contact, stacked, cornell, panes, arealight, glow, layers, arealight_ramp, gi_wall)");
  }
  for (const char* missing : {"/nonexistent/dir/x.gltf", "missing.GLB", "missing.glTF"}) {
    try {
      loadScene(missing);
      FAIL() << "expected an error for " << missing;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::Input) << missing;
      EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
  }
}

} // namespace
} // namespace rtlab
