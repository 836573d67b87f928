// `rtlab_bench_reference --progressive` (docs/progressive-reference.md, "Measured"): how soon the
// viewer's progressive reference shows something and reaches 16 and 64 spp, and what averaging
// independent batches costs in error against one stratified pass of the same sample count.
#pragma once
#include "app/frame_options.h"

#include <string>
#include <vector>

// Per AOV: time to the first snapshot, to 16 and 64 spp, and to the first snapshot of a restart
// that reuses the BVH; single-pass times at 16 and 64 spp on as many threads; RMSE of the
// progressive mean and of the single pass, each against a truthSpp single pass of another seed;
// the time of computeLiveMetrics on one frame (the single 16 spp pass against the 64 spp mean).
int runProgressiveBench(const rtlab::ResolvedFrame& frame, const std::vector<std::string>& aovs, int threads,
                        int truthSpp);
