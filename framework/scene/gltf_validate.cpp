// glTF validation: tinygltf 2.7 parses but does not check accessor bounds, index and texture
// references or the node hierarchy, so everything rtlab later dereferences is checked here.
#include "scene/gltf_internal.h"
#include "scene/scene_params.h"
#include "util/number_format.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace rtlab::gltf {
namespace {

using Model = tinygltf::Model;
std::string str(size_t i) { return std::to_string(i); }

class Validator {
public:
  Validator(const Model& model, const std::string& file) : m(model), m_file(file) {}

  void run() {
    bufferViews();
    for (size_t i = 0; i < m.accessors.size(); ++i) accessor(i);
    for (size_t i = 0; i < m.meshes.size(); ++i) mesh(i);
    for (size_t i = 0; i < m.materials.size(); ++i) material(i);
    for (size_t i = 0; i < m.textures.size(); ++i) texture(i);
    for (size_t i = 0; i < m.cameras.size(); ++i) camera(i);
    for (size_t i = 0; i < m.lights.size(); ++i) light(i);
    for (size_t i = 0; i < m.nodes.size(); ++i) node(i);
    hierarchy();
    scenes();
  }

private:
  [[noreturn]] void bad(const std::string& what) const { fail(m_file, what); }

  static bool inRange(int index, size_t size) { return index >= 0 && static_cast<size_t>(index) < size; }
  // An index into an array of `size`; -1 ("none") is allowed unless `required`.
  void ref(int index, size_t size, const std::string& who, const std::string& what,
           bool required = false) const {
    if ((required || index != -1) && !inRange(index, size))
      bad(who + " refers to " + what + " " + std::to_string(index) + ", but there are " +
          str(size));
  }
  void finite(const std::vector<double>& v, const std::string& who) const {
    for (double x : v)
      if (!std::isfinite(x)) bad(who + " contains a non-finite number");
  }

  void bufferViews() const {
    for (size_t i = 0; i < m.bufferViews.size(); ++i) {
      const auto& bv = m.bufferViews[i];
      const std::string who = "bufferView " + str(i);
      ref(bv.buffer, m.buffers.size(), who, "buffer", true);
      size_t size = m.buffers[static_cast<size_t>(bv.buffer)].data.size();
      if (bv.byteLength == 0) bad(who + " has byteLength 0");
      if (bv.byteOffset > size || bv.byteLength > size - bv.byteOffset)
        bad(who + " (bytes " + str(bv.byteOffset) + ".." + str(bv.byteOffset + bv.byteLength) +
            ") lies outside buffer " + std::to_string(bv.buffer) + " (" + str(size) + " bytes)");
    }
  }

  void accessor(size_t i) const {
    const auto& a = m.accessors[i];
    const std::string who = "accessor " + str(i);
    const int cs = componentSize(a.componentType), nc = componentCount(a.type);
    if (cs == 0) bad(who + " has invalid componentType " + std::to_string(a.componentType));
    if (nc == 0) bad(who + " has an invalid type");
    if (a.count == 0) bad(who + " has count 0");
    if (a.bufferView == -1) return; // zero-filled or sparse: rejected where it would be read
    ref(a.bufferView, m.bufferViews.size(), who, "bufferView", true);
    const auto& bv = m.bufferViews[static_cast<size_t>(a.bufferView)];
    // Matrix columns start on 4-byte boundaries.
    size_t elementSize = static_cast<size_t>(cs) * static_cast<size_t>(nc);
    if (a.type == TINYGLTF_TYPE_MAT2 && cs == 1) elementSize = 8;
    if (a.type == TINYGLTF_TYPE_MAT3 && cs == 1) elementSize = 12;
    if (a.type == TINYGLTF_TYPE_MAT3 && cs == 2) elementSize = 24;
    size_t stride = bv.byteStride != 0 ? bv.byteStride : elementSize;
    if (stride < elementSize)
      bad(who + " has elements of " + str(elementSize) + " bytes but bufferView " +
          std::to_string(a.bufferView) + " has byteStride " + str(stride));
    const std::string past = who + " reads past the end of bufferView " + std::to_string(a.bufferView);
    if (a.byteOffset > bv.byteLength || a.count > bv.byteLength) bad(past);
    // No overflow: count <= byteLength (a real buffer's size) and stride <= 252.
    if (a.byteOffset + stride * (a.count - 1) + elementSize > bv.byteLength) bad(past);
  }

  // An accessor rtlab reads: stored in a buffer view, not sparse, of the given type/components.
  void readable(int index, const std::string& who, int type, std::initializer_list<int> comps,
                bool normalizedInts) const {
    ref(index, m.accessors.size(), who, "accessor", true);
    const auto& a = m.accessors[static_cast<size_t>(index)];
    const std::string acc = who + " (accessor " + std::to_string(index) + ")";
    if (a.sparse.isSparse) bad(acc + " is sparse, which rtlab does not support");
    if (a.bufferView == -1) bad(acc + " has no bufferView, which rtlab does not support");
    if (a.type != type) bad(acc + " has the wrong type");
    bool ok = false;
    for (int c : comps) ok = ok || c == a.componentType;
    if (!ok) bad(acc + " has the wrong componentType " + std::to_string(a.componentType));
    bool isInt = a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT;
    if (isInt && normalizedInts && !a.normalized) bad(acc + " must be normalized");
    if (isInt && !normalizedInts && a.normalized) bad(acc + " must not be normalized");
  }

  void mesh(size_t i) const {
    const auto& mesh = m.meshes[i];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const auto& prim = mesh.primitives[p];
      const std::string who = "mesh " + str(i) + " primitive " + str(p);
      ref(prim.material, m.materials.size(), who, "material");
      for (const auto& [name, index] : prim.attributes) ref(index, m.accessors.size(), who + " " + name, "accessor");
      for (const auto& target : prim.targets)
        for (const auto& [name, index] : target) ref(index, m.accessors.size(), who + " morph target", "accessor");
      if (prim.mode != -1 && (prim.mode < 0 || prim.mode > 6))
        bad(who + " has invalid mode " + std::to_string(prim.mode));
      auto pos = prim.attributes.find("POSITION");
      if (pos == prim.attributes.end()) bad(who + " has no POSITION attribute");
      constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
      readable(pos->second, who + " POSITION", TINYGLTF_TYPE_VEC3, {kFloat}, false);
      const size_t count = m.accessors[static_cast<size_t>(pos->second)].count;
      auto check = [&](const char* name, int type, std::initializer_list<int> comps, bool norm) {
        auto it = prim.attributes.find(name);
        if (it == prim.attributes.end()) return;
        readable(it->second, who + " " + name, type, comps, norm);
        if (m.accessors[static_cast<size_t>(it->second)].count != count)
          bad(who + " " + name + " has a different count than POSITION");
      };
      check("NORMAL", TINYGLTF_TYPE_VEC3, {kFloat}, false);
      check("TANGENT", TINYGLTF_TYPE_VEC4, {kFloat}, false);
      check("TEXCOORD_0", TINYGLTF_TYPE_VEC2,
            {kFloat, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}, true);
      if (prim.indices != -1)
        readable(prim.indices, who + " indices", TINYGLTF_TYPE_SCALAR,
                 {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                 false);
      if (prim.indices != -1 &&
          m.bufferViews[static_cast<size_t>(m.accessors[static_cast<size_t>(prim.indices)].bufferView)].byteStride != 0)
        bad(who + " indices use a bufferView with byteStride");
    }
  }

  void textureRef(int index, const std::string& who) const {
    ref(index, m.textures.size(), who, "texture");
  }

  void material(size_t i) const {
    const auto& mat = m.materials[i];
    const std::string who = "material " + str(i);
    const auto& pbr = mat.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() != 4) bad(who + " baseColorFactor must have 4 numbers");
    finite(pbr.baseColorFactor, who + " baseColorFactor");
    finite(mat.emissiveFactor, who + " emissiveFactor");
    if (mat.emissiveFactor.size() != 3) bad(who + " emissiveFactor must have 3 numbers");
    if (!std::isfinite(pbr.metallicFactor) || !std::isfinite(pbr.roughnessFactor) ||
        !std::isfinite(mat.alphaCutoff) || !std::isfinite(mat.normalTexture.scale) ||
        !std::isfinite(mat.occlusionTexture.strength))
      bad(who + " has a non-finite factor");
    if (mat.alphaMode != "OPAQUE" && mat.alphaMode != "MASK" && mat.alphaMode != "BLEND")
      bad(who + " has invalid alphaMode '" + mat.alphaMode + "'");
    textureRef(pbr.baseColorTexture.index, who + " baseColorTexture");
    textureRef(pbr.metallicRoughnessTexture.index, who + " metallicRoughnessTexture");
    textureRef(mat.normalTexture.index, who + " normalTexture");
    textureRef(mat.occlusionTexture.index, who + " occlusionTexture");
    textureRef(mat.emissiveTexture.index, who + " emissiveTexture");
  }

  void texture(size_t i) const {
    const auto& t = m.textures[i];
    ref(t.source, m.images.size(), "texture " + str(i), "image");
    ref(t.sampler, m.samplers.size(), "texture " + str(i), "sampler");
  }

  void camera(size_t i) const {
    const auto& c = m.cameras[i];
    const std::string who = "camera " + str(i);
    if (c.type == "orthographic") return; // ignored with a warning where it is used
    if (c.type != "perspective") bad(who + " has invalid type '" + c.type + "'");
    const double yfov = c.perspective.yfov;
    if (!(yfov > 0.0 && yfov < 3.14159)) bad(who + " has yfov outside (0, pi)");
  }

  void extrasNumber(const tinygltf::Value& extras, const char* key, double max, const std::string& who) const {
    if (!extras.IsObject() || !extras.Has(key)) return;
    const auto& v = extras.Get(key);
    double x = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    if (!v.IsNumber() || !std::isfinite(x) || x < 0.0 || x > max)
      bad(who + " extras." + key + " must be a number in [0, " + formatNumber(max) + "]");
  }

  void light(size_t i) const {
    const auto& l = m.lights[i];
    const std::string who = "light " + str(i);
    if (l.type != "directional" && l.type != "point" && l.type != "spot")
      bad(who + " has invalid type '" + l.type + "'");
    if (!l.color.empty() && l.color.size() != 3) bad(who + " color must have 3 numbers");
    finite(l.color, who + " color");
    if (!std::isfinite(l.intensity) || l.intensity < 0.0) bad(who + " has a negative or non-finite intensity");
    if (!std::isfinite(l.range) || l.range < 0.0) bad(who + " has a negative or non-finite range");
    if (l.type == "spot") {
      double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
      if (!(inner >= 0.0 && inner < outer && outer <= 1.5707964))
        bad(who + " needs 0 <= innerConeAngle < outerConeAngle <= pi/2");
    }
    extrasNumber(l.extras, "radius", 1e6, who);
    extrasNumber(l.extras, "angle", 89.0, who);
  }

  void areaLight(const tinygltf::Value& a, const std::string& who) const {
    if (!a.IsObject()) bad(who + " extras.rtlab_area_light must be an object");
    for (const char* key : {"width", "height"}) {
      const auto& v = a.Get(key);
      if (!v.IsNumber() || !(v.GetNumberAsDouble() > 0.0) || !std::isfinite(v.GetNumberAsDouble()))
        bad(who + " rtlab_area_light." + key + " must be a positive number");
    }
    if (a.Has("intensity")) {
      const auto& v = a.Get("intensity");
      if (!v.IsNumber() || !(v.GetNumberAsDouble() >= 0.0) || !std::isfinite(v.GetNumberAsDouble()))
        bad(who + " rtlab_area_light.intensity must be a non-negative number");
    }
    if (a.Has("two_sided") && !a.Get("two_sided").IsBool()) bad(who + " rtlab_area_light.two_sided must be true or false");
    if (a.Has("color")) {
      const auto& c = a.Get("color");
      bool ok = c.IsArray() && c.ArrayLen() == 3;
      for (int k = 0; ok && k < 3; ++k)
        ok = c.Get(k).IsNumber() && std::isfinite(c.Get(k).GetNumberAsDouble()) && c.Get(k).GetNumberAsDouble() >= 0.0;
      if (!ok) bad(who + " rtlab_area_light.color must be 3 non-negative numbers");
    }
  }

  void node(size_t i) const {
    const auto& n = m.nodes[i];
    const std::string who = "node " + str(i);
    ref(n.mesh, m.meshes.size(), who, "mesh");
    ref(n.camera, m.cameras.size(), who, "camera");
    ref(n.skin, m.skins.size(), who, "skin");
    for (int c : n.children) ref(c, m.nodes.size(), who, "child node", true);
    if (!n.matrix.empty() && n.matrix.size() != 16) bad(who + " matrix must have 16 numbers");
    if (!n.translation.empty() && n.translation.size() != 3) bad(who + " translation must have 3 numbers");
    if (!n.rotation.empty() && n.rotation.size() != 4) bad(who + " rotation must have 4 numbers");
    if (!n.scale.empty() && n.scale.size() != 3) bad(who + " scale must have 3 numbers");
    finite(n.matrix, who + " matrix");
    finite(n.translation, who + " translation");
    finite(n.rotation, who + " rotation");
    finite(n.scale, who + " scale");
    if (n.rotation.size() == 4) {
      double len2 = 0;
      for (double q : n.rotation) len2 += q * q;
      if (!(len2 > 1e-12)) bad(who + " has a zero rotation quaternion");
    }
    auto ext = n.extensions.find("KHR_lights_punctual");
    if (ext != n.extensions.end()) {
      const auto& e = ext->second;
      if (!e.IsObject() || !e.Get("light").IsInt()) bad(who + " KHR_lights_punctual needs an integer 'light'");
      int l = e.Get("light").GetNumberAsInt();
      ref(l, m.lights.size(), who, "light", true);
    }
    if (n.extras.IsObject() && n.extras.Has("rtlab_area_light"))
      areaLight(n.extras.Get("rtlab_area_light"), who);
  }

  // Every node has at most one parent and no node is its own ancestor.
  void hierarchy() const {
    const size_t n = m.nodes.size();
    std::vector<int> parent(n, -1);
    for (size_t i = 0; i < n; ++i) {
      for (int c : m.nodes[i].children) {
        size_t ci = static_cast<size_t>(c);
        if (ci == i) bad("node " + str(i) + " is its own child (cycle in the node hierarchy)");
        if (parent[ci] != -1)
          bad("node " + str(ci) + " is reached twice (children of nodes " + std::to_string(parent[ci]) +
              " and " + str(i) + ")");
        parent[ci] = static_cast<int>(i);
      }
    }
    // With one parent each, a cycle is a loop of parents. Walk up from every node: state 1 marks
    // the current path, 2 the nodes known to lead to a root.
    std::vector<char> state(n, 0);
    for (size_t i = 0; i < n; ++i) {
      std::vector<size_t> path;
      for (size_t k = i; state[k] != 2;) {
        if (state[k] == 1) bad("node hierarchy has a cycle through node " + str(k));
        state[k] = 1;
        path.push_back(k);
        if (parent[k] == -1) break;
        k = static_cast<size_t>(parent[k]);
      }
      for (size_t p : path) state[p] = 2;
    }
  }

  void scenes() const {
    ref(m.defaultScene, m.scenes.size(), "the default scene", "scene");
    for (size_t s = 0; s < m.scenes.size(); ++s) {
      const auto& extras = m.scenes[s].extras;
      if (extras.IsObject() && extras.Has("ambient")) {
        const auto& a = extras.Get("ambient");
        bool ok = a.IsArray() && a.ArrayLen() == 3;
        for (int k = 0; ok && k < 3; ++k) {
          const double x = a.Get(k).IsNumber() ? a.Get(k).GetNumberAsDouble() : -1.0;
          ok = std::isfinite(x) && x >= 0.0 && x <= kMaxAmbient;
        }
        if (!ok)
          bad("scene " + str(s) + " extras.ambient must be 3 numbers in [0, " + formatNumber(kMaxAmbient) + "]");
      }
      std::set<int> seen;
      for (int r : m.scenes[s].nodes) {
        ref(r, m.nodes.size(), "scene " + str(s), "node", true);
        if (!seen.insert(r).second) bad("scene " + str(s) + " lists node " + std::to_string(r) + " twice");
      }
    }
    // A root listed in a scene must not be some other node's child (it would be reached twice).
    std::vector<char> isChild(m.nodes.size(), 0);
    for (const auto& n : m.nodes)
      for (int c : n.children) isChild[static_cast<size_t>(c)] = 1;
    for (size_t s = 0; s < m.scenes.size(); ++s)
      for (int r : m.scenes[s].nodes)
        if (isChild[static_cast<size_t>(r)])
          bad("scene " + str(s) + " lists node " + std::to_string(r) + ", which is another node's child");
  }

  const Model& m;
  std::string m_file;
};

} // namespace

void validateModel(const tinygltf::Model& model, const std::string& file) {
  Validator(model, file).run();
}

} // namespace rtlab::gltf
