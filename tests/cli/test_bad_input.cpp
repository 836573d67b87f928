// Bad input through the real binary: each case gives the documented exit code, exactly one line
// on stderr beginning "rtlab: error:", no crash, no hang, and no output file.
#include "process.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using rtlab::test::runProcess;

namespace {

std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 | (unsigned char)bytes[i + 2];
    out += {k[v >> 18], k[(v >> 12) & 63], k[(v >> 6) & 63], k[v & 63]};
  }
  if (i + 1 == bytes.size()) {
    unsigned v = (unsigned char)bytes[i] << 16;
    out += {k[v >> 18], k[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8;
    out += {k[v >> 18], k[(v >> 12) & 63], k[(v >> 6) & 63], '='};
  }
  return out;
}

// A valid one-triangle glTF: positions (3 x VEC3 float, 36 bytes) then uint16 indices (6 bytes).
nlohmann::json triangleGltf() {
  std::string bin(44, '\0');
  const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const unsigned short idx[3] = {0, 1, 2};
  std::memcpy(bin.data(), pos, 36);
  std::memcpy(bin.data() + 36, idx, 6);
  nlohmann::json j;
  j["asset"] = {{"version", "2.0"}};
  j["buffers"] = {{{"byteLength", 44}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
  j["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                      {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}};
  j["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                     {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                    {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}};
  j["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}};
  j["nodes"] = {{{"mesh", 0}}};
  j["scenes"] = {{{"nodes", {0}}}};
  j["scene"] = 0;
  return j;
}

class BadInput : public ::testing::Test {
protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = fs::path(RTLAB_TEST_TMP) / "cli" / info->name();
    fs::remove_all(m_dir);
    fs::create_directories(m_dir / "out");
  }
  std::string path(const std::string& name) const { return (m_dir / name).string(); }
  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(path(name), std::ios::binary) << content;
    return path(name);
  }
  std::string writeJson(const std::string& name, const nlohmann::json& j) const { return write(name, j.dump()); }

  // Runs `rtlab render ... --out <dir>/out/x.png` and checks the contract for a failure.
  void expectFailure(const std::vector<std::string>& testArgs, int code, const std::string& mention = "") {
    // Defaults first: for options given twice the last wins, so the test's own values count.
    std::vector<std::string> args = {"render", "--size", "32x32", "--out", (m_dir / "out" / "x.png").string()};
    args.insert(args.end(), testArgs.begin(), testArgs.end());
    const auto r = runProcess(RTLAB_BINARY, args, 60);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, code) << r.err;
    EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("rtlab: error:", 0), 0u) << r.err;
    if (!mention.empty()) {
      EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
    }
    EXPECT_TRUE(fs::is_empty(m_dir / "out")) << "output left behind";
  }

  fs::path m_dir;
};

TEST_F(BadInput, MissingSceneFile) { expectFailure({"--scene", path("nope.gltf")}, 3, "nope.gltf"); }
TEST_F(BadInput, EmptySceneFile) { expectFailure({"--scene", write("empty.gltf", "")}, 3, "empty.gltf"); }
TEST_F(BadInput, TruncatedGltf) {
  const std::string text = triangleGltf().dump();
  expectFailure({"--scene", write("trunc.gltf", text.substr(0, text.size() / 2))}, 3, "trunc.gltf");
}
TEST_F(BadInput, NonJsonGltf) { expectFailure({"--scene", write("text.gltf", "this is not json")}, 3, "text.gltf"); }
TEST_F(BadInput, BufferShorterThanByteLength) {
  auto j = triangleGltf();
  j["buffers"][0]["byteLength"] = 400;
  expectFailure({"--scene", writeJson("short.gltf", j)}, 3, "short.gltf");
}
TEST_F(BadInput, AccessorCountPastBuffer) {
  auto j = triangleGltf();
  j["accessors"][0]["count"] = 30;
  expectFailure({"--scene", writeJson("count.gltf", j)}, 3, "count.gltf");
}
TEST_F(BadInput, NodeCycle) {
  auto j = triangleGltf();
  j["nodes"] = {{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}};
  expectFailure({"--scene", writeJson("cycle.gltf", j)}, 3, "cycle.gltf");
}
TEST_F(BadInput, IndexValueOutOfRange) {
  auto j = triangleGltf();
  std::string bin(44, '\0');
  const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const unsigned short idx[3] = {0, 1, 7};
  std::memcpy(bin.data(), pos, 36);
  std::memcpy(bin.data() + 36, idx, 6);
  j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin);
  expectFailure({"--scene", writeJson("index.gltf", j)}, 3, "index.gltf");
}
TEST_F(BadInput, MaterialReferenceOutOfRange) {
  auto j = triangleGltf();
  j["meshes"][0]["primitives"][0]["material"] = 5;
  expectFailure({"--scene", writeJson("material.gltf", j)}, 3, "material.gltf");
}
TEST_F(BadInput, TextureReferenceOutOfRange) {
  auto j = triangleGltf();
  j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 3}}}}}}};
  j["meshes"][0]["primitives"][0]["material"] = 0;
  expectFailure({"--scene", writeJson("texture.gltf", j)}, 3, "texture.gltf");
}
TEST_F(BadInput, GlbBadMagic) {
  std::string glb("XXXX\x02\0\0\0\x20\0\0\0", 12);
  glb.append(20, ' '); // appended rather than concatenated: GCC 12 at -O2 warns (-Warray-bounds) on string&& + string&&
  expectFailure({"--scene", write("bad.glb", glb)}, 3, "bad.glb");
}
TEST_F(BadInput, UnknownTechnique) { expectFailure({"-t", "no_such_technique"}, 2, "no_such_technique"); }
TEST_F(BadInput, UnknownKey) { expectFailure({"--set", "shadow.no_such_key=1"}, 2, "shadow.no_such_key"); }
TEST_F(BadInput, OutOfRangeValue) { expectFailure({"--set", "shadow.resolution=100000"}, 2, "shadow.resolution"); }
TEST_F(BadInput, BadValueSyntax) { expectFailure({"--set", "shadow.constant_bias=abc"}, 2, "shadow.constant_bias"); }
TEST_F(BadInput, KeyOfWrongLightType) { expectFailure({"--scene", "stacked", "--set", "light0.radius=1"}, 2, "light0.radius"); }
TEST_F(BadInput, BadSize) { expectFailure({"--size", "0x10"}, 2, "0x10"); }
TEST_F(BadInput, BadSizeSyntax) { expectFailure({"--size", "wide"}, 2, "wide"); }
TEST_F(BadInput, UnknownSceneName) { expectFailure({"--scene", "no_such_scene"}, 2, "no_such_scene"); }
TEST_F(BadInput, UnknownAov) { expectFailure({"--aov", "no_such_aov"}, 2, "no_such_aov"); }
// A scene with a rectangular light and no arealight technique holds no arealight value (the lighting's
// point approximation is in the colour): a usage error naming the stage, not a silent 0 (docs/stages.md).
TEST_F(BadInput, ArealightAovWithoutItsTechnique) {
  expectFailure({"--scene", "arealight", "--aov", "arealight", "--out", path("out/x.exr")}, 2, "arealight technique");
}
TEST_F(BadInput, UnknownOption) { expectFailure({"--no-such-option"}, 2, "--no-such-option"); }
TEST_F(BadInput, MissingPreset) { expectFailure({"--preset", path("none.json")}, 3, "none.json"); }
TEST_F(BadInput, UnreadablePreset) {
  fs::create_directories(path("dir.json"));
  expectFailure({"--preset", path("dir.json")}, 3, "dir.json");
}
TEST_F(BadInput, MalformedPreset) { expectFailure({"--preset", write("bad.json", "{\"schema\": 1, ")}, 3, "bad.json"); }
TEST_F(BadInput, PresetWithUnknownKey) {
  expectFailure({"--preset", write("key.json", R"({"schema": 1, "params": {"nope.key": 1}})")}, 2, "nope.key");
}
TEST_F(BadInput, UnwritableOutput) {
  expectFailure({"--out", path("missing_dir/x.png")}, 6, "missing_dir");
}
TEST_F(BadInput, UnsupportedOutputFormat) { expectFailure({"--out", path("out/x.bmp")}, 2, "x.bmp"); }

TEST(Cli, VersionAndHelp) {
  auto r = runProcess(RTLAB_BINARY, {"--version"});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.out.rfind("rtlab ", 0), 0u);
  for (const char* cmd : {"list", "render", "view"}) {
    r = runProcess(RTLAB_BINARY, {cmd, "--help"});
    EXPECT_EQ(r.exitCode, 0) << cmd;
    EXPECT_NE(r.out.find("Usage: rtlab"), std::string::npos) << cmd;
  }
  r = runProcess(RTLAB_BINARY, {"frobnicate"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err.rfind("rtlab: error:", 0), 0u);
}

TEST(Cli, ViewWithoutDisplayExits4) {
  // The window path needs a display; without one it is exit 4 with one line.
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((display && *display) || (wayland && *wayland)) {
    unsetenv("DISPLAY");
    unsetenv("WAYLAND_DISPLAY");
  }
  const auto r = runProcess(RTLAB_BINARY, {"view", "--size", "32x32"});
  EXPECT_EQ(r.exitCode, 4) << r.err;
  EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
}

} // namespace
