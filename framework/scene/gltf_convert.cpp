// glTF materials, textures and mesh primitives -> rtlab Scene (after validateModel).
#include "scene/gltf_internal.h"

#include "scene/mesh_builder.h"

#include <cmath>
#include <map>
#include <numeric>

namespace rtlab::gltf {
namespace {

// Scene textures, one per (image, colour space) pair actually used.
class TextureTable {
public:
  TextureTable(const tinygltf::Model& model, Scene& scene, const std::string& file)
      : m_model(model), m_scene(scene), m_file(file) {}

  int get(const tinygltf::TextureInfo& info, bool srgb, const std::string& who) {
    return get(info.index, info.texCoord, srgb, who);
  }

  int get(int texture, int texCoord, bool srgb, const std::string& who) {
    if (texture < 0) return -1;
    if (texCoord != 0) warn(m_file, who + " uses TEXCOORD_" + std::to_string(texCoord) + "; rtlab reads TEXCOORD_0");
    const int image = m_model.textures[static_cast<size_t>(texture)].source;
    if (image < 0) {
      warn(m_file, "texture " + std::to_string(texture) + " has no image rtlab can read; ignored");
      return -1;
    }
    auto key = std::make_pair(image, srgb);
    auto it = m_index.find(key);
    if (it != m_index.end()) return it->second;
    const tinygltf::Image& img = m_model.images[static_cast<size_t>(image)];
    const std::string label = img.uri.empty() || img.uri.rfind("data:", 0) == 0 ? "" : " ('" + img.uri + "')";
    if (img.image.empty() || img.width <= 0 || img.height <= 0 || img.component != 4 || img.bits != 8 ||
        img.image.size() != static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 4)
      fail(m_file, "image " + std::to_string(image) + label + " could not be loaded");
    TextureImage t;
    t.name = !img.name.empty() ? img.name : !label.empty() ? img.uri : "image" + std::to_string(image);
    t.width = img.width;
    t.height = img.height;
    t.rgba8 = img.image;
    t.srgb = srgb;
    m_scene.textures.push_back(std::move(t));
    const int index = static_cast<int>(m_scene.textures.size()) - 1;
    m_index.emplace(key, index);
    return index;
  }

private:
  const tinygltf::Model& m_model;
  Scene& m_scene;
  const std::string& m_file;
  std::map<std::pair<int, bool>, int> m_index;
};

float emissiveStrength(const tinygltf::Material& mat, const std::string& who, const std::string& file) {
  auto it = mat.extensions.find("KHR_materials_emissive_strength");
  if (it == mat.extensions.end() || !it->second.IsObject() || !it->second.Has("emissiveStrength"))
    return 1.0f;
  const auto& v = it->second.Get("emissiveStrength");
  const double s = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
  if (!(s >= 0.0) || !std::isfinite(s)) fail(file, who + " has an invalid emissiveStrength");
  return static_cast<float>(s);
}

bool allFinite(const float* p, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(p[i])) return false;
  return true;
}

template <typename V>
void requireFinite(const std::vector<V>& v, const std::string& who, const std::string& file) {
  if (!v.empty() && !allFinite(&v[0][0], v.size() * V::length()))
    fail(file, who + " contains a non-finite value");
}

// Strips and fans to lists; drops degenerate strip/fan triangles (repeated indices).
std::vector<std::uint32_t> triangleList(const std::vector<std::uint32_t>& idx, int mode,
                                        const std::string& who, const std::string& file) {
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    if (idx.size() % 3 != 0)
      fail(file, who + " has " + std::to_string(idx.size()) + " indices, not a multiple of 3");
    return idx;
  }
  std::vector<std::uint32_t> out;
  for (size_t i = 0; i + 2 < idx.size(); ++i) {
    std::uint32_t a, b, c = idx[i + 2];
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      a = idx[0];
      b = idx[i + 1];
    } else {
      a = idx[i + (i % 2)];     // odd strip triangles swap their first two corners
      b = idx[i + 1 - (i % 2)];
    }
    if (a != b && b != c && a != c) out.insert(out.end(), {a, b, c});
  }
  return out;
}

} // namespace

void convertMaterials(const tinygltf::Model& model, Scene& scene, const std::string& file) {
  TextureTable textures(model, scene, file);
  for (size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& src = model.materials[i];
    const auto& pbr = src.pbrMetallicRoughness;
    const std::string who = "material " + std::to_string(i);
    Material m;
    m.name = src.name.empty() ? "material" + std::to_string(i) : src.name;
    for (int c = 0; c < 4; ++c) m.baseColor[c] = static_cast<float>(pbr.baseColorFactor[static_cast<size_t>(c)]);
    m.metallic = static_cast<float>(pbr.metallicFactor);
    m.roughness = static_cast<float>(pbr.roughnessFactor);
    const float strength = emissiveStrength(src, who, file);
    for (int c = 0; c < 3; ++c)
      m.emissive[c] = strength * static_cast<float>(src.emissiveFactor[static_cast<size_t>(c)]);
    m.normalScale = static_cast<float>(src.normalTexture.scale);
    m.occlusionStrength = static_cast<float>(src.occlusionTexture.strength);
    m.alphaMode = src.alphaMode == "BLEND" ? AlphaMode::Blend
                  : src.alphaMode == "MASK" ? AlphaMode::Mask
                                            : AlphaMode::Opaque;
    m.alphaCutoff = static_cast<float>(src.alphaCutoff);
    m.doubleSided = src.doubleSided;
    m.baseColorTexture = textures.get(pbr.baseColorTexture, true, who + " baseColorTexture");
    m.emissiveTexture = textures.get(src.emissiveTexture, true, who + " emissiveTexture");
    m.metallicRoughnessTexture = textures.get(pbr.metallicRoughnessTexture, false, who + " metallicRoughnessTexture");
    m.normalTexture = textures.get(src.normalTexture.index, src.normalTexture.texCoord, false, who + " normalTexture");
    m.occlusionTexture = textures.get(src.occlusionTexture.index, src.occlusionTexture.texCoord, false,
                                      who + " occlusionTexture");
    scene.materials.push_back(std::move(m));
  }
}

std::vector<std::vector<int>> convertMeshes(const tinygltf::Model& model, Scene& scene,
                                            const std::string& file) {
  std::vector<std::vector<int>> map(model.meshes.size());
  for (size_t mi = 0; mi < model.meshes.size(); ++mi) {
    const tinygltf::Mesh& mesh = model.meshes[mi];
    const std::string baseName = mesh.name.empty() ? "mesh" + std::to_string(mi) : mesh.name;
    for (size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
      const tinygltf::Primitive& prim = mesh.primitives[pi];
      const std::string who = "mesh " + std::to_string(mi) + " primitive " + std::to_string(pi);
      const int mode = prim.mode == -1 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
      if (mode < TINYGLTF_MODE_TRIANGLES) {
        warn(file, who + " draws points or lines (mode " + std::to_string(mode) + "); skipped");
        continue;
      }
      auto attr = [&](const char* name) {
        auto it = prim.attributes.find(name);
        return it == prim.attributes.end() ? -1 : it->second;
      };
      const std::vector<glm::vec3> positions = readVec3(model, attr("POSITION"));
      requireFinite(positions, who + " POSITION", file);
      const size_t n = positions.size();
      std::vector<std::uint32_t> idx;
      if (prim.indices >= 0) {
        idx = readIndices(model, prim.indices);
        for (size_t k = 0; k < idx.size(); ++k)
          if (idx[k] >= n)
            fail(file, who + " index " + std::to_string(idx[k]) + " (element " + std::to_string(k) +
                           " of accessor " + std::to_string(prim.indices) + ") is out of range: " +
                           std::to_string(n) + " vertices");
      } else {
        idx.resize(n);
        std::iota(idx.begin(), idx.end(), 0u);
      }
      Mesh out;
      out.name = mesh.primitives.size() > 1 ? baseName + "_" + std::to_string(pi) : baseName;
      out.material = prim.material;
      out.indices = triangleList(idx, mode, who, file);
      if (out.indices.empty()) {
        warn(file, who + " has no triangles; skipped");
        continue;
      }
      out.vertices.resize(n);
      for (size_t k = 0; k < n; ++k) out.vertices[k].position = positions[k];
      const int normals = attr("NORMAL"), tangents = attr("TANGENT"), uvs = attr("TEXCOORD_0");
      if (uvs >= 0) {
        auto v = readVec2(model, uvs);
        requireFinite(v, who + " TEXCOORD_0", file);
        for (size_t k = 0; k < n; ++k) out.vertices[k].uv = v[k];
      }
      if (normals >= 0) {
        auto v = readVec3(model, normals);
        requireFinite(v, who + " NORMAL", file);
        for (size_t k = 0; k < n; ++k) out.vertices[k].normal = v[k];
      }
      if (tangents >= 0) {
        auto v = readVec4(model, tangents);
        requireFinite(v, who + " TANGENT", file);
        for (size_t k = 0; k < n; ++k) out.vertices[k].tangent = v[k];
      }
      if (normals < 0) generateFlatNormals(out);
      const bool normalMapped = prim.material >= 0 &&
                                model.materials[static_cast<size_t>(prim.material)].normalTexture.index >= 0;
      if (normalMapped && tangents < 0) generateTangents(out);
      if (int fixedCount = normalizeFrames(out); fixedCount > 0)
        warn(file, who + ": " + std::to_string(fixedCount) + " zero-length normals replaced by +y");
      computeBounds(out);
      scene.meshes.push_back(std::move(out));
      map[mi].push_back(static_cast<int>(scene.meshes.size()) - 1);
    }
  }
  return map;
}

} // namespace rtlab::gltf
