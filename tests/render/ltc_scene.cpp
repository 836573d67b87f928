#include "ltc_scene.h"

#include "rect_quadrature.h"

#include <algorithm>
#include <cmath>

namespace rtlab::ltc_test {

Light rectLight(const glm::vec3& center, const glm::vec3& direction, const glm::vec3& right, float width,
                float height, float intensity, bool twoSided) {
  Light l;
  l.name = "rect";
  l.type = LightType::Rect;
  l.position = center;
  l.direction = glm::normalize(direction);
  l.right = glm::normalize(right);
  l.up = glm::cross(l.right, l.direction);
  l.width = width;
  l.height = height;
  l.intensity = intensity;
  l.twoSided = twoSided;
  return l;
}

Scene floorScene(const std::string& name, const FloorMaterial& material, const Light& light, const glm::vec3& eye,
                 const glm::vec3& target) {
  builtin::SceneBuilder b(name);
  Material m = builtin::diffuseMaterial("floor", material.baseColor, material.roughness);
  m.metallic = material.metallic;
  b.addObject(makePlane("floor", 40.0f, 40.0f, 1), b.addMaterial(m));
  b.addLight(light);
  Scene scene = b.finish(builtin::camera(eye, target, 50.0f));
  scene.ambient = glm::vec3(0.0f);
  return scene;
}

std::array<glm::dvec3, 4> corners(const Light& light) {
  const glm::dvec3 c(light.position), r = glm::dvec3(light.right) * (0.5 * light.width);
  glm::dvec3 u = glm::dvec3(light.up) * (0.5 * light.height);
  if (glm::dot(glm::cross(r, u), glm::dvec3(light.direction)) > 0.0) u = -u;
  return {c - r - u, c + r - u, c + r + u, c - r + u};
}

double lambertFormFactor(const Light& light, const glm::dvec3& p, const glm::dvec3& n, bool clip) {
  std::vector<glm::dvec3> poly;
  for (const auto& c : corners(light)) poly.push_back(c - p);
  if (clip) { // the part with n.x >= 0
    std::vector<glm::dvec3> kept;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const glm::dvec3 a = poly[i], b = poly[(i + 1) % poly.size()];
      const double da = glm::dot(a, n), db = glm::dot(b, n);
      if (da >= 0.0) kept.push_back(a);
      if ((da >= 0.0) != (db >= 0.0)) kept.push_back(a + (b - a) * (da / (da - db)));
    }
    poly = kept;
  }
  if (poly.size() < 3) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 a = glm::normalize(poly[i]), b = glm::normalize(poly[(i + 1) % poly.size()]);
    const glm::dvec3 c = glm::cross(a, b);
    const double s = glm::length(c);
    if (s < 1e-15) continue;
    sum += std::atan2(s, glm::dot(a, b)) * glm::dot(n, c / s);
  }
  sum /= 2.0 * brdf::kPi;
  const bool front = glm::dot(p - glm::dvec3(light.position), glm::dvec3(light.direction)) > 0.0;
  return light.twoSided ? std::abs(sum) : (front ? std::max(sum, 0.0) : 0.0);
}

glm::dvec3 brdfIntegral(const Light& light, const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& v,
                        const brdf::Material& m, int cells, bool diffuseOnly) {
  return test::rectQuadrature(area_mc::rectLightFrom(light), p, n, v, m, cells, std::max(1, cells / 2),
                              diffuseOnly ? test::BrdfTerm::Diffuse : test::BrdfTerm::Full);
}

LtcRenderer::LtcRenderer(const Scene& s) : scene(s) {
  testContext().makeCurrent();
  renderer.setScene(scene);
  params = makeParamSet(scene, TechniqueRegistry::instance());
}

void LtcRenderer::render(const std::vector<std::string>& aovs, int w, int h, const std::vector<std::string>& techniques) {
  FrameOutputs outputs;
  outputs.aovs = aovs;
  outputs.surfaces = true;
  renderOwnFrame(renderer, params, techniques, outputs, w, h);
}

} // namespace rtlab::ltc_test
