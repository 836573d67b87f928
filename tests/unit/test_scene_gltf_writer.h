// Test helper: builds small glTF files (embedded base64, external .bin, or .glb) with
// nlohmann::json, so the loader tests need no checked-in assets.
#pragma once
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rtlab::test {

inline std::string base64(const std::vector<std::uint8_t>& in) {
  static const char* kTable = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < in.size(); i += 3) {
    std::uint32_t v = static_cast<std::uint32_t>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<std::uint32_t>(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= in[i + 2];
    out += kTable[(v >> 18) & 63];
    out += kTable[(v >> 12) & 63];
    out += i + 1 < in.size() ? kTable[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? kTable[v & 63] : '=';
  }
  return out;
}

// A w x h 24-bit BMP (stb_image decodes it), every pixel the given colour.
inline std::vector<std::uint8_t> solidBmp(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  const int rowBytes = (w * 3 + 3) & ~3;
  const std::uint32_t dataSize = static_cast<std::uint32_t>(rowBytes * h);
  std::vector<std::uint8_t> f(54 + dataSize, 0);
  auto put32 = [&](size_t at, std::uint32_t v) { for (int k = 0; k < 4; ++k) f[at + k] = static_cast<std::uint8_t>(v >> (8 * k)); };
  f[0] = 'B';
  f[1] = 'M';
  put32(2, static_cast<std::uint32_t>(f.size()));
  put32(10, 54);
  put32(14, 40);
  put32(18, static_cast<std::uint32_t>(w));
  put32(22, static_cast<std::uint32_t>(h));
  f[26] = 1;
  f[28] = 24;
  put32(34, dataSize);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      size_t p = 54 + static_cast<size_t>(y * rowBytes + x * 3);
      f[p] = b;
      f[p + 1] = g;
      f[p + 2] = r;
    }
  return f;
}

class GltfWriter {
public:
  enum class Mode { Embedded, External, Glb };

  nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
  std::vector<std::uint8_t> bin;

  // Appends bytes (4-byte aligned) as a new buffer view of buffer 0.
  int addView(const void* data, size_t bytes, size_t stride = 0) {
    while (bin.size() % 4) bin.push_back(0);
    nlohmann::json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
    if (stride) view["byteStride"] = stride;
    const auto* p = static_cast<const std::uint8_t*>(data);
    bin.insert(bin.end(), p, p + bytes);
    return push("bufferViews", view);
  }
  int addAccessor(int view, int componentType, const std::string& type, size_t count, size_t offset = 0,
                  bool normalized = false) {
    nlohmann::json a = {{"bufferView", view}, {"componentType", componentType}, {"type", type},
                        {"count", count}, {"byteOffset", offset}};
    if (normalized) a["normalized"] = true;
    return push("accessors", a);
  }
  int addFloats(const std::vector<float>& v, const std::string& type, size_t perElement) {
    int view = addView(v.data(), v.size() * 4);
    return addAccessor(view, 5126, type, v.size() / perElement);
  }
  int addIndices(const std::vector<std::uint16_t>& v) {
    int view = addView(v.data(), v.size() * 2);
    return addAccessor(view, 5123, "SCALAR", v.size());
  }
  // A unit quad in the xy plane facing +z (two triangles), optionally with normals and UVs.
  int addQuadMesh(const std::string& name, bool normals, bool uvs, int material = -1) {
    nlohmann::json attrs = {{"POSITION", addFloats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3)}};
    if (normals) attrs["NORMAL"] = addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    if (uvs) attrs["TEXCOORD_0"] = addFloats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
    nlohmann::json prim = {{"attributes", attrs}, {"indices", addIndices({0, 1, 2, 0, 2, 3})}};
    if (material >= 0) prim["material"] = material;
    return push("meshes", {{"name", name}, {"primitives", {prim}}});
  }
  int addNode(const nlohmann::json& node) { return push("nodes", node); }
  int push(const std::string& key, const nlohmann::json& value) {
    if (!doc.contains(key)) doc[key] = nlohmann::json::array();
    doc[key].push_back(value);
    return static_cast<int>(doc[key].size()) - 1;
  }
  void setScene(const std::vector<int>& roots) {
    doc["scenes"] = nlohmann::json::array({{{"nodes", roots}}});
    doc["scene"] = 0;
  }

  // Writes dir/name(.gltf|.glb) (and name.bin for External); returns the scene path.
  std::string write(const std::string& dir, const std::string& name, Mode mode) {
    std::filesystem::create_directories(dir);
    nlohmann::json d = doc;
    while (bin.size() % 4) bin.push_back(0);
    if (!bin.empty()) {
      nlohmann::json buffer = {{"byteLength", bin.size()}};
      if (mode == Mode::Embedded) buffer["uri"] = "data:application/octet-stream;base64," + base64(bin);
      if (mode == Mode::External) {
        buffer["uri"] = name + ".bin";
        writeBytes(dir + "/" + name + ".bin", bin);
      }
      d["buffers"] = nlohmann::json::array({buffer});
    }
    if (mode != Mode::Glb) {
      std::string path = dir + "/" + name + ".gltf";
      std::string text = d.dump();
      writeBytes(path, std::vector<std::uint8_t>(text.begin(), text.end()));
      return path;
    }
    std::string path = dir + "/" + name + ".glb";
    writeBytes(path, glb(d.dump(), bin));
    return path;
  }

  static std::vector<std::uint8_t> glb(std::string json, const std::vector<std::uint8_t>& binChunk) {
    while (json.size() % 4) json += ' ';
    std::vector<std::uint8_t> out;
    out.reserve(28 + json.size() + binChunk.size());
    auto put32 = [&](std::uint32_t v) { for (int k = 0; k < 4; ++k) out.push_back(static_cast<std::uint8_t>(v >> (8 * k))); };
    const size_t total = 12 + 8 + json.size() + (binChunk.empty() ? 0 : 8 + binChunk.size());
    put32(0x46546C67); // "glTF"
    put32(2);
    put32(static_cast<std::uint32_t>(total));
    put32(static_cast<std::uint32_t>(json.size()));
    put32(0x4E4F534A);
    out.insert(out.end(), json.begin(), json.end());
    if (!binChunk.empty()) {
      put32(static_cast<std::uint32_t>(binChunk.size()));
      put32(0x004E4942);
      out.insert(out.end(), binChunk.begin(), binChunk.end());
    }
    return out;
  }

  static void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
};

inline std::string sceneTmpDir(const std::string& sub) {
  std::string dir = std::string(RTLAB_TEST_TMP) + "/scene/" + sub;
  std::filesystem::create_directories(dir);
  return dir;
}

} // namespace rtlab::test
