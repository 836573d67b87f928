// The acceptance test of the moment techniques' precision (issue 19; techniques/vssm/README.md and
// techniques/msm/README.md, "Precision"): vssm and msm render `contact` and `stacked`, and their
// own moment map and summed-area table are read back. Then
//   1. the GL table equals, word for word, the CPU model's table (tests/support/moment_model.h) built
//      from the moments as sat.comp reads them: its fixed point and wrap-around are what the model says;
//   2. boxMoments and the bound on that table (tests/render/shaders/moment_lookup.comp, the
//      functions of shaders/shadow/common/moments.glsl) over a grid of lookups into the scene's map
//      (every radius the techniques use, receivers at and near the box centre's depth) are what the
//      float model computes, and match the fp64 model of the same table within kBound, with at most
//      kMaxOver lookups over it: vssm, and msm with `msm.centred`; msm without it departs on a
//      sixth of them or more (the finding), and matches the float model on llvmpipe only (a GPU's
//      fused multiply-adds change its last bits, which that solve amplifies);
//   3. against the fp64 model of the exact stored moments (a lossless table), the 64-bit table
//      (`<id>.sat_bits` 64) departs less often than the 32-bit one.
#include "frame_graph_fixture.h"
#include "render_fixture.h"
#include "techniques/common/shadow/moment_map.h"
#include "tests/support/moment_model.h"

#include "gl/buffer.h"

#include <gtest/gtest.h>

using namespace rtlab;
using namespace rtlab::moment_model;

// Named: the test executables are unity builds (tests/CMakeLists.txt).
namespace moment_precision_test {
namespace {

constexpr int kMapSize = 256;       // shadow.resolution of these renders
constexpr double kBound = 0.01;     // visibility difference that counts
constexpr int kMaxOver = 1;         // lookups over it allowed against the fp64 model (of 6144)
const float kRadii[] = {0.5f, 1.5f, 3.0f, 8.0f, 24.0f, 64.0f};
const double kReceiverOffsets[] = {-1e-3, 1e-4, 1e-3, 1e-2}; // t - the centre texel's depth

struct Lookups {
  std::vector<glm::vec4> queries; // u, v, radius, t
  std::vector<TexelBox> boxes;
};

struct Case {
  std::string technique, scene;
  int bits;
  bool centred = false; // msm.centred
};

std::string caseName(const Case& c) {
  return c.technique + " on " + c.scene + ", " + std::to_string(c.bits) + "-bit table" + (c.centred ? ", centred" : "");
}

// The stored moments of the last frame's "<id>.moments" as sat.comp reads them (texelFetch in a
// shader: tests/render/shaders/moment_fetch.comp), and its table "<id>.sat".
std::vector<float> readMoments(Renderer& r, const std::string& id, int channels) {
  const gl::Texture* t = r.resource(id + ".moments");
  EXPECT_NE(t, nullptr);
  if (!t) return {};
  gl::ProgramDesc desc;
  desc.stages = {testShader("moment_fetch.comp")};
  desc.label = "moment-fetch";
  static gl::ProgramCache programs;
  gl::Program& p = programs.get(desc);
  const std::size_t texels = std::size_t(kMapSize) * kMapSize;
  gl::BufferObject out({gl::BufferKind::Storage, texels * sizeof(glm::vec4)}, "moment-texels");
  p.use();
  p.set("uSize", kMapSize);
  glBindTextureUnit(0, t->id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, out.id());
  glDispatchCompute(GLuint((texels + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<glm::vec4> rgba = out.downloadAs<glm::vec4>();
  glUseProgram(0);
  glBindTextureUnit(0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  std::vector<float> v;
  v.reserve(texels * channels);
  for (const glm::vec4& m : rgba)
    for (int ch = 0; ch < channels; ++ch) v.push_back(m[ch]);
  return v;
}
std::vector<uint32_t> readTable(Renderer& r, const std::string& id, int channels, int width) {
  const gl::Texture* t = r.resource(id + ".sat");
  EXPECT_NE(t, nullptr);
  if (!t) return {};
  EXPECT_EQ(t->desc().width, width);
  std::vector<uint32_t> v(size_t(width) * kMapSize * channels);
  glGetTextureImage(t->id(), 0, channels == 2 ? GL_RG_INTEGER : GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                    GLsizei(v.size() * sizeof(uint32_t)), v.data());
  return v;
}

// A 16 x 16 grid of box centres over the map (texel centres), each with every radius and receiver.
Lookups makeLookups(const MomentMapModel& map) {
  Lookups l;
  for (int gy = 0; gy < 16; ++gy)
    for (int gx = 0; gx < 16; ++gx) {
      const int x = gx * kMapSize / 16 + 5, y = gy * kMapSize / 16 + 11;
      const float u = (float(x) + 0.5f) / kMapSize, v = (float(y) + 0.5f) / kMapSize;
      const double z = map.storedMean(TexelBox{x, y, x, y})[0];
      for (float radius : kRadii)
        for (double dt : kReceiverOffsets) {
          l.queries.push_back(glm::vec4(u, v, radius, float(z + dt)));
          l.boxes.push_back(texelBox(u, v, radius, kMapSize));
        }
    }
  return l;
}

struct Outcome {
  int overModel = 0;    // |GPU - fp64 model of the same table| > kBound
  int overLossless = 0; // |GPU - fp64 model of the exact stored moments| > kBound
  double maxModel = 0;
  int lookups = 0;
  int overFloat = 0;     // |GPU - float model of the shader| > kBound
};

Outcome check(const Case& c) {
  const bool msm = c.technique == "msm";
  const int channels = msm ? 4 : 2;
  const double knob = msm ? 3e-5 : 1e-5; // the defaults: msm.moment_bias, vssm.min_variance
  std::vector<std::string> sets = {"shadow.resolution=" + std::to_string(kMapSize),
                                   c.technique + ".sat_bits=" + std::to_string(c.bits)};
  if (msm) sets.push_back(std::string("msm.centred=") + (c.centred ? "true" : "false"));
  const TestFrame frame = makeTestFrame(c.scene, c.technique, sets, 160, 90);
  const TestRender r = renderTestFrame(frame, {"visibility"});
  EXPECT_EQ(r.glErrors, 0);

  MomentMapModel map;
  map.size = kMapSize;
  map.moments = channels;
  map.optimized = msm;
  map.wide = c.bits == 64;
  MomentMapConfig config;
  config.technique = c.technique;
  config.moments = channels;
  map.scale = momentSatScale(frame.params, config);
  map.stored = readMoments(*r.renderer, c.technique, channels);
  const int tableWidth = map.wide ? 2 * kMapSize : kMapSize;
  const std::vector<uint32_t> gpuTable = readTable(*r.renderer, c.technique, channels, tableWidth);
  Outcome out;
  if (map.stored.empty() || gpuTable.empty()) return out;

  // 1. The table, word for word.
  const SummedAreaTable sat = map.table();
  int mismatches = 0;
  for (int y = 0; y < kMapSize; ++y)
    for (int x = 0; x < kMapSize; ++x)
      for (int ch = 0; ch < channels; ++ch) {
        const uint64_t sum = sat.at(x, y, ch);
        const size_t row = size_t(y) * tableWidth;
        mismatches += gpuTable[(row + x) * channels + ch] != uint32_t(sum);
        if (map.wide) mismatches += gpuTable[(row + kMapSize + x) * channels + ch] != uint32_t(sum >> 32);
      }
  EXPECT_EQ(mismatches, 0) << caseName(c);

  // 2. and 3. The lookups on the GL table against the model.
  const Lookups l = makeLookups(map);
  gl::ProgramDesc desc;
  desc.stages = {testShader("moment_lookup.comp")};
  desc.defines = {"MOMENTS " + std::to_string(channels)};
  desc.label = "moment-lookup";
  static gl::ProgramCache programs;
  gl::Program& p = programs.get(desc);
  gl::BufferObject queries({gl::BufferKind::Storage, l.queries.size() * sizeof(glm::vec4)}, "moment-queries",
                           l.queries.data());
  gl::BufferObject results({gl::BufferKind::Storage, 2 * l.queries.size() * sizeof(glm::vec4)}, "moment-results");
  p.use();
  glBindTextureUnit(3, r.renderer->resource(c.technique + ".sat")->id());
  p.set("uSat", 3)
      .set("uSatOffset", glm::vec4(0.5f))
      .set("uSatScale", float(map.scale))
      .set("uSatWide", map.wide)
      .set("uMapResolution", float(kMapSize))
      .set("uCount", int(l.queries.size()))
      .set("uKnob", float(knob))
      .set("uCentred", c.centred);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, queries.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, results.id());
  glDispatchCompute(GLuint((l.queries.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<glm::vec4> got = results.downloadAs<glm::vec4>();
  // Back to the known state the frame graph checks before its next frame.
  glUseProgram(0);
  glBindTextureUnit(3, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  EXPECT_EQ(drainGlErrors(), 0);

  auto bound = [&](const Vec4<double>& m, double t) {
    return msm ? 1.0 - hamburger4Msm(m, t, knob) : chebyshevUpperBound(m[0], m[1], t, knob);
  };
  for (size_t i = 0; i < l.queries.size(); ++i) {
    const double t = l.queries[i].w;
    const double gpu = got[2 * i + 1].x;
    EXPECT_TRUE(std::isfinite(gpu)) << caseName(c) << " lookup " << i;
    const double model = bound(map.boxMoments<double>(sat, l.boxes[i]), t);
    const double lossless = bound(map.storedMean(l.boxes[i]), t);
    out.maxModel = std::max(out.maxModel, std::abs(gpu - model));
    // The float model of the shader's path (centred: the moments in double, then about t in float).
    const Vec4<float> mf = map.boxMoments<float>(sat, l.boxes[i]);
    double floatModel = 0;
    if (!msm)
      floatModel = chebyshevUpperBound(mf[0], mf[1], float(t), float(knob));
    else if (c.centred)
      floatModel = 1.0 - hamburger4Msm(momentsAbout(map.boxMoments<double>(sat, l.boxes[i]), t, knob), 0.0f, 0.0f);
    else
      floatModel = 1.0 - hamburger4Msm(mf, float(t), float(knob));
    out.overFloat += std::abs(gpu - floatModel) > kBound;
    out.overModel += std::abs(gpu - model) > kBound;
    out.overLossless += std::abs(gpu - lossless) > kBound;
  }
  out.lookups = int(l.queries.size());
  std::printf("%s: %d lookups; over %.2f: %d against the float model, %d against the fp64 model of the same table "
              "(max %.4f), %d against a lossless table\n",
              caseName(c).c_str(), out.lookups, kBound, out.overFloat, out.overModel, out.maxModel, out.overLossless);
  return out;
}

} // namespace
} // namespace moment_precision_test
using namespace moment_precision_test;

TEST(MomentModel, GlTableAndLookupsMatchTheFp64Model) {
  for (const char* technique : {"vssm", "msm"})
    for (const char* scene : {"contact", "stacked"})
      for (bool centred : {false, true}) {
        if (centred && std::string(technique) != "msm") continue;
        const Outcome narrow = check({technique, scene, 32, centred});
        const Outcome wide = check({technique, scene, 64, centred});
        const std::string what = std::string(technique) + " on " + scene + (centred ? ", centred" : "");
        for (const Outcome& o : {narrow, wide}) {
          if (std::string(technique) == "vssm" || centred) {
            EXPECT_EQ(o.overFloat, 0) << what; // the model emulates the shader
          } else if (testContext().info().software) {
            // The uncentred 4MSM in float amplifies last-bit differences (the finding below), and
            // GLSL lets a compiler fuse multiply-adds (the 64-bit table's high * 2^32 + low) and
            // divide to 2.5 ulp: the float model is llvmpipe's arithmetic exactly, not a GPU's. On
            // an NVIDIA H200, 16-18 of 6144 lookups (32-bit table) and 1093-1487 (64-bit) leave the
            // float model by more than kBound, as many as leave the fp64 model: docs/testing.md,
            // "Skip conditions"; docs/performance.md, "Issue 20: a GPU in the loop".
            EXPECT_EQ(o.overFloat, 0) << what;
          }
          if (std::string(technique) == "vssm" || centred) {
            // Float arithmetic after an exact table is good to kBound (measured: at most 1 lookup
            // over it, by 0.0132; techniques/msm/README.md, "Precision").
            EXPECT_LE(o.overModel, kMaxOver) << what;
            EXPECT_LT(o.maxModel, 0.02) << what;
          } else {
            // The plain 4MSM in float departs on a sixth of the lookups or more (1104-1511 of 6144):
            // the finding msm.centred fixes.
            EXPECT_GT(o.overModel, o.lookups / 6) << what;
          }
        }
        // The 64-bit table is at least as close to the lossless one as the 32-bit table, and with
        // vssm or centred msm it is the lossless one to kBound.
        EXPECT_LE(wide.overLossless, narrow.overLossless) << what;
        if (std::string(technique) == "vssm" || centred) {
          EXPECT_EQ(wide.overLossless, 0) << what;
        }
      }
}
