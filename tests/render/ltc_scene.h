// Scenes and CPU integrals for the ltc render tests (tests/render/test_ltc.cpp): a large floor in
// the plane y = 0 of one material under one rectangular light, and the integrals of the arealight
// stage's definition (docs/contract.md "Area lights") over that light in double precision:
// Lambert's closed-form polygon formula, and quadrature of the frame's BRDF (shading/brdf_model.h).
#pragma once
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "params/param_set.h"
#include "reference/surfaces.h"
#include "render/renderer.h"
#include "render_fixture.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "shading/brdf_model.h"

#include <array>
#include <string>
#include <vector>

namespace rtlab::ltc_test {

struct FloorMaterial {
  glm::vec3 baseColor{0.5f};
  float metallic = 0.0f;
  float roughness = 0.5f;
};

// A rectangle centred at `center` emitting along `direction` (unit), with `right` perpendicular to
// it; up = right x direction, as the scene parameters build it.
Light rectLight(const glm::vec3& center, const glm::vec3& direction, const glm::vec3& right, float width,
                float height, float intensity, bool twoSided = false);

// The floor (40 x 40, y = 0, normal +y) and the light, ambient 0, seen from `eye` looking at `target`.
Scene floorScene(const std::string& name, const FloorMaterial& material, const Light& light, const glm::vec3& eye,
                 const glm::vec3& target);

// The light's corners, counter-clockwise about -direction.
std::array<glm::dvec3, 4> corners(const Light& light);

// (1/pi) integral of max(0, n.l) over the light's solid angle from p (both faces, one face, as the
// light): Lambert's formula (1/2pi) sum_i gamma_i n.normalize(a_i x a_i+1) on the polygon clipped
// to p's horizon, `clip` false: the same formula on the unclipped polygon (what a missing clip
// gives).
double lambertFormFactor(const Light& light, const glm::dvec3& p, const glm::dvec3& n, bool clip = true);

// Quadrature over the light's area (`cells` x `cells/2` midpoints): the radiance it adds at p
// towards v, integral of L_e f(v, l) cos dw, with f = the frame's BRDF; `diffuseOnly`: only its
// diffuse term (1 - F)(1 - metallic) baseColor / pi.
glm::dvec3 brdfIntegral(const Light& light, const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& v,
                        const brdf::Material& m, int cells, bool diffuseOnly = false);

// The renderer of one test scene with its parameters.
struct LtcRenderer {
  Renderer renderer{TechniqueRegistry::instance()};
  Scene scene;
  ParamSet params;
  explicit LtcRenderer(const Scene& s);
  void set(const std::string& key, const std::string& value) { params.setText(key, value); }
  // Renders `aovs` with ltc active (or `techniques`), keeping the surface points.
  void render(const std::vector<std::string>& aovs, int w, int h, const std::vector<std::string>& techniques = {"ltc"});
  Image aov(const std::string& name) const { return renderer.readAov(name); }
  SurfaceData surfaces() const { return renderer.readSurfaces(); }
};

} // namespace rtlab::ltc_test
