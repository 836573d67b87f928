// Malformed glTF input: every case must throw Error(Input) with a one-line message naming the
// file (and never crash or read out of bounds; run under RTLAB_SANITIZE to check the latter).
#include "scene/gltf_loader.h"
#include "scene/load.h"
#include "test_scene_gltf_writer.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

namespace rtlab {
namespace {

using test::GltfWriter;
using Json = nlohmann::json;

std::string dir() { return test::sceneTmpDir("bad"); }

// Loads path, expects Error(Input) naming the file and containing `fragment`.
void expectInputError(const std::string& path, const std::string& fragment) {
  try {
    loadScene(path);
    ADD_FAILURE() << path << ": loaded, expected an error containing '" << fragment << "'";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_EQ(e.code(), ExitCode::Input) << msg;
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_LT(msg.size(), 400u) << msg;
  }
}

std::string writeText(const std::string& name, const std::string& text) {
  std::string path = dir() + "/" + name;
  GltfWriter::writeBytes(path, std::vector<std::uint8_t>(text.begin(), text.end()));
  return path;
}

// A valid one-quad file, modified by `edit` before writing.
std::string quadFile(const std::string& name, const std::function<void(GltfWriter&)>& edit,
                     GltfWriter::Mode mode = GltfWriter::Mode::Embedded) {
  GltfWriter w;
  w.push("materials", Json{{"name", "m"}});
  int mesh = w.addQuadMesh("quad", true, true, 0);
  w.setScene({w.addNode({{"mesh", mesh}})});
  edit(w);
  return w.write(dir(), name, mode);
}

TEST(SceneGltfErrors, MissingFile) {
  const std::string path = dir() + "/does_not_exist.gltf";
  expectInputError(path, "No such file or directory");
  try {
    loadGltf(path);
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read scene '" + path + "': No such file or directory");
  }
}

TEST(SceneGltfErrors, EmptyTruncatedAndNonJsonFiles) {
  expectInputError(writeText("empty.gltf", ""), "empty");
  const std::string valid = quadFile("whole", [](GltfWriter&) {});
  std::ifstream in(valid);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  expectInputError(writeText("truncated.gltf", text.substr(0, text.size() / 2)), "not a valid glTF file");
  expectInputError(writeText("prose.gltf", "this is not JSON at all"), "not a valid glTF file");
  expectInputError(writeText("array.gltf", "[1, 2, 3]"), "not a valid glTF file");
}

TEST(SceneGltfErrors, BinaryFiles) {
  expectInputError(writeText("magic.glb", "glTX0000000000000000000000000000"), "bad magic");
  expectInputError(writeText("short.glb", "glTF"), "not a valid binary glTF file");
  const std::string glb = quadFile("whole_glb", [](GltfWriter&) {}, GltfWriter::Mode::Glb);
  std::ifstream in(glb, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  expectInputError(writeText("cut.glb", bytes.substr(0, bytes.size() - 10)), "not a valid binary glTF file");
}

TEST(SceneGltfErrors, BufferShorterThanByteLength) {
  // Embedded: the data URI decodes to fewer bytes than byteLength.
  GltfWriter w;
  int mesh = w.addQuadMesh("quad", true, false);
  w.setScene({w.addNode({{"mesh", mesh}})});
  std::string path = w.write(dir(), "short_embedded", GltfWriter::Mode::Embedded);
  std::ifstream in(path);
  Json doc = Json::parse(in);
  doc["buffers"][0]["byteLength"] = doc["buffers"][0]["byteLength"].get<size_t>() + 16;
  expectInputError(writeText("short_embedded.gltf", doc.dump()), "buffer");
  // External: the .bin file is shorter than byteLength.
  path = w.write(dir(), "short_external", GltfWriter::Mode::External);
  std::vector<std::uint8_t> half(w.bin.begin(), w.bin.begin() + static_cast<long>(w.bin.size() / 2));
  GltfWriter::writeBytes(dir() + "/short_external.bin", half);
  expectInputError(path, "size mismatch");
  // External: the .bin file is missing.
  std::filesystem::remove(dir() + "/short_external.bin");
  expectInputError(path, "not found");
}

TEST(SceneGltfErrors, AccessorAndBufferViewBounds) {
  expectInputError(quadFile("count", [](GltfWriter& w) { w.doc["accessors"][0]["count"] = 5; }),
                   "accessor 0 reads past the end of bufferView 0");
  expectInputError(quadFile("offset", [](GltfWriter& w) { w.doc["accessors"][1]["byteOffset"] = 8; }),
                   "accessor 1 reads past the end of bufferView 1");
  expectInputError(quadFile("huge", [](GltfWriter& w) { w.doc["accessors"][0]["count"] = 4611686018427387904ull; }),
                   "accessor 0");
  expectInputError(quadFile("view", [](GltfWriter& w) { w.doc["bufferViews"][2]["byteLength"] = 4096; }),
                   "bufferView 2");
  expectInputError(quadFile("viewbuf", [](GltfWriter& w) { w.doc["bufferViews"][0]["buffer"] = 3; }),
                   "bufferView 0 refers to buffer 3");
  expectInputError(quadFile("stride", [](GltfWriter& w) { w.doc["bufferViews"][0]["byteStride"] = 4; }),
                   "byteStride");
  expectInputError(quadFile("badacc", [](GltfWriter& w) { w.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 42; }),
                   "accessor 42");
}

TEST(SceneGltfErrors, AttributeTypes) {
  expectInputError(quadFile("postype", [](GltfWriter& w) { w.doc["accessors"][0]["type"] = "VEC2"; }),
                   "POSITION");
  expectInputError(quadFile("idxtype", [](GltfWriter& w) { w.doc["accessors"][3]["componentType"] = 5120; }),
                   "indices");
  expectInputError(quadFile("nopos", [](GltfWriter& w) { w.doc["meshes"][0]["primitives"][0]["attributes"].erase("POSITION"); }),
                   "no POSITION");
  expectInputError(quadFile("uvcount", [](GltfWriter& w) { w.doc["accessors"][2]["count"] = 3; }),
                   "different count");
  expectInputError(quadFile("nfinite", [](GltfWriter& w) { w.doc["nodes"][0]["scale"] = {1, 1}; }), "scale");
}

TEST(SceneGltfErrors, IndexOutOfVertexRange) {
  GltfWriter w;
  int pos = w.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  w.push("meshes", {{"primitives", {{{"attributes", {{"POSITION", pos}}}, {"indices", w.addIndices({0, 1, 3})}}}}});
  w.setScene({w.addNode({{"mesh", 0}})});
  expectInputError(w.write(dir(), "index", GltfWriter::Mode::Embedded), "index 3");
}

TEST(SceneGltfErrors, ReferencesOutOfRange) {
  expectInputError(quadFile("material", [](GltfWriter& w) { w.doc["meshes"][0]["primitives"][0]["material"] = 7; }),
                   "refers to material 7");
  expectInputError(quadFile("texture", [](GltfWriter& w) {
                     w.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 2}}}};
                   }),
                   "refers to texture 2");
  expectInputError(quadFile("image", [](GltfWriter& w) { w.push("textures", {{"source", 4}}); }), "refers to image 4");
  expectInputError(quadFile("mesh", [](GltfWriter& w) { w.doc["nodes"][0]["mesh"] = 9; }), "refers to mesh 9");
  expectInputError(quadFile("child", [](GltfWriter& w) { w.doc["nodes"][0]["children"] = {5}; }),
                   "refers to child node 5");
  expectInputError(quadFile("root", [](GltfWriter& w) { w.doc["scenes"][0]["nodes"] = {3}; }), "refers to node 3");
  expectInputError(quadFile("defscene", [](GltfWriter& w) { w.doc["scene"] = 2; }), "scene 2");
  expectInputError(quadFile("camera", [](GltfWriter& w) { w.doc["nodes"][0]["camera"] = 0; }), "refers to camera 0");
  expectInputError(quadFile("light", [](GltfWriter& w) {
                     w.doc["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 1}}}};
                   }),
                   "refers to light 1");
  expectInputError(quadFile("imgview", [](GltfWriter& w) {
                     w.push("images", {{"bufferView", 0}, {"mimeType", "image/png"}});
                     w.doc["bufferViews"][0]["byteLength"] = 100000;
                   }),
                   "bufferView 0");
}

TEST(SceneGltfErrors, NodeCycles) {
  expectInputError(quadFile("selfchild", [](GltfWriter& w) { w.doc["nodes"][0]["children"] = {0}; }), "own child");
  expectInputError(quadFile("loop", [](GltfWriter& w) {
                     w.addNode({{"children", {2}}});
                     w.addNode({{"children", {1}}});
                   }),
                   "cycle");
  expectInputError(quadFile("rootloop", [](GltfWriter& w) {
                     w.addNode({{"children", {0}}}); // node 1 -> root node 0 -> node 1
                     w.doc["nodes"][0]["children"] = {1};
                   }),
                   "node");
  expectInputError(quadFile("twoparents", [](GltfWriter& w) {
                     w.addNode({{"children", {0}}});
                     w.addNode({{"children", {0}}});
                     w.doc["scenes"][0]["nodes"] = {1, 2};
                   }),
                   "reached twice");
  expectInputError(quadFile("duproot", [](GltfWriter& w) { w.doc["scenes"][0]["nodes"] = {0, 0}; }), "twice");
}

TEST(SceneGltfErrors, LightsAndExtras) {
  auto withLight = [](const Json& light) {
    return [light](GltfWriter& w) {
      w.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {light}}}}};
      w.doc["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
    };
  };
  expectInputError(quadFile("lighttype", withLight({{"type", "laser"}})), "invalid type");
  expectInputError(quadFile("cone", withLight({{"type", "spot"}, {"spot", {{"innerConeAngle", 1.0}, {"outerConeAngle", 0.5}}}})),
                   "ConeAngle");
  expectInputError(quadFile("radius", withLight({{"type", "point"}, {"extras", {{"radius", "big"}}}})), "radius");
  expectInputError(quadFile("area", [](GltfWriter& w) {
                     w.doc["nodes"][0]["extras"] = {{"rtlab_area_light", {{"width", -1}, {"height", 1}}}};
                   }),
                   "rtlab_area_light.width");
  for (const Json& bad : {Json("bright"), Json({0.1, 0.1}), Json({0.1, -0.1, 0.1}), Json({0.1, 0.1, 1000.0})})
    expectInputError(quadFile("ambient", [&](GltfWriter& w) { w.doc["scenes"][0]["extras"] = {{"ambient", bad}}; }),
                     "extras.ambient must be 3 numbers in [0, 100]");
}

TEST(SceneGltfErrors, NoTriangles) {
  GltfWriter w;
  w.setScene({w.addNode({{"name", "empty"}})});
  expectInputError(w.write(dir(), "nothing", GltfWriter::Mode::Embedded), "no triangle meshes");
}

// Truncations and byte corruptions of valid files: each either loads or fails with Error(Input).
TEST(SceneGltfErrors, CorruptedFilesNeverCrash) {
  std::mt19937 rng(12345);
  for (GltfWriter::Mode mode : {GltfWriter::Mode::Embedded, GltfWriter::Mode::Glb}) {
    const std::string path = quadFile("fuzz_src", [](GltfWriter&) {}, mode);
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string target = dir() + (mode == GltfWriter::Mode::Glb ? "/fuzz.glb" : "/fuzz.gltf");
    for (int iter = 0; iter < 300; ++iter) {
      std::string b = bytes;
      if (iter % 3 == 0) {
        b.resize(rng() % b.size());
      } else {
        for (int k = 0; k < 1 + iter % 4; ++k) b[rng() % b.size()] = static_cast<char>(rng() % 256);
      }
      GltfWriter::writeBytes(target, std::vector<std::uint8_t>(b.begin(), b.end()));
      try {
        loadScene(target);
      } catch (const Error& e) {
        ASSERT_EQ(e.code(), ExitCode::Input) << e.what();
      }
    }
  }
}

} // namespace
} // namespace rtlab
