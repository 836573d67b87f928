// `rtlab sweep --collect DIR`: merges the finished points of a sweep into DIR/results.csv
// (CONTRACT.md columns) and DIR/report.html, and writes each point's error heat map.
#pragma once
#include "app/sweep_plan.h"

#include <string>

namespace rtlab {

// Error(Input) naming what is missing when a point or a reference has not finished.
void collectSweep(const std::string& dir);

// The results.csv header for a plan: technique, each varied key, ms, frame_ms, rmse, psnr,
// ssim, flip, timing.
std::vector<std::string> sweepCsvHeader(const SweepPlan& plan);

} // namespace rtlab
