// Synthetic scenes and surface points for the reference tests: quads placed by hand and G-buffer
// data built from analytic points, so the tests need no GL context.
#pragma once
#include "reference/surfaces.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace rtlab::test {

// A quad centred at c spanning c +- u +- v, facing cross(u, v); returns the instance index.
inline int addQuad(Scene& scene, const glm::vec3& c, const glm::vec3& u, const glm::vec3& v, int material = -1,
                   bool transparent = false) {
  Mesh m;
  m.name = "quad" + std::to_string(scene.meshes.size());
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  const glm::vec3 corners[4] = {c - u - v, c + u - v, c + u + v, c - u + v};
  const glm::vec2 uvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  for (int i = 0; i < 4; ++i) {
    Vertex vx;
    vx.position = corners[i];
    vx.normal = n;
    vx.uv = uvs[i];
    m.vertices.push_back(vx);
    m.bounds.extend(corners[i]);
  }
  m.indices = {0, 1, 2, 0, 2, 3};
  m.material = material;
  scene.meshes.push_back(m);
  Instance inst;
  inst.mesh = int(scene.meshes.size()) - 1;
  inst.transparent = transparent;
  scene.instances.push_back(inst);
  return int(scene.instances.size()) - 1;
}

inline int addMaterial(Scene& scene, const glm::vec3& baseColor) {
  Material m;
  m.baseColor = glm::vec4(baseColor, 1.0f);
  scene.materials.push_back(m);
  return int(scene.materials.size()) - 1;
}

inline Light directional(const glm::vec3& travels, float lux, float angleDegrees) {
  Light l;
  l.type = LightType::Directional;
  l.direction = glm::normalize(travels);
  l.intensity = lux;
  l.angle = angleDegrees;
  return l;
}

inline Light point(const glm::vec3& position, float candela, float radius) {
  Light l;
  l.type = LightType::Point;
  l.position = position;
  l.intensity = candela;
  l.radius = radius;
  return l;
}

inline Light rect(const glm::vec3& position, float width, float height, float nits) {
  Light l;
  l.type = LightType::Rect;
  l.position = position;
  l.direction = {0, -1, 0};
  l.right = {1, 0, 0};
  l.up = {0, 0, -1};
  l.width = width;
  l.height = height;
  l.intensity = nits;
  return l;
}

// width x height surface points from point(x, y); every one valid with both normals = normal.
inline SurfaceData gridSurfaces(int width, int height, const glm::vec3& normal,
                                const std::function<glm::vec3(int, int)>& point) {
  SurfaceData s;
  s.width = width;
  s.height = height;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      s.position.push_back(point(x, y));
      s.geometricNormal.push_back(glm::normalize(normal));
      s.shadingNormal.push_back(glm::normalize(normal));
      s.valid.push_back(1);
    }
  }
  return s;
}

// docs/measuring.md, "AO beside a wall": a floor point at distance d from a wall that meets the
// floor at 90 degrees; with a = d / R < 1 the occluded part of the cosine-weighted hemisphere is a
// circular segment of the projected unit disk: ao = 1 - (acos(a) - a sqrt(1 - a^2)) / pi.
inline double aoBesideWall(double d, double radius) {
  const double a = d / radius;
  if (a >= 1.0) return 1.0;
  return 1.0 - (std::acos(a) - a * std::sqrt(1.0 - a * a)) / std::numbers::pi;
}

// Floor y = 0 for x > 0 and a wall x = 0 facing +x, both 100 wide; points at x = d in (0, 1.25 R).
struct WallCase {
  Scene scene;
  SurfaceData points;
  std::vector<double> expected; // per pixel
  float radius = 1.0f;
};

inline WallCase wallCase(int columns, int rows, float maxD) {
  WallCase c;
  c.scene.name = "wall";
  addQuad(c.scene, {50, 0, 0}, {50, 0, 0}, {0, 0, -50}); // floor, facing +y
  addQuad(c.scene, {0, 50, 0}, {0, 0, -50}, {0, 50, 0}); // wall, facing +x
  c.scene.camera.position = {6, 4, 0.5f};
  c.points = gridSurfaces(columns, rows, {0, 1, 0}, [&](int x, int y) {
    return glm::vec3(maxD * (x + 0.5f) / columns, 0.0f, -1.0f + 2.0f * (y + 0.5f) / rows);
  });
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < columns; ++x)
      c.expected.push_back(aoBesideWall(maxD * (x + 0.5) / columns, c.radius));
  return c;
}

} // namespace rtlab::test
