// `rtlab sweep --collect DIR`: merges the finished points of a sweep into DIR/results.csv
// (docs/contract.md columns) and DIR/report.html, and writes each point's error heat map.
#pragma once
#include "app/sweep_plan.h"
#include "app/sweep_report.h"

#include <string>

namespace rtlab {

struct SweepCollection {
  SweepPlan plan;
  std::vector<SweepResult> results; // in point order; each points into plan.points
  SweepReportInfo info;
  SweepCollection() = default;
  SweepCollection(const SweepCollection&) = delete; // results point into plan
  SweepCollection& operator=(const SweepCollection&) = delete;
  SweepCollection(SweepCollection&&) = default; // a moved vector keeps its elements in place
  SweepCollection& operator=(SweepCollection&&) = default;
};

// Writes DIR/results.csv, DIR/report.html, each point's error.png and aov.png, each reference's
// PNG, and the "measured" object of DIR/sweep.json (renderer, backend, timing, concurrency).
// Error(Input) naming what is missing when a point or a reference has not finished.
SweepCollection collectSweep(const std::string& dir);

// The results.csv header for a plan: technique, each varied key, ms, frame_ms, rmse, psnr,
// ssim, flip, timing.
std::vector<std::string> sweepCsvHeader(const SweepPlan& plan);

} // namespace rtlab
