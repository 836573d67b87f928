// The sweep's report.html (docs/sweeps.md): one self-contained page, no network and no files
// referenced: an inline SVG chart of error against time with the Pareto front, a table of the
// points with thumbnails and error heat maps as data: URIs, the parameters and the run metadata.
#pragma once
#include "app/sweep_plan.h"
#include "image/metrics.h"

#include <string>
#include <vector>

namespace rtlab {

struct SweepResult {
  const SweepPoint* point = nullptr;
  double ms = 0, frameMs = 0;
  std::string timing;
  Metrics metrics;
  std::string aovPng, heatPng; // thumbnails of the stage AOV and its error heat map, base64-encoded PNG
};

struct SweepReportInfo {
  std::string renderer, backend, timing; // from the points' stats (distinct values joined)
  double heatScale = 1.0;                // |error| mapped to the top of the heat maps
  std::vector<std::pair<std::string, std::string>> references; // (hash, base64 PNG thumbnail)
};

std::string sweepReportHtml(const SweepPlan& plan, const std::vector<SweepResult>& results,
                            const SweepReportInfo& info);

// The inline SVG chart alone: x = ms (log axis when every ms > 0 and they span 10x or more),
// y = rmse; one colour per technique, the Pareto front as a step line with its points ringed.
std::string sweepChartSvg(const SweepPlan& plan, const std::vector<SweepResult>& results);

// "%.6g", or "" when not finite.
std::string formatMetric(double v);

} // namespace rtlab
