#include "reference/transparency_reference.h"

#include "reference/reference_registry.h"
#include "util/error.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

namespace rtlab {

Image compositeOver(const CapturedFragments& captured, const Image& opaque, const std::atomic<bool>* cancel) {
  const int w = captured.width, h = captured.height;
  if (opaque.width != w || opaque.height != h || opaque.channels != 3)
    throw Error(ExitCode::Internal, "transparency reference: the opaque colour is " + std::to_string(opaque.width) + "x" +
                                        std::to_string(opaque.height) + "x" + std::to_string(opaque.channels) +
                                        ", the capture " + std::to_string(w) + "x" + std::to_string(h) + "x3");
  // Bucket the fragments by pixel (a counting sort), then sort each pixel's list by depth.
  const std::size_t pixels = std::size_t(w) * std::size_t(h);
  std::vector<std::uint32_t> start(pixels + 1, 0);
  for (const CapturedFragment& f : captured.fragments) {
    if (f.x >= std::uint32_t(w) || f.y >= std::uint32_t(h))
      throw Error(ExitCode::Internal, "transparency reference: a captured fragment at (" + std::to_string(f.x) + ", " +
                                          std::to_string(f.y) + ") lies outside the frame");
    ++start[std::size_t(f.y) * std::size_t(w) + f.x + 1];
  }
  for (std::size_t i = 0; i < pixels; ++i) start[i + 1] += start[i];
  std::vector<std::uint32_t> order(captured.fragments.size());
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::uint32_t i = 0; i < order.size(); ++i) {
      const CapturedFragment& f = captured.fragments[i];
      order[next[std::size_t(f.y) * std::size_t(w) + f.x]++] = i;
    }
  }
  auto farther = [&](std::uint32_t a, std::uint32_t b) {
    const CapturedFragment& p = captured.fragments[a];
    const CapturedFragment& q = captured.fragments[b];
    if (p.depth != q.depth) return p.depth > q.depth;
    if (p.alpha != q.alpha) return p.alpha < q.alpha;
    if (p.r != q.r) return p.r < q.r;
    if (p.g != q.g) return p.g < q.g;
    return p.b < q.b;
  };

  Image out(w, h, 3);
  out.mask.assign(pixels, 0.0f);
  for (int y = 0; y < h; ++y) {
    if (cancel && cancel->load(std::memory_order_relaxed)) throw Error(ExitCode::Interrupted, "interrupted");
    for (int x = 0; x < w; ++x) {
      const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
      auto first = order.begin() + start[p], last = order.begin() + start[p + 1];
      std::sort(first, last, farther); // back to front
      double c[3] = {opaque.at(x, y, 0), opaque.at(x, y, 1), opaque.at(x, y, 2)};
      for (auto it = first; it != last; ++it) {
        const CapturedFragment& f = captured.fragments[*it];
        const double a = f.alpha;
        c[0] = a * double(f.r) + (1.0 - a) * c[0];
        c[1] = a * double(f.g) + (1.0 - a) * c[1];
        c[2] = a * double(f.b) + (1.0 - a) * c[2];
      }
      for (int k = 0; k < 3; ++k) out.at(x, y, k) = float(c[k]);
      const bool covered = (opaque.hasMask() ? opaque.mask[p] > 0.5f : true) || first != last;
      out.mask[p] = covered ? 1.0f : 0.0f;
    }
  }
  return out;
}

void registerTransparencyReference(ReferenceRegistry& registry) {
  ReferenceEntry e;
  e.aov = "transparency";
  e.stage = "transparency";
  e.help = "exact Over of every transparent fragment, sorted per pixel, onto the opaque colour";
  e.channels = 3;
  e.inputs = {FrameInput::TransparentFragments};
  // The layers' shading depends on the lights and the camera; the opaque colour on every key before
  // the stage (referenceDependsOnKey).
  e.keys = {"light<N>.", "camera."};
  e.compute = [](const ReferenceFrame& frame, ReferenceStats& stats) {
    const auto begin = std::chrono::steady_clock::now();
    Image out = compositeOver(frame.transparentFragments(), frame.opaqueColor(), frame.cancelFlag());
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    return out;
  };
  registry.add(std::move(e));
}

} // namespace rtlab
