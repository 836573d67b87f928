// The CPU reference (docs/measuring.md): Embree 3 ray
// casting over the scene's opaque triangles, from the frame's own surface points, in parallel
// over 16x16 tiles with TBB: one batch of every tile (reference_batch.h). Every pixel's samples
// come from a pattern keyed by (seed, pixel), so the image does not depend on how tiles are
// scheduled or on the number of threads.
#include "reference/reference.h"

#include "reference/embree_scene.h"
#include "reference/estimators.h"
#include "reference/progress.h"
#include "reference/reference_batch.h"

#include <atomic>
#include <chrono>

namespace rtlab {

bool isReferenceAov(const std::string& aov) {
  return aov == "visibility" || aov == "ao" || aov == "indirect";
}

Image renderReference(const Scene& scene, const SurfaceData& surfaces, const std::string& aov,
                      const ReferenceOptions& options) {
  ReferenceStats stats;
  return renderReference(scene, surfaces, aov, options, stats);
}

Image renderReference(const Scene& scene, const SurfaceData& surfaces, const std::string& aov,
                      const ReferenceOptions& options, ReferenceStats& stats) {
  const reference::Quantity quantity = reference::parseQuantity(aov);
  reference::checkReferenceJob(quantity, options.spp, "--spp", options.aoRadius, scene.lights, surfaces);

  const auto start = std::chrono::steady_clock::now();
  const reference::EmbreeScene tracer(scene);
  const reference::EstimatorContext ctx{scene, tracer, options.aoRadius, scene.lights};

  Image image(surfaces.width, surfaces.height, reference::channelCount(quantity));
  image.mask.assign(surfaces.pixelCount(), 0.0f);
  reference::ProgressBar progress("reference " + aov, surfaces.pixelCount(), options.progress);
  std::atomic<std::uint64_t> rays{0};
  const reference::BatchSpec spec{quantity, options.spp, options.seed, options.stratified, scene.camera.position};
  reference::renderBatch(ctx, surfaces, spec, image, 0, reference::tileCount(surfaces.width, surfaces.height), nullptr,
                         rays, &progress);
  progress.finish();

  stats.rays = rays.load();
  stats.triangles = tracer.triangleCount();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return image;
}

} // namespace rtlab
