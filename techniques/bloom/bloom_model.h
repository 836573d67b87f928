// What bloom computes, on the CPU (docs/contract.md "Bloom"; techniques/bloom/README.md): the
// soft-knee bright pass, the point-spread function (a mean of Gaussians of widths sigma * 2^k),
// the exact convolution that `rtlab reference --aov bloom` writes, and the plan of the mip
// method's chain (how many levels, and the weight of each so that its PSF approximates the
// declared one). The technique, its reference and its tests all use these definitions.
#pragma once
#include "image/image.h"
#include "params/param_set.h"

#include <atomic>

#include <cstdint>
#include <vector>

namespace rtlab::bloom {

struct Definition {
  float threshold = 1.0f;   // T, luma
  float knee = 0.5f;        // a fraction of T: K = knee * T
  float intensity = 0.1f;
  float sigma = 2.0f;       // pixels of the frame, octave 0
  int octaves = 5;          // n
  bool hardCut = false;     // the hard threshold luma > T ? c : 0 instead of the soft knee
};

// The definition a frame's bloom.* keys give.
Definition definitionFrom(const ParamSet& params);

inline constexpr float kLumaR = 0.2126f, kLumaG = 0.7152f, kLumaB = 0.0722f;

// The factor w of bright(c) = c * w for a colour of luma `luma` (0 <= w <= 1).
float brightWeight(float luma, const Definition& d);

// Octave k's Gaussian width: sigma * 2^k.
double octaveSigma(const Definition& d, int k);
// The truncation radius of a Gaussian of width `sigma`: ceil(4 sigma) taps each side.
int gaussianRadius(double sigma);
// 1 / sum_{i=-R..R} exp(-i^2 / (2 sigma^2)): the renormalisation of the truncated 1D kernel (the 2D
// kernel is the product of two, so its sum is 1 too).
double gaussianNormalisation(double sigma, int radius);

// What the bright pass did to the colour it was given.
struct InputCounts {
  std::uint64_t nonFinite = 0; // pixels with a NaN or infinite channel, replaced by 0
};

// bright(c) per pixel of a 3-channel image, after replacing non-finite pixels by 0 (counted).
Image brightPass(const Image& color, const Definition& d, InputCounts* counts = nullptr);
// intensity * (bright ⊛ PSF), outside the frame black: the exact value of the `bloom` AOV, computed
// separably per octave in double precision on `threads` threads (0: the hardware's). Mask 1.
// When `cancel` is set (checked every row), it stops within a row of work per thread and throws
// Error(Interrupted).
Image convolve(const Image& bright, const Definition& d, unsigned threads = 0,
               const std::atomic<bool>* cancel = nullptr);

// ---- the mip method ---------------------------------------------------------------------------

// The width (pixels of the frame) of the blur that mip level j applies to the bright pass on its
// way down (13-tap filter per level) and back up (3x3 tent per level, bilinear 2x upsampling):
// variances add, sigma_j^2 = 1.5 (4^j - 1); level 0 is the bright pass itself (a pixel's box:
// variance 1/12 per axis).
double mipLevelSigma(int level);
// The deepest level a frame allows: each level halves the size, and the last is at least 1 texel.
int maxMipLevels(int width, int height);

struct MipPlan {
  int levels = 0;              // L: levels 1..L below the full-resolution bright pass
  std::vector<float> weights;  // a_0..a_L, summing to 1: the share of each level in the PSF
  int cappedOctaves = 0;       // octaves wider than the deepest level the frame allows
};
// The levels go down until one is as wide as the widest octave (or the frame allows no more); the
// weights are the least-squares fit, in 2D L2 with each level's PSF modelled as a Gaussian of width
// mipLevelSigma, of the declared mean of Gaussians, under a_j >= 0 and sum a_j = 1 (energy kept).
MipPlan planMipChain(const Definition& d, int width, int height);

} // namespace rtlab::bloom
