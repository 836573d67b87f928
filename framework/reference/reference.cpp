// The CPU reference (DESIGN.md "Ground truth and metrics", docs/measuring.md): Embree 3 ray
// casting over the scene's opaque triangles, from the frame's own surface points, in parallel
// over 16x16 tiles with TBB. Every pixel's samples come from a pattern keyed by (seed, pixel), so
// the image does not depend on how tiles are scheduled or on the number of threads.
#include "reference/reference.h"

#include "reference/embree_scene.h"
#include "reference/estimators.h"
#include "reference/progress.h"
#include "reference/sampling.h"
#include "util/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <atomic>
#include <chrono>
#include <cmath>

namespace rtlab {
namespace {

constexpr int kTile = 16;

enum class Quantity { Visibility, Ao, Indirect };

Quantity parseQuantity(const std::string& aov) {
  if (aov == "visibility") return Quantity::Visibility;
  if (aov == "ao") return Quantity::Ao;
  if (aov == "indirect") return Quantity::Indirect;
  usageError("the reference has no AOV '" + aov + "' (choices: visibility, ao, indirect)");
}

bool usable(const glm::vec3& n) {
  const float l2 = glm::dot(n, n);
  return std::isfinite(l2) && l2 > 0.25f;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The pixel's point with unit normals; false when the G-buffer holds nothing usable there.
bool surfacePoint(const SurfaceData& s, std::size_t i, const glm::vec3& eye, reference::SurfacePoint& x) {
  if (!s.valid[i] || !finite(s.position[i])) return false;
  glm::vec3 ng = s.geometricNormal[i], ns = s.shadingNormal[i];
  if (!usable(ng) && !usable(ns)) return false;
  if (!usable(ng)) ng = ns;
  ng = glm::normalize(ng);
  ns = usable(ns) ? glm::normalize(ns) : ng;
  if (glm::dot(ns, ng) < 0.0f) ns = glm::normalize(ns - 1.01f * glm::dot(ns, ng) * ng);
  // The camera saw p along the segment from the eye: free space to start secondary rays in.
  const glm::vec3 d = eye - s.position[i];
  const float d2 = glm::dot(d, d);
  glm::vec3 toViewer = d2 > 0.0f && std::isfinite(d2) ? d / std::sqrt(d2) : ng;
  if (!(glm::dot(toViewer, ng) >= 0.0f)) toViewer = ng; // not seen from the eye: normal offset only
  x = {s.position[i], ng, ns, toViewer};
  return true;
}

void checkSurfaces(const SurfaceData& s) {
  const std::size_t n = s.pixelCount();
  if (s.width < 0 || s.height < 0 || s.position.size() != n || s.geometricNormal.size() != n ||
      s.shadingNormal.size() != n || s.valid.size() != n)
    throw Error(ExitCode::Internal, "reference: surface data of inconsistent size");
}

} // namespace

bool isReferenceAov(const std::string& aov) { return aov == "visibility" || aov == "ao" || aov == "indirect"; }

Image renderReference(const Scene& scene, const SurfaceData& surfaces, const std::string& aov,
                      const ReferenceOptions& options) {
  ReferenceStats stats;
  return renderReference(scene, surfaces, aov, options, stats);
}

Image renderReference(const Scene& scene, const SurfaceData& surfaces, const std::string& aov,
                      const ReferenceOptions& options, ReferenceStats& stats) {
  const Quantity quantity = parseQuantity(aov);
  if (options.spp < kReferenceMinSpp || options.spp > kReferenceMaxSpp)
    usageError("--spp " + std::to_string(options.spp) + " is out of range " + std::to_string(kReferenceMinSpp) +
               ".." + std::to_string(kReferenceMaxSpp));
  if (quantity == Quantity::Ao && !(options.aoRadius > 0.0f))
    usageError("ao.radius must be positive for the ao reference");
  if (quantity == Quantity::Visibility && scene.lights.empty())
    usageError("the visibility reference needs a light 0; the scene has no light");
  checkSurfaces(surfaces);

  const auto start = std::chrono::steady_clock::now();
  const reference::EmbreeScene tracer(scene);
  const reference::EstimatorContext ctx{scene, tracer, options.aoRadius};

  const int channels = quantity == Quantity::Indirect ? 3 : 1;
  Image image(surfaces.width, surfaces.height, channels);
  image.mask.assign(surfaces.pixelCount(), 0.0f);
  const int tilesX = (surfaces.width + kTile - 1) / kTile, tilesY = (surfaces.height + kTile - 1) / kTile;
  const int tiles = tilesX * tilesY;
  reference::ProgressBar progress("reference " + aov, surfaces.pixelCount(), options.progress);
  std::atomic<std::uint64_t> rays{0};

  tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& range) {
    std::uint64_t tileRays = 0, pixels = 0;
    for (int tile = range.begin(); tile < range.end(); ++tile) {
      const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
      const int x1 = std::min(x0 + kTile, surfaces.width), y1 = std::min(y0 + kTile, surfaces.height);
      for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
          const std::size_t i = std::size_t(y) * std::size_t(surfaces.width) + std::size_t(x);
          ++pixels;
          reference::SurfacePoint point;
          if (!surfacePoint(surfaces, i, scene.camera.position, point)) continue; // background: 0, mask 0
          image.mask[i] = 1.0f;
          const reference::PixelSampler sampler(options.seed, i, options.spp, options.stratified);
          switch (quantity) {
          case Quantity::Visibility:
            image.pixels[i] = reference::estimateVisibility(ctx, point, sampler, tileRays);
            break;
          case Quantity::Ao:
            image.pixels[i] = reference::estimateAo(ctx, point, sampler, tileRays);
            break;
          case Quantity::Indirect: {
            const glm::vec3 e = reference::estimateIndirect(ctx, point, sampler, tileRays);
            image.pixels[i * 3] = e.x;
            image.pixels[i * 3 + 1] = e.y;
            image.pixels[i * 3 + 2] = e.z;
            break;
          }
          }
        }
      }
    }
    rays.fetch_add(tileRays, std::memory_order_relaxed);
    progress.advance(pixels);
  }, tbb::simple_partitioner());
  progress.finish();

  stats.rays = rays.load();
  stats.triangles = tracer.triangleCount();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return image;
}

} // namespace rtlab
