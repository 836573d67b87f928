#include "reference/estimators.h"

#include "reference/light_model.h"
#include "reference/texture_sample.h"

#include <bit>
#include <limits>

namespace rtlab::reference {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// A shadow ray from `start` toward a point of `light` chosen by u, added to `packet` unless the
// answer is known without tracing: Hidden when the light point is below the tangent plane of
// `horizon` (the surface itself hides it), Visible when it is closer than any surface can be.
enum class Shadow { Hidden, Visible, Traced };
Shadow addShadowRay(EmbreeScene::Packet& packet, const Light& light, const RayStart& start,
                    const glm::vec3& horizon, glm::vec2 u) {
  const ShadowRay ray = shadowRayToLight(light, start.origin, u);
  if (!(glm::dot(ray.direction, horizon) > 0.0f)) return Shadow::Hidden;
  if (!(ray.tfar > start.tnear)) return Shadow::Visible;
  packet.add(start.origin, ray.direction, start.tnear, ray.tfar);
  return Shadow::Traced;
}

// Direct irradiance at up to 8 ray hits (bit set in hitMask) from every light, each shadowed by
// one ray; pair index 1 + i of the pixel's sampler picks light i's point for sample samples[k].
// Adds albedo[k] * E_direct(hit k) to sum.
void addReflected(const EstimatorContext& ctx, const RayHit* hits, const glm::vec3* incoming, const int* samples,
                  unsigned hitMask, const PixelSampler& sampler, glm::vec3& sum, std::uint64_t& rays) {
  glm::vec3 albedo[8];
  RayStart starts[8];
  for (int k = 0; k < 8; ++k) {
    if (!(hitMask >> k & 1u)) continue;
    albedo[k] = surfaceInputs(ctx.scene, hits[k].material, hits[k].uv).diffuseAlbedo();
    if (!(albedo[k].x > 0.0f || albedo[k].y > 0.0f || albedo[k].z > 0.0f)) hitMask &= ~(1u << k);
    else starts[k] = rayStart(hits[k].shadingPoint, hits[k].geometricNormal, -incoming[k]);
  }
  for (std::size_t i = 0; i < ctx.lights.size() && hitMask != 0; ++i) {
    const Light& light = ctx.lights[i];
    EmbreeScene::Packet packet;
    glm::vec3 contribution[8];
    for (int k = 0; k < 8; ++k) {
      if (!(hitMask >> k & 1u)) continue;
      glm::vec3 toLight;
      const glm::vec3 irradiance = lightIrradiance(light, hits[k].position, toLight);
      const float cosine = glm::dot(hits[k].shadingNormal, toLight);
      if (!(cosine > 0.0f) || !(irradiance.x > 0.0f || irradiance.y > 0.0f || irradiance.z > 0.0f)) continue;
      const glm::vec3 c = albedo[k] * irradiance * cosine;
      const int before = packet.count;
      const Shadow shadow = addShadowRay(packet, light, starts[k], hits[k].shadingNormal,
                                         sampler.get(samples[k], 1 + int(i)));
      if (shadow == Shadow::Visible) sum += c;
      if (shadow == Shadow::Traced) contribution[before] = c;
    }
    if (packet.count == 0) continue;
    rays += std::uint64_t(packet.count);
    const unsigned occluded = ctx.tracer.occluded(packet);
    for (int j = 0; j < packet.count; ++j)
      if (!(occluded >> j & 1u)) sum += contribution[j];
  }
}

} // namespace

float estimateVisibility(const EstimatorContext& ctx, const SurfacePoint& x, const PixelSampler& sampler,
                         std::uint64_t& rays) {
  if (ctx.lights.empty()) return 0.0f;
  const Light& light = ctx.lights.front();
  const RayStart start = rayStart(x.shadingPoint, x.geometricNormal, x.toViewer);
  const int n = lightHasExtent(light) ? sampler.spp() : 1;
  int visible = 0;
  EmbreeScene::Packet packet;
  const auto flush = [&] {
    visible += packet.count - std::popcount(ctx.tracer.occluded(packet));
    rays += std::uint64_t(packet.count);
    packet.count = 0;
  };
  for (int s = 0; s < n; ++s) {
    if (addShadowRay(packet, light, start, x.smoothNormal, sampler.get(s, 0)) == Shadow::Visible) ++visible;
    if (packet.count == 8) flush();
  }
  if (packet.count > 0) flush();
  return float(visible) / float(n);
}

float estimateAo(const EstimatorContext& ctx, const SurfacePoint& x, const PixelSampler& sampler,
                 std::uint64_t& rays) {
  const RayStart start = rayStart(x.shadingPoint, x.geometricNormal, x.toViewer);
  const Frame frame(x.shadingNormal);
  int open = 0;
  EmbreeScene::Packet packet;
  const auto flush = [&] {
    open += packet.count - std::popcount(ctx.tracer.occluded(packet));
    rays += std::uint64_t(packet.count);
    packet.count = 0;
  };
  for (int s = 0; s < sampler.spp(); ++s) {
    const glm::vec3 w = frame.toWorld(squareToCosineHemisphere(sampler.get(s, 0)));
    if (!(glm::dot(w, x.smoothNormal) > 0.0f)) continue;
    packet.add(start.origin, w, start.tnear, ctx.aoRadius);
    if (packet.count == 8) flush();
  }
  if (packet.count > 0) flush();
  return float(open) / float(sampler.spp());
}

glm::vec3 estimateIndirect(const EstimatorContext& ctx, const SurfacePoint& x, const PixelSampler& sampler,
                           std::uint64_t& rays) {
  const RayStart start = rayStart(x.shadingPoint, x.geometricNormal, x.toViewer);
  const Frame frame(x.shadingNormal);
  glm::vec3 sum(0.0f);
  EmbreeScene::Packet packet;
  int samples[8];
  RayHit hits[8];
  const auto flush = [&] {
    rays += std::uint64_t(packet.count);
    const unsigned hitMask = ctx.tracer.intersect(packet, hits);
    // pdf cos/pi cancels the cosine and the 1/pi of the diffuse BRDF: each sample adds
    // albedo * E_direct(hit).
    if (hitMask != 0) addReflected(ctx, hits, packet.direction, samples, hitMask, sampler, sum, rays);
    packet.count = 0;
  };
  for (int s = 0; s < sampler.spp(); ++s) {
    const glm::vec3 w = frame.toWorld(squareToCosineHemisphere(sampler.get(s, 0)));
    if (!(glm::dot(w, x.smoothNormal) > 0.0f)) continue;
    samples[packet.count] = s;
    packet.add(start.origin, w, start.tnear, kInfinity);
    if (packet.count == 8) flush();
  }
  if (packet.count > 0) flush();
  return sum / float(sampler.spp());
}

} // namespace rtlab::reference
