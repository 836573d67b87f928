#include "techniques/area_mc/area_mc_model.h"

#include "reference/progress.h"
#include "util/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>

namespace rtlab::area_mc {
namespace {

// An orthonormal basis about the unit vector n (Duff et al., JCGT 2017), in double precision.
struct Basis {
  glm::dvec3 t, b, n;
  explicit Basis(const glm::dvec3& normal) : n(normal) {
    const double s = std::copysign(1.0, n.z);
    const double a = -1.0 / (s + n.z);
    const double c = n.x * n.y * a;
    t = {1.0 + s * n.x * n.x * a, s * c, -s * n.x};
    b = {c, s + n.y * n.y * a, -n.y};
  }
  glm::dvec3 toWorld(const glm::dvec3& v) const { return t * v.x + b * v.y + n * v.z; }
};

// The power heuristic, exponent 2 (Veach & Guibas 1995): pdf^2 / (pdf^2 + other^2), written as
// 1 / (1 + r^2) so that a huge density (a grazing face) cannot overflow.
double powerWeight(double pdf, double other) {
  const double r = other / pdf;
  return 1.0 / (1.0 + r * r);
}

} // namespace

RectLight rectLightFrom(const Light& light) {
  RectLight r;
  r.center = glm::dvec3(light.position);
  r.normal = glm::normalize(glm::dvec3(light.direction));
  r.right = glm::normalize(glm::dvec3(light.right));
  r.up = glm::normalize(glm::dvec3(light.up));
  r.width = light.width;
  r.height = light.height;
  r.radiance = glm::dvec3(light.color) * double(light.intensity);
  r.twoSided = light.twoSided;
  return r;
}

std::vector<RectLight> rectLights(const Scene& scene) {
  std::vector<RectLight> out;
  for (const Light& l : scene.lights)
    if (l.type == LightType::Rect) out.push_back(rectLightFrom(l));
  return out;
}

glm::dvec3 emittedToward(const RectLight& light, const glm::dvec3& x, const glm::dvec3& p, double& cosLight) {
  const glm::dvec3 d = p - x;
  const double len = glm::length(d);
  cosLight = len > 0.0 ? glm::dot(d, light.normal) / len : 0.0;
  if (light.twoSided) cosLight = std::abs(cosLight);
  if (!(cosLight > 0.0)) {
    cosLight = 0.0;
    return glm::dvec3(0.0);
  }
  return light.radiance;
}

bool intersect(const RectLight& light, const glm::dvec3& p, const glm::dvec3& l, double& t) {
  const double denom = glm::dot(l, light.normal);
  if (std::abs(denom) < 1e-12) return false;
  t = glm::dot(light.center - p, light.normal) / denom;
  if (!(t > 0.0) || !std::isfinite(t)) return false;
  const glm::dvec3 q = p + t * l - light.center;
  return std::abs(glm::dot(q, light.right)) <= 0.5 * light.width && std::abs(glm::dot(q, light.up)) <= 0.5 * light.height;
}

glm::dvec3 sampleRect(const ShadingPoint& x, const RectLight& light, glm::dvec2 uLight, glm::dvec2 uBrdf,
                      Strategy strategy) {
  const glm::dvec3& p = x.position;
  const glm::dvec3& n = x.normal;
  const glm::dvec3& v = x.toViewer;
  const double alpha = brdf::alphaFromRoughness(x.material.roughness);
  const double area = light.area();
  glm::dvec3 sum(0.0);

  // Light-area sampling: a uniform point q of the rectangle, pdf 1/A over its area, so over solid
  // angle at p: pdf = r^2 / (A |cos theta'|) (dw = dA cos theta' / r^2).
  if (strategy != Strategy::Brdf) {
    const glm::dvec3 q = light.center + (uLight.x - 0.5) * light.width * light.right +
                         (uLight.y - 0.5) * light.height * light.up;
    const glm::dvec3 d = q - p;
    const double r2 = glm::dot(d, d);
    double cosLight = 0.0;
    const glm::dvec3 le = emittedToward(light, q, p, cosLight);
    if (r2 > 0.0 && cosLight > 0.0) {
      const glm::dvec3 l = d / std::sqrt(r2);
      const glm::dvec3 f = brdf::evaluateBrdfCos(n, v, l, x.material); // 0 below the horizon
      if (f != glm::dvec3(0.0)) {
        const double pdfLight = r2 / (area * cosLight);
        const double w =
            strategy == Strategy::Mis ? powerWeight(pdfLight, brdf::ggxReflectionPdf(n, v, l, alpha)) : 1.0;
        sum += w * f * le / pdfLight;
      }
    }
  }

  // GGX sampling: a half vector h with density D(h) n.h about n, l = v reflected about h, density
  // D(h) n.h / (4 v.h) over directions; it counts where the ray meets the emitting face.
  if (strategy != Strategy::Light) {
    const glm::dvec3 h = Basis(n).toWorld(brdf::sampleGgxHalfVector(alpha, uBrdf.x, uBrdf.y));
    const double vDotH = glm::dot(v, h);
    double t = 0.0;
    if (vDotH > 0.0) {
      const glm::dvec3 l = glm::normalize(2.0 * vDotH * h - v);
      if (glm::dot(n, l) > 0.0 && intersect(light, p, l, t)) {
        double cosLight = 0.0;
        const glm::dvec3 le = emittedToward(light, p + t * l, p, cosLight);
        const double pdfBrdf = brdf::ggxReflectionPdf(n, v, l, alpha);
        if (cosLight > 0.0 && pdfBrdf > 0.0) {
          const glm::dvec3 f = brdf::evaluateBrdfCos(n, v, l, x.material);
          const double w = strategy == Strategy::Mis ? powerWeight(pdfBrdf, t * t / (area * cosLight)) : 1.0;
          sum += w * f * le / pdfBrdf;
        }
      }
    }
  }
  return sum;
}

glm::dvec3 estimateRect(const ShadingPoint& x, const RectLight& light, const reference::PixelSampler& sampler,
                        int firstPair, Strategy strategy) {
  glm::dvec3 sum(0.0);
  for (int s = 0; s < sampler.spp(); ++s)
    sum += sampleRect(x, light, glm::dvec2(sampler.get(s, firstPair)), glm::dvec2(sampler.get(s, firstPair + 1)),
                      strategy);
  return sum / double(sampler.spp());
}

Image renderArealightReference(const Scene& scene, const SurfaceData& s, const ReferenceJob& job) {
  const std::size_t n = s.pixelCount();
  if (s.position.size() != n || s.shadingNormal.size() != n || s.valid.size() != n || s.baseColor.size() != n ||
      s.metallic.size() != n || s.roughness.size() != n)
    throw Error(ExitCode::Internal, "arealight reference: surface data without the G-buffer's material per pixel");
  const std::vector<RectLight> lights = rectLights(scene);
  const glm::dvec3 eye(scene.camera.position);

  Image image(s.width, s.height, 3);
  image.mask.assign(n, 0.0f);
  reference::ProgressBar progress("reference arealight", n, job.progress);
  std::atomic<bool> cancelled{false};
  tbb::task_arena arena(job.threads > 0 ? int(job.threads) : tbb::task_arena::automatic);
  arena.execute([&] {
  tbb::parallel_for(tbb::blocked_range<int>(0, s.height, 1), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      if (job.cancel && job.cancel->load(std::memory_order_relaxed)) {
        cancelled.store(true, std::memory_order_relaxed);
        return;
      }
      for (int xx = 0; xx < s.width; ++xx) {
        const std::size_t i = std::size_t(y) * std::size_t(s.width) + std::size_t(xx);
        if (!s.valid[i]) continue;
        image.mask[i] = 1.0f;
        ShadingPoint x;
        x.position = glm::dvec3(s.position[i]);
        x.normal = glm::normalize(glm::dvec3(s.shadingNormal[i]));
        x.toViewer = glm::normalize(eye - x.position);
        x.material = {glm::dvec3(s.baseColor[i]), double(s.metallic[i]), double(s.roughness[i])};
        if (!std::isfinite(x.normal.x + x.normal.y + x.normal.z + x.toViewer.x + x.toViewer.y + x.toViewer.z)) continue;
        const reference::PixelSampler sampler(job.seed, i, job.spp, job.stratified);
        glm::dvec3 sum(0.0);
        for (std::size_t k = 0; k < lights.size(); ++k) sum += estimateRect(x, lights[k], sampler, int(2 * k));
        for (int c = 0; c < 3; ++c) image.pixels[i * 3 + std::size_t(c)] = float(sum[c]);
      }
      progress.advance(std::uint64_t(s.width));
    }
  });
  });
  if (cancelled.load()) throw Error(ExitCode::Interrupted, "interrupted");
  progress.finish();
  return image;
}

} // namespace rtlab::area_mc
