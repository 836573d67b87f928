// One batch of the CPU reference over a range of tiles (reference_batch.h): the per-pixel loop of
// renderReference, shared with the progressive reference.
#include "reference/reference_batch.h"

#include "reference/reference.h"
#include "util/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <cmath>

namespace rtlab::reference {
namespace {

bool usable(const glm::vec3& n) {
  const float l2 = glm::dot(n, n);
  return std::isfinite(l2) && l2 > 0.25f;
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The pixel's point with unit normals; false when the G-buffer holds nothing usable there.
bool surfacePoint(const SurfaceData& s, std::size_t i, const glm::vec3& eye, SurfacePoint& x) {
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
  // The shadow terminator rule's point and normal; without them, the flat surface's.
  glm::vec3 shadingPoint = s.position[i], nv = ng;
  if (!s.shadingPoint.empty() && finite(s.shadingPoint[i])) shadingPoint = s.shadingPoint[i];
  if (!s.smoothNormal.empty() && usable(s.smoothNormal[i])) nv = glm::normalize(s.smoothNormal[i]);
  if (glm::dot(nv, ng) < 0.0f) nv = glm::normalize(nv - 1.01f * glm::dot(nv, ng) * ng);
  x = {s.position[i], ng, ns, toViewer, shadingPoint, nv};
  return true;
}

// One tile's pixels; returns the pixels visited and adds the rays cast to `rays`.
std::uint64_t renderTile(const EstimatorContext& ctx, const SurfaceData& surfaces, const BatchSpec& spec, int tile,
                         Image& image, std::uint64_t& rays) {
  const int tilesX = (surfaces.width + kTileSize - 1) / kTileSize;
  const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
  const int x1 = std::min(x0 + kTileSize, surfaces.width), y1 = std::min(y0 + kTileSize, surfaces.height);
  std::uint64_t pixels = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(surfaces.width) + std::size_t(x);
      ++pixels;
      SurfacePoint point;
      if (!surfacePoint(surfaces, i, spec.eye, point)) continue; // background: left to the caller
      image.mask[i] = 1.0f;
      const PixelSampler sampler(spec.seed, i, spec.spp, spec.stratified);
      switch (spec.quantity) {
      case Quantity::Visibility:
        image.pixels[i] = estimateVisibility(ctx, point, sampler, rays);
        break;
      case Quantity::Ao:
        image.pixels[i] = estimateAo(ctx, point, sampler, rays);
        break;
      case Quantity::Indirect: {
        const glm::vec3 e = estimateIndirect(ctx, point, sampler, rays);
        image.pixels[i * 3] = e.x;
        image.pixels[i * 3 + 1] = e.y;
        image.pixels[i * 3 + 2] = e.z;
        break;
      }
      }
    }
  }
  return pixels;
}

} // namespace

Quantity parseQuantity(const std::string& aov) {
  if (aov == "visibility") return Quantity::Visibility;
  if (aov == "ao") return Quantity::Ao;
  if (aov == "indirect") return Quantity::Indirect;
  usageError("the reference has no AOV '" + aov + "' (choices: visibility, ao, indirect)");
}

int channelCount(Quantity quantity) {
  return quantity == Quantity::Indirect ? 3 : 1;
}

void checkReferenceJob(Quantity quantity, int spp, const std::string& sppName, float aoRadius,
                       const std::vector<Light>& lights, const SurfaceData& s) {
  if (spp < kReferenceMinSpp || spp > kReferenceMaxSpp)
    usageError(sppName + " " + std::to_string(spp) + " is out of range " + std::to_string(kReferenceMinSpp) + ".." +
               std::to_string(kReferenceMaxSpp));
  if (quantity == Quantity::Ao && !(aoRadius > 0.0f)) usageError("ao.radius must be positive for the ao reference");
  if (quantity == Quantity::Visibility && lights.empty())
    usageError("the visibility reference needs a light 0; the scene has no light");
  const std::size_t n = s.pixelCount();
  if (s.width < 0 || s.height < 0 || s.position.size() != n || s.geometricNormal.size() != n ||
      s.shadingNormal.size() != n || s.valid.size() != n || (!s.shadingPoint.empty() && s.shadingPoint.size() != n) ||
      (!s.smoothNormal.empty() && s.smoothNormal.size() != n))
    throw Error(ExitCode::Internal, "reference: surface data of inconsistent size");
}

int tileCount(int width, int height) {
  return ((width + kTileSize - 1) / kTileSize) * ((height + kTileSize - 1) / kTileSize);
}

bool renderBatch(const EstimatorContext& ctx, const SurfaceData& surfaces, const BatchSpec& spec, Image& image,
                 int firstTile, int lastTile, const std::atomic<bool>* cancel, std::atomic<std::uint64_t>& rays,
                 ProgressBar* progress) {
  std::atomic<bool> cancelled{false};
  tbb::parallel_for(
      tbb::blocked_range<int>(firstTile, lastTile, 1),
      [&](const tbb::blocked_range<int>& range) {
        std::uint64_t tileRays = 0, pixels = 0;
        for (int tile = range.begin(); tile < range.end(); ++tile) {
          if (cancel && cancel->load(std::memory_order_relaxed)) {
            cancelled.store(true, std::memory_order_relaxed);
            break;
          }
          pixels += renderTile(ctx, surfaces, spec, tile, image, tileRays);
        }
        rays.fetch_add(tileRays, std::memory_order_relaxed);
        if (progress) progress->advance(pixels);
      },
      tbb::simple_partitioner());
  return !cancelled.load();
}

} // namespace rtlab::reference
