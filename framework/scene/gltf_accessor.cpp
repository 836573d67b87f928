// Reading validated glTF accessors into typed arrays.
#include "scene/gltf_internal.h"

#include "util/error.h"

#include <algorithm>
#include <cstring>

namespace rtlab::gltf {

int componentSize(int componentType) {
  switch (componentType) {
  case TINYGLTF_COMPONENT_TYPE_BYTE:
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
  case TINYGLTF_COMPONENT_TYPE_SHORT:
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
  case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
  default: return 0; // INT (5124) and DOUBLE are not glTF 2.0 accessor component types
  }
}

int componentCount(int type) {
  switch (type) {
  case TINYGLTF_TYPE_SCALAR: return 1;
  case TINYGLTF_TYPE_VEC2: return 2;
  case TINYGLTF_TYPE_VEC3: return 3;
  case TINYGLTF_TYPE_VEC4: return 4;
  case TINYGLTF_TYPE_MAT2: return 4;
  case TINYGLTF_TYPE_MAT3: return 9;
  case TINYGLTF_TYPE_MAT4: return 16;
  default: return 0;
  }
}

namespace {

// One component at `p` as a double; normalized integers map to [0,1] (unsigned) or [-1,1].
double readComponent(const unsigned char* p, int componentType, bool normalized) {
  switch (componentType) {
  case TINYGLTF_COMPONENT_TYPE_FLOAT: {
    float f;
    std::memcpy(&f, p, 4);
    return f;
  }
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
  case TINYGLTF_COMPONENT_TYPE_BYTE: {
    auto v = static_cast<signed char>(p[0]);
    return normalized ? std::max(v / 127.0, -1.0) : v;
  }
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
    std::uint16_t v;
    std::memcpy(&v, p, 2);
    return normalized ? v / 65535.0 : v;
  }
  case TINYGLTF_COMPONENT_TYPE_SHORT: {
    std::int16_t v;
    std::memcpy(&v, p, 2);
    return normalized ? std::max(v / 32767.0, -1.0) : v;
  }
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return normalized ? v / 4294967295.0 : v;
  }
  default: return 0.0;
  }
}

// Calls fn(elementIndex, bytes) for every element. The accessor must have passed validateModel's
// bounds check and be stored in a buffer view (validateModel rejects the others where read).
template <typename Fn>
void forEachElement(const tinygltf::Model& model, int accessorIndex, int minComponents, Fn fn) {
  const auto& a = model.accessors.at(static_cast<size_t>(accessorIndex));
  if (a.bufferView < 0 || componentCount(a.type) < minComponents)
    throw Error(ExitCode::Internal, "glTF accessor " + std::to_string(accessorIndex) + " read unvalidated");
  if (a.count == 0) return;
  const auto& bv = model.bufferViews.at(static_cast<size_t>(a.bufferView));
  const auto& buffer = model.buffers.at(static_cast<size_t>(bv.buffer));
  const size_t elementSize = static_cast<size_t>(componentSize(a.componentType) * componentCount(a.type));
  const size_t stride = bv.byteStride != 0 ? bv.byteStride : elementSize;
  const size_t begin = bv.byteOffset + a.byteOffset;
  if (begin + stride * (a.count - 1) + elementSize > buffer.data.size())
    throw Error(ExitCode::Internal, "glTF accessor " + std::to_string(accessorIndex) + " out of bounds");
  const unsigned char* base = buffer.data.data() + begin;
  for (size_t i = 0; i < a.count; ++i) fn(i, base + i * stride, a);
}

template <int N>
std::vector<glm::vec<N, float>> readVector(const tinygltf::Model& model, int accessorIndex) {
  std::vector<glm::vec<N, float>> out;
  out.resize(model.accessors.at(static_cast<size_t>(accessorIndex)).count);
  forEachElement(model, accessorIndex, N, [&](size_t i, const unsigned char* p, const tinygltf::Accessor& a) {
    const int cs = componentSize(a.componentType);
    for (int c = 0; c < N; ++c)
      out[i][c] = static_cast<float>(readComponent(p + c * cs, a.componentType, a.normalized));
  });
  return out;
}

} // namespace

std::vector<glm::vec2> readVec2(const tinygltf::Model& model, int accessor) {
  return readVector<2>(model, accessor);
}
std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int accessor) {
  return readVector<3>(model, accessor);
}
std::vector<glm::vec4> readVec4(const tinygltf::Model& model, int accessor) {
  return readVector<4>(model, accessor);
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor) {
  std::vector<std::uint32_t> out(model.accessors.at(static_cast<size_t>(accessor)).count);
  forEachElement(model, accessor, 1, [&](size_t i, const unsigned char* p, const tinygltf::Accessor& a) {
    out[i] = static_cast<std::uint32_t>(readComponent(p, a.componentType, false));
  });
  return out;
}

} // namespace rtlab::gltf
