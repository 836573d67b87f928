#include "ltc_scene.h"

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
  const int nx = cells, ny = std::max(1, cells / 2);
  const glm::dvec3 c(light.position), r(light.right), u(light.up), d(light.direction);
  const double dA = double(light.width) * light.height / (double(nx) * ny);
  const glm::dvec3 le = glm::dvec3(light.color) * double(light.intensity);
  glm::dvec3 sum(0.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const glm::dvec3 x = c + r * (((i + 0.5) / nx - 0.5) * light.width) + u * (((j + 0.5) / ny - 0.5) * light.height);
      const glm::dvec3 toX = x - p;
      const double dist2 = glm::dot(toX, toX);
      const glm::dvec3 l = toX / std::sqrt(dist2);
      const double cosE = light.twoSided ? std::abs(glm::dot(-l, d)) : std::max(glm::dot(-l, d), 0.0);
      const double dOmega = dA * cosE / dist2;
      if (dOmega <= 0.0) continue;
      glm::dvec3 f;
      if (diffuseOnly) {
        const double nDotL = glm::dot(n, l);
        if (nDotL <= 0.0) continue;
        const glm::dvec3 h = glm::normalize(l + v);
        const glm::dvec3 f0 = glm::mix(glm::dvec3(brdf::kDielectricF0), m.baseColor, m.metallic);
        const glm::dvec3 fresnel = f0 + (1.0 - f0) * brdf::schlickWeight(std::max(glm::dot(v, h), 0.0));
        f = (1.0 - fresnel) * (1.0 - m.metallic) * m.baseColor / brdf::kPi * nDotL;
      } else {
        f = brdf::evaluateBrdfCos(n, v, l, m);
      }
      sum += le * f * dOmega;
    }
  return sum;
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
