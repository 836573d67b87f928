// The sweep's report.html (docs/sweeps.md): one self-contained page, nothing to fetch: how the
// times were taken (and a warning when they are not to be trusted), an inline SVG chart of error
// against time with the Pareto front, the command that reproduces the sweep, notes, a table of
// the points with thumbnails and error heat maps as data: URIs (linked to the full-size images
// in the sweep folder by relative paths), the parameters and the run metadata. The showcase's
// atlas reuses the chart, the heat-map scale and the warning.
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
  std::string aovPng, heatPng;   // thumbnails of the stage AOV and its error heat map, base64-encoded PNG
  std::string aovFile, heatFile; // the full-size PNGs, relative to the sweep folder
};

struct SweepReferenceShown {
  std::string hash, png, file; // base64 PNG thumbnail; full-size PNG relative to the sweep folder
};

struct SweepReportInfo {
  std::string renderer, backend, timing; // from the points' stats (distinct values joined)
  bool software = false;                 // a point ran on a software rasterizer (llvmpipe, ...)
  int concurrentPoints = 0;              // points whose measured frames overlapped another point's
  double heatScale = 1.0;                // |error| mapped to the top of the heat maps (above: saturated)
  double heatMax = 0;                    // the largest |error| of the sweep
  std::string colorBarPng;               // base64 PNG: 0 .. heatScale
  std::vector<SweepReferenceShown> references;
};

// The warning the page shows near the chart, "" when none: the points' timings were taken with
// more than one point running at a time (--jobs N > 1, or measured frames that overlapped) on a
// software rasterizer, where the points share the CPU cores that draw them.
std::string sweepTimingWarning(const SweepPlan& plan, const SweepReportInfo& info);
// How the plan's reference was computed, for captions: "64 spp" for a sampling reference, "exact"
// for one that does not sample (bloom's convolution).
std::string referenceSamplesText(const SweepPlan& plan);

// Notes that explain a sweep's results from the techniques' declared parameters, "" when none:
// a technique whose own filter widths are in shadow-map texels, swept over shadow.resolution.
std::vector<std::string> sweepNotes(const SweepPlan& plan);

std::string sweepReportHtml(const SweepPlan& plan, const std::vector<SweepResult>& results,
                            const SweepReportInfo& info);

// The inline SVG chart alone: x = ms (log axis when every ms > 0 and they span 10x or more),
// y = rmse; one colour per technique, each technique's points joined in parameter order and
// labelled with their values, the legend beside the plot, the Pareto front as a step line with
// its points ringed. Each point links to `linkPrefix` + its index (the report's rows by default;
// another page links to the report's rows by a relative path).
std::string sweepChartSvg(const SweepPlan& plan, const std::vector<SweepResult>& results,
                          const std::string& linkPrefix = "#point-");

// The stylesheet the report's parts need (a page that embeds them appends it to its own).
std::string sweepPageCss();

// The heat maps' colour bar with its scale and rule, as an HTML block.
std::string heatScaleHtml(const SweepPlan& plan, const SweepReportInfo& info);

// "%.6g", or "" when not finite.
std::string formatMetric(double v);

} // namespace rtlab
