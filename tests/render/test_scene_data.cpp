// The GPU scene data (docs/scene-data.md "GPU scene data"): a compute shader in a technique's pass
// reads the world-space triangles through shaders/common/scene_triangles.glsl, and what it reads
// (corners, material words, normals, areas, bounds, counts) matches the Scene computed on the CPU.
// The buffers exist only once a technique asks for them, and such a technique rebakes only when
// the geometry changed.
#include <gtest/gtest.h>

#include "frame/frame_graph.h"
#include "gl/program_cache.h"
#include "own_registry.h"
#include "scene/world_triangles.h"
#include "shading/base_passes.h"
#include "shading/scene_gpu.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace rtlab {
namespace {

// std430 layout of shaders/tests/scene_triangles.comp's Results block.
struct ResultHeader {
  std::uint32_t visited = 0, infoTriangles = 0, infoVertices = 0, pad = 0;
  std::int32_t codeMin[4] = {INT32_MAX, INT32_MAX, INT32_MAX, INT32_MAX};
  std::int32_t codeMax[4] = {INT32_MIN, INT32_MIN, INT32_MIN, INT32_MIN};
  glm::vec4 infoMin{0.0f}, infoMax{0.0f};
};
struct TriangleResult {
  glm::uvec4 corners;
  glm::vec4 normalArea;
};
static_assert(sizeof(ResultHeader) == 80 && sizeof(TriangleResult) == 32);

float decodeOrder(std::int32_t code) { return std::bit_cast<float>(code >= 0 ? code : code ^ 0x7FFFFFFF); }

struct Measurement {
  int bakes = 0;
  ResultHeader header;
  std::vector<TriangleResult> triangles;
};

// Bakes on the first frame and after each geometry change only, as a distance-field technique
// would: the measuring dispatch runs in the pass that writes the technique's debug view.
class ProbeTechnique : public Technique {
public:
  ProbeTechnique(TechniqueInfo info, std::shared_ptr<Measurement> out) : m_info(std::move(info)), m_out(std::move(out)) {}
  const TechniqueInfo& info() const override { return m_info; }
  void sceneChanged(const SceneChange& change) override { m_stale = m_stale || change.geometry; }
  void setup(FrameGraph& frame) override {
    const std::string out = aovResource("probe.area");
    frame.addPass("probe.measure", [&](PassBuilder& b) { b.write(out, frameTexture(frame, GL_RGBA32F)); },
                  [this, out](PassContext& ctx) {
                    if (m_stale) bake(ctx);
                    m_stale = false;
                    const float zero[4] = {0, 0, 0, 0};
                    glClearTexImage(ctx.texture(out).id(), 0, GL_RGBA, GL_FLOAT, zero);
                  });
  }
  std::size_t ownedBytes() const override { return m_bytes; }

private:
  void bake(PassContext& ctx) {
    const SceneTrianglesGpu& scene = ctx.sceneGpu.triangles();
    const std::size_t count = scene.triangleCount();
    std::vector<std::uint8_t> init(sizeof(ResultHeader) + count * sizeof(TriangleResult), 0);
    const ResultHeader header;
    std::memcpy(init.data(), &header, sizeof(header));
    m_results = gl::Buffer("probe.results");
    glNamedBufferStorage(m_results.id(), GLsizeiptr(init.size()), init.data(), 0);
    m_bytes = init.size();
    gl::Program& p = ctx.programs.get({{"tests/scene_triangles.comp"}, {}, "tests.scene_triangles"});
    p.use();
    ctx.sceneGpu.bindTriangles();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, m_results.id());
    glDispatchCompute(GLuint(std::max<std::size_t>(1, (count + 63) / 64)), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(m_results.id(), 0, sizeof(ResultHeader), &m_out->header);
    m_out->triangles.resize(count);
    if (count > 0)
      glGetNamedBufferSubData(m_results.id(), sizeof(ResultHeader), GLsizeiptr(count * sizeof(TriangleResult)),
                              m_out->triangles.data());
    ++m_out->bakes;
  }

  TechniqueInfo m_info;
  std::shared_ptr<Measurement> m_out;
  gl::Buffer m_results;
  std::size_t m_bytes = 0;
  bool m_stale = false;
};

class SceneData : public OwnRegistryTest {
protected:
  void SetUp() override {
    OwnRegistryTest::SetUp();
    TechniqueEntry e;
    e.info.id = "probe";
    e.info.stage = "post";
    e.info.title = "probe";
    e.info.debugViews = {DebugView{"probe.area", 1, "nothing (the pass measures the scene data)"}};
    e.create = [info = e.info, out = m_out] { return std::make_unique<ProbeTechnique>(info, out); };
    m_registry.add(e);
  }

  void render(int frames = 1) { OwnRegistryTest::render(FrameOutputs{{"probe.area"}}, frames); }
  std::size_t resourceBytes(const std::string& name) const {
    for (const auto& r : m_renderer->resources())
      if (r.name == name) return r.bytes;
    return 0;
  }

  // Compares the GPU's reading with the Scene, triangle by triangle in the documented order.
  void expectMatchesScene() {
    const Measurement& m = *m_out;
    std::uint32_t base = 0;
    std::size_t t = 0, vertices = 0;
    Bounds bounds;
    double area = 0.0, gpuArea = 0.0;
    for (const Instance& inst : m_scene.instances) {
      const Mesh& mesh = m_scene.meshes[std::size_t(inst.mesh)];
      const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
      auto world = [&](std::uint32_t i) { return glm::vec3(inst.transform * glm::vec4(mesh.vertices[i].position, 1.0f)); };
      auto normal = [&](std::uint32_t i) { return glm::normalize(normalMatrix * mesh.vertices[i].normal); };
      const std::uint32_t material = mesh.material >= 0 ? std::uint32_t(mesh.material) : kTriangleDefaultMaterial;
      for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3, ++t) {
        ASSERT_LT(t, m.triangles.size());
        const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
        const TriangleResult& r = m.triangles[t];
        EXPECT_EQ(r.corners, glm::uvec4(base + a, base + b, base + c, material | (inst.transparent ? kTriangleTransparent : 0u)))
            << "triangle " << t;
        const float expectedArea = 0.5f * glm::length(glm::cross(world(b) - world(a), world(c) - world(a)));
        EXPECT_NEAR(r.normalArea.w, expectedArea, 1e-5f * std::max(1.0f, expectedArea)) << "triangle " << t;
        const glm::vec3 normalSum = normal(a) + normal(b) + normal(c);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.normalArea[k], normalSum[k], 1e-5f) << "triangle " << t;
        for (std::uint32_t v : {a, b, c}) bounds.extend(world(v));
        area += expectedArea;
        gpuArea += r.normalArea.w;
      }
      base += std::uint32_t(mesh.vertices.size());
      vertices += mesh.vertices.size();
    }
    EXPECT_EQ(m.triangles.size(), t);
    EXPECT_EQ(m.header.visited, t);
    EXPECT_EQ(m.header.infoTriangles, t);
    EXPECT_EQ(m.header.infoVertices, vertices);
    EXPECT_NEAR(gpuArea, area, 1e-5 * area);
    for (int k = 0; k < 3; ++k) {
      EXPECT_FLOAT_EQ(decodeOrder(m.header.codeMin[k]), bounds.min[k]) << "axis " << k;
      EXPECT_FLOAT_EQ(decodeOrder(m.header.codeMax[k]), bounds.max[k]) << "axis " << k;
      EXPECT_FLOAT_EQ(m.header.infoMin[k], bounds.min[k]) << "axis " << k;
      EXPECT_FLOAT_EQ(m.header.infoMax[k], bounds.max[k]) << "axis " << k;
    }
    const std::size_t expectedBytes = 48 + 32 * vertices + 16 * t; // info, positions + normals, triangles
    EXPECT_EQ(resourceBytes("scene.triangles"), expectedBytes);
  }

  std::shared_ptr<Measurement> m_out = std::make_shared<Measurement>();
};

TEST_F(SceneData, AComputeShaderReadsTheWorldSpaceTrianglesOfRotatedInstances) {
  load("cornell"); // two blocks turned by +-17 degrees
  m_renderer->setTechniques({"probe"});
  render();
  ASSERT_EQ(m_out->bakes, 1);
  expectMatchesScene();
}

TEST_F(SceneData, TransparentInstancesAreFlagged) {
  load("panes");
  m_renderer->setTechniques({"probe"});
  render();
  ASSERT_EQ(m_out->bakes, 1);
  expectMatchesScene();
  const auto flagged = std::count_if(m_out->triangles.begin(), m_out->triangles.end(),
                                     [](const TriangleResult& r) { return (r.corners.w & kTriangleTransparent) != 0; });
  EXPECT_GT(flagged, 0);
  EXPECT_LT(std::size_t(flagged), m_out->triangles.size());
}

TEST_F(SceneData, BuiltOnlyWhenAskedAndRebakedOnlyOnGeometryChange) {
  load("contact");
  OwnRegistryTest::render(FrameOutputs{{}, true}); // a whole frame without a technique that asks
  EXPECT_EQ(resourceBytes("scene.triangles"), 0u);
  m_renderer->setTechniques({"probe"});
  render(3);
  EXPECT_EQ(m_out->bakes, 1);
  EXPECT_GT(resourceBytes("scene.triangles"), 0u);
  m_params.setAssignment("light0.intensity=100");
  m_params.setAssignment("camera.fov=30");
  render(2);
  EXPECT_EQ(m_out->bakes, 1) << "a light or camera change must not rebake";
  m_renderer->setScene(m_scene);
  EXPECT_EQ(resourceBytes("scene.triangles"), 0u) << "a new scene drops the old triangle buffers";
  render(2);
  EXPECT_EQ(m_out->bakes, 2);
  expectMatchesScene();
}

} // namespace
} // namespace rtlab
