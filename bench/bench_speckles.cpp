// Umbra speckle share (image/umbra_speckles.h, techniques/vssm/README.md "Speckles"): for each
// visibility image, the share of the reference's deep umbra (reference exactly 0, eroded by 3 px)
// where the visibility exceeds 0.05. Images from `rtlab render --aov visibility` and
// `rtlab reference --aov visibility` of the same frame (.exr or .pfm; bench/speckles.sh).
//   rtlab_bench_speckles REFERENCE VISIBILITY [VISIBILITY...]
#include "image/image.h"
#include "image/umbra_speckles.h"
#include "util/error.h"

#include <cstdio>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: rtlab_bench_speckles REFERENCE VISIBILITY [VISIBILITY...]\n");
    return 2;
  }
  try {
    const rtlab::Image reference = rtlab::readImage(argv[1]);
    for (int i = 2; i < argc; ++i) {
      const rtlab::UmbraSpeckles s = rtlab::measureUmbraSpeckles(reference, rtlab::readImage(argv[i]));
      std::printf("%-40s umbra %7zu  speckles %6zu  share %.3f%%\n", argv[i], s.umbraPixels, s.speckles,
                  100.0 * s.share());
    }
  } catch (const rtlab::Error& e) {
    std::fprintf(stderr, "rtlab: error: %s\n", e.what());
    return int(e.code());
  }
  return 0;
}
