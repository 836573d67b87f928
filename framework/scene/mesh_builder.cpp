// Procedural meshes and vertex-attribute generation (see mesh_builder.h for the conventions).
#include "scene/mesh_builder.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

bool isFinite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::uint32_t vertexCount(const Mesh& mesh) {
  return static_cast<std::uint32_t>(mesh.vertices.size());
}

} // namespace

glm::vec3 anyPerpendicular(const glm::vec3& n) {
  // Cross with the axis least aligned with n.
  glm::vec3 a = std::fabs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(a, n));
}

void appendQuad(Mesh& mesh, const glm::vec3& center, const glm::vec3& halfU,
                const glm::vec3& halfV, int segments) {
  segments = std::max(segments, 1);
  const glm::vec3 normal = glm::normalize(glm::cross(halfU, halfV));
  const glm::vec4 tangent(glm::normalize(halfU), 1.0f); // bitangent = cross(n, u) = +v = image up
  const std::uint32_t base = vertexCount(mesh);
  const int n = segments + 1;
  for (int j = 0; j < n; ++j) {
    float t = static_cast<float>(j) / segments; // 0 at -halfV, 1 at +halfV
    for (int i = 0; i < n; ++i) {
      float s = static_cast<float>(i) / segments;
      Vertex v;
      v.position = center + (2.0f * s - 1.0f) * halfU + (2.0f * t - 1.0f) * halfV;
      v.normal = normal;
      v.tangent = tangent;
      v.uv = glm::vec2(s, 1.0f - t);
      mesh.vertices.push_back(v);
    }
  }
  for (int j = 0; j < segments; ++j) {
    for (int i = 0; i < segments; ++i) {
      std::uint32_t a = base + static_cast<std::uint32_t>(j * n + i);
      std::uint32_t b = a + 1;
      std::uint32_t c = a + static_cast<std::uint32_t>(n) + 1;
      std::uint32_t d = a + static_cast<std::uint32_t>(n);
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  }
}

Mesh makeQuad(const std::string& name, const glm::vec3& center, const glm::vec3& halfU,
              const glm::vec3& halfV, int segments) {
  Mesh mesh;
  mesh.name = name;
  appendQuad(mesh, center, halfU, halfV, segments);
  computeBounds(mesh);
  return mesh;
}

Mesh makePlane(const std::string& name, float sizeX, float sizeZ, int segments) {
  return makeQuad(name, glm::vec3(0), glm::vec3(0.5f * sizeX, 0, 0), glm::vec3(0, 0, -0.5f * sizeZ),
                  segments);
}

Mesh makeBox(const std::string& name, const glm::vec3& size) {
  const glm::vec3 h = 0.5f * size;
  Mesh mesh;
  mesh.name = name;
  // Each face: (center, halfU, halfV) with cross(halfU, halfV) pointing outward.
  appendQuad(mesh, {h.x, 0, 0}, {0, 0, -h.z}, {0, h.y, 0});
  appendQuad(mesh, {-h.x, 0, 0}, {0, 0, h.z}, {0, h.y, 0});
  appendQuad(mesh, {0, h.y, 0}, {h.x, 0, 0}, {0, 0, -h.z});
  appendQuad(mesh, {0, -h.y, 0}, {h.x, 0, 0}, {0, 0, h.z});
  appendQuad(mesh, {0, 0, h.z}, {h.x, 0, 0}, {0, h.y, 0});
  appendQuad(mesh, {0, 0, -h.z}, {-h.x, 0, 0}, {0, h.y, 0});
  computeBounds(mesh);
  return mesh;
}

Mesh makeSphere(const std::string& name, float radius, int slices, int stacks) {
  slices = std::max(slices, 3);
  stacks = std::max(stacks, 2);
  Mesh mesh;
  mesh.name = name;
  const float pi = glm::pi<float>();
  for (int i = 0; i <= stacks; ++i) {
    float theta = pi * static_cast<float>(i) / stacks; // 0 at the north pole (+y)
    for (int j = 0; j <= slices; ++j) {
      float phi = 2.0f * pi * static_cast<float>(j) / slices; // 0 at +z, increasing towards +x
      glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      Vertex v;
      v.position = radius * n;
      v.normal = n;
      v.tangent = glm::vec4(std::cos(phi), 0.0f, -std::sin(phi), 1.0f); // d(position)/d(phi)
      v.uv = glm::vec2(static_cast<float>(j) / slices, static_cast<float>(i) / stacks);
      mesh.vertices.push_back(v);
    }
  }
  const std::uint32_t row = static_cast<std::uint32_t>(slices + 1);
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      std::uint32_t a = static_cast<std::uint32_t>(i) * row + static_cast<std::uint32_t>(j);
      std::uint32_t b = a + row, c = a + row + 1, d = a + 1;
      if (i != stacks - 1) mesh.indices.insert(mesh.indices.end(), {a, b, c}); // not at south pole
      if (i != 0) mesh.indices.insert(mesh.indices.end(), {a, c, d});          // not at north pole
    }
  }
  computeBounds(mesh);
  return mesh;
}

Mesh makeCylinder(const std::string& name, float radius, float height, int segments) {
  segments = std::max(segments, 3);
  Mesh mesh;
  mesh.name = name;
  const float pi = glm::pi<float>();
  const std::uint32_t base = 0;
  for (int j = 0; j <= segments; ++j) {
    float phi = 2.0f * pi * static_cast<float>(j) / segments;
    glm::vec3 n(std::sin(phi), 0.0f, std::cos(phi));
    for (int k = 0; k < 2; ++k) { // k = 0 top, 1 bottom
      Vertex v;
      v.position = radius * n + glm::vec3(0, k == 0 ? height : 0.0f, 0);
      v.normal = n;
      v.tangent = glm::vec4(std::cos(phi), 0.0f, -std::sin(phi), 1.0f);
      v.uv = glm::vec2(static_cast<float>(j) / segments, static_cast<float>(k));
      mesh.vertices.push_back(v);
    }
  }
  for (int j = 0; j < segments; ++j) {
    std::uint32_t top = base + static_cast<std::uint32_t>(2 * j), bottom = top + 1;
    mesh.indices.insert(mesh.indices.end(), {top, bottom, bottom + 2, top, bottom + 2, top + 2});
  }
  // Caps: a fan around a centre vertex each.
  for (int k = 0; k < 2; ++k) {
    const float y = k == 0 ? height : 0.0f;
    const glm::vec3 n(0, k == 0 ? 1.0f : -1.0f, 0);
    const std::uint32_t center = vertexCount(mesh);
    Vertex c;
    c.position = glm::vec3(0, y, 0);
    c.normal = n;
    c.tangent = glm::vec4(1, 0, 0, 1);
    c.uv = glm::vec2(0.5f);
    mesh.vertices.push_back(c);
    for (int j = 0; j <= segments; ++j) {
      float phi = 2.0f * pi * static_cast<float>(j) / segments;
      Vertex v = c;
      v.position = glm::vec3(radius * std::sin(phi), y, radius * std::cos(phi));
      v.uv = glm::vec2(0.5f + 0.5f * std::sin(phi), 0.5f - 0.5f * n.y * std::cos(phi));
      mesh.vertices.push_back(v);
    }
    for (int j = 0; j < segments; ++j) {
      std::uint32_t a = center + 1 + static_cast<std::uint32_t>(j), b = a + 1;
      if (k == 0) mesh.indices.insert(mesh.indices.end(), {center, a, b});
      else mesh.indices.insert(mesh.indices.end(), {center, b, a});
    }
  }
  generateTangents(mesh); // the caps' tangents follow their UVs
  computeBounds(mesh);
  return mesh;
}

void computeBounds(Mesh& mesh) {
  mesh.bounds = Bounds{};
  for (const Vertex& v : mesh.vertices) mesh.bounds.extend(v.position);
}

void generateFlatNormals(Mesh& mesh) {
  std::vector<Vertex> out;
  std::vector<std::uint32_t> indices;
  out.reserve(mesh.indices.size());
  indices.reserve(mesh.indices.size());
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    Vertex v[3] = {mesh.vertices[mesh.indices[t]], mesh.vertices[mesh.indices[t + 1]],
                   mesh.vertices[mesh.indices[t + 2]]};
    glm::vec3 n = glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
    float len = glm::length(n);
    n = (len > 0.0f && std::isfinite(len)) ? n / len : glm::vec3(0, 1, 0);
    for (Vertex& x : v) {
      x.normal = n;
      indices.push_back(static_cast<std::uint32_t>(out.size()));
      out.push_back(x);
    }
  }
  mesh.vertices = std::move(out);
  mesh.indices = std::move(indices);
}

void generateTangents(Mesh& mesh) {
  const size_t n = mesh.vertices.size();
  std::vector<glm::vec3> tan(n, glm::vec3(0)), bit(n, glm::vec3(0));
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    const Vertex& v0 = mesh.vertices[i[0]];
    const Vertex& v1 = mesh.vertices[i[1]];
    const Vertex& v2 = mesh.vertices[i[2]];
    glm::vec3 e1 = v1.position - v0.position, e2 = v2.position - v0.position;
    glm::vec2 d1 = v1.uv - v0.uv, d2 = v2.uv - v0.uv;
    float det = d1.x * d2.y - d2.x * d1.y;
    float area = 0.5f * glm::length(glm::cross(e1, e2));
    if (std::fabs(det) < 1e-12f || !(area > 0.0f)) continue;
    glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) / det;
    glm::vec3 dpdv = (e2 * d1.x - e1 * d2.x) / det;
    float lu = glm::length(dpdu), lv = glm::length(dpdv);
    if (!(lu > 0.0f) || !(lv > 0.0f) || !std::isfinite(lu) || !std::isfinite(lv)) continue;
    for (std::uint32_t k : i) {
      tan[k] += area * dpdu / lu;
      bit[k] += area * dpdv / lv;
    }
  }
  for (size_t k = 0; k < n; ++k) {
    Vertex& v = mesh.vertices[k];
    glm::vec3 t = tan[k] - v.normal * glm::dot(v.normal, tan[k]);
    float len = glm::length(t);
    t = (len > 1e-12f && std::isfinite(len)) ? t / len : anyPerpendicular(v.normal);
    // glTF bitangent points towards decreasing v (image up): -dP/dv.
    float w = glm::dot(glm::cross(v.normal, t), -bit[k]) < 0.0f ? -1.0f : 1.0f;
    v.tangent = glm::vec4(t, w);
  }
}

int normalizeFrames(Mesh& mesh) {
  int fixedCount = 0;
  for (Vertex& v : mesh.vertices) {
    float len = glm::length(v.normal);
    if (len > 1e-20f && std::isfinite(len)) {
      v.normal /= len;
    } else {
      v.normal = glm::vec3(0, 1, 0);
      ++fixedCount;
    }
    glm::vec3 t(v.tangent);
    t -= v.normal * glm::dot(v.normal, t);
    len = glm::length(t);
    if (len > 1e-12f && isFinite(t)) {
      t /= len;
    } else {
      t = anyPerpendicular(v.normal);
    }
    v.tangent = glm::vec4(t, v.tangent.w < 0.0f ? -1.0f : 1.0f);
  }
  return fixedCount;
}

} // namespace rtlab
