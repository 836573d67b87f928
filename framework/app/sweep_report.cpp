#include "app/sweep_report.h"

#include "app/html.h"
#include "frame/registry.h"
#include "params/sweep_spec.h"
#include "reference/reference_registry.h"
#include "util/chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace rtlab {
namespace {

// The reference's defining keys in words: "light and camera values, ao.radius".
std::string definingKeysText(const ReferenceEntry& reference) {
  const auto& keys = reference.keys;
  const bool lightAndCamera = std::find(keys.begin(), keys.end(), "light<N>.") != keys.end() &&
                              std::find(keys.begin(), keys.end(), "camera.") != keys.end();
  std::string s = lightAndCamera ? "light and camera values" : "";
  for (const auto& k : keys)
    if (!lightAndCamera || (k != "light<N>." && k != "camera."))
      s += (s.empty() ? "" : ", ") + (k.back() == '.' ? k + "*" : k);
  return s;
}

// Distinguishable on white, and in order of the -t list.
const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

std::string num(double v, const char* fmt = "%.1f") {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string tickLabel(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string image(const std::string& base64, const std::string& alt) {
  if (base64.empty()) return "";
  return "<img class=\"thumb\" src=\"data:image/png;base64," + base64 + "\" alt=\"" + html::escape(alt) + "\">";
}

// A thumbnail linked to its full-size image (a path relative to the page).
std::string linked(const std::string& file, const std::string& inner) {
  if (file.empty() || inner.empty()) return inner;
  return "<a href=\"" + html::escape(file) + "\">" + inner + "</a>";
}

std::string techniqueColor(const SweepPlan& plan, const std::string& technique) {
  for (std::size_t i = 0; i < plan.techniques.size(); ++i)
    if (plan.techniques[i] == technique) return kPalette[i % (sizeof kPalette / sizeof *kPalette)];
  return "#444";
}

// Points beyond this many are labelled on hover and in the table only.
constexpr std::size_t kMaxLabelledPoints = 60;

// The point's values, in --vary order: "512", or "512 / 16" for two axes.
std::string pointLabel(const SweepPoint& p) {
  std::string s;
  for (const auto& [key, value] : p.values) s += (s.empty() ? "" : " / ") + value;
  return s;
}

std::string valueOf(const SweepPoint& p, const std::string& key) {
  for (const auto& [k, v] : p.values)
    if (k == key) return v;
  return "";
}

} // namespace

std::string formatMetric(double v) {
  if (!std::isfinite(v)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string sweepChartSvg(const SweepPlan& plan, const std::vector<SweepResult>& results, const std::string& linkPrefix) {
  // The legend sits right of the plot, so it never covers a point.
  const double width = 900, height = 440, left = 78, legendW = 210, right = 16, top = 20, bottom = 56;
  const double plotW = width - left - legendW - right, plotH = height - top - bottom;
  std::vector<ChartPoint> pts;
  double xmin = INFINITY, xmax = -INFINITY, ymax = 0;
  for (const auto& r : results) {
    pts.push_back({r.ms, r.metrics.rmse});
    if (!std::isfinite(r.ms) || !std::isfinite(r.metrics.rmse)) continue;
    xmin = std::min(xmin, r.ms);
    xmax = std::max(xmax, r.ms);
    ymax = std::max(ymax, r.metrics.rmse);
  }
  if (!(xmin <= xmax)) xmin = 0, xmax = 1;
  const ChartAxis xa = (xmin > 0 && xmax / xmin >= 10) ? niceLogAxis(xmin, xmax) : niceLinearAxis(xmin, xmax);
  const ChartAxis ya = niceLinearAxis(0, ymax > 0 ? ymax : 1e-3);
  auto X = [&](double v) { return left + axisFraction(xa, v) * plotW; };
  auto Y = [&](double v) { return top + (1 - axisFraction(ya, v)) * plotH; };
  auto finite = [&](std::size_t i) { return std::isfinite(pts[i].x) && std::isfinite(pts[i].y); };

  std::string s = "<svg class=\"chart\" role=\"img\" aria-label=\"error against time\" width=\"" + num(width, "%.0f") +
                  "\" height=\"" + num(height, "%.0f") + "\" viewBox=\"0 0 " + num(width, "%.0f") + " " +
                  num(height, "%.0f") + "\">\n";
  s += "<rect x=\"" + num(left) + "\" y=\"" + num(top) + "\" width=\"" + num(plotW) + "\" height=\"" + num(plotH) +
       "\" fill=\"#fcfcfc\" stroke=\"#999\"/>\n";
  // Grid and ticks.
  for (double t : xa.ticks) {
    const double x = X(t);
    s += "<line x1=\"" + num(x) + "\" y1=\"" + num(top) + "\" x2=\"" + num(x) + "\" y2=\"" + num(top + plotH) +
         "\" stroke=\"#e4e4e4\"/>";
    s += "<text x=\"" + num(x) + "\" y=\"" + num(top + plotH + 16) + "\" font-size=\"11\" text-anchor=\"middle\">" +
         tickLabel(t) + "</text>\n";
  }
  for (double t : ya.ticks) {
    const double y = Y(t);
    s += "<line x1=\"" + num(left) + "\" y1=\"" + num(y) + "\" x2=\"" + num(left + plotW) + "\" y2=\"" + num(y) +
         "\" stroke=\"#e4e4e4\"/>";
    s += "<text x=\"" + num(left - 6) + "\" y=\"" + num(y + 4) + "\" font-size=\"11\" text-anchor=\"end\">" +
         tickLabel(t) + "</text>\n";
  }
  s += "<text x=\"" + num(left + plotW / 2) + "\" y=\"" + num(height - 12) +
       "\" font-size=\"12\" text-anchor=\"middle\">ms: the technique's passes, summed (" +
       std::string(xa.log ? "log" : "linear") + " axis)</text>\n";
  s += "<text x=\"16\" y=\"" + num(top + plotH / 2) + "\" font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 16 " +
       num(top + plotH / 2) + ")\">RMSE against the reference</text>\n";

  // Each technique's points joined in parameter order: one line per combination of the other
  // axes' values, along the last axis that applies to it (the grid's fastest).
  for (const auto& technique : plan.techniques) {
    std::map<std::string, std::vector<std::size_t>> lines;
    for (std::size_t i = 0; i < results.size(); ++i) {
      const SweepPoint& p = *results[i].point;
      if (p.technique != technique || p.values.empty() || !finite(i)) continue;
      std::string group;
      for (std::size_t k = 0; k + 1 < p.values.size(); ++k) group += p.values[k].first + "=" + p.values[k].second + " ";
      lines[group].push_back(i); // point order: the line axis' values in their --vary order
    }
    for (const auto& [group, members] : lines) {
      if (members.size() < 2) continue;
      std::string coords;
      for (std::size_t i : members) { // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "literal" + string&&
        if (!coords.empty()) coords += ' ';
        coords += num(X(pts[i].x));
        coords += ',';
        coords += num(Y(pts[i].y));
      }
      s += "<polyline class=\"series\" data-technique=\"" + html::escape(technique) + "\" points=\"" + coords +
           "\" fill=\"none\" stroke=\"" + techniqueColor(plan, technique) + "\" stroke-width=\"1.5\" stroke-opacity=\"0.7\"/>\n";
    }
  }

  // Pareto front: the lowest error for each cost, as a step line to the right edge.
  const auto front = paretoFront(pts);
  if (!front.empty()) {
    std::string d = "M" + num(X(pts[front[0]].x)) + "," + num(Y(pts[front[0]].y));
    for (std::size_t i = 1; i < front.size(); ++i)
      d += " H" + num(X(pts[front[i]].x)) + " V" + num(Y(pts[front[i]].y));
    d += " H" + num(left + plotW);
    s += "<path class=\"pareto\" d=\"" + d + "\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.5\" stroke-dasharray=\"5 3\"/>\n";
    for (std::size_t i : front)
      s += "<circle cx=\"" + num(X(pts[i].x)) + "\" cy=\"" + num(Y(pts[i].y)) +
           "\" r=\"8.5\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.5\"/>\n";
  }
  // Points, each linked to its table row and labelled with its values (beside it while the
  // chart stays readable, always on hover and in the table).
  const bool labelled = results.size() <= kMaxLabelledPoints;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    if (!finite(i)) continue;
    const std::string title = describePoint(*r.point) + ": " + html::formatMs(r.ms) + " ms, RMSE " + formatMetric(r.metrics.rmse);
    s += "<a href=\"" + html::escape(linkPrefix) + std::to_string(r.point->index) + "\"><circle class=\"point\" cx=\"" +
         num(X(pts[i].x)) + "\" cy=\"" + num(Y(pts[i].y)) + "\" r=\"5\" fill=\"" + techniqueColor(plan, r.point->technique) +
         "\" stroke=\"#fff\"><title>" + html::escape(title) + "</title></circle></a>\n";
    if (labelled && !r.point->values.empty())
      s += "<text class=\"label\" x=\"" + num(X(pts[i].x) + 7) + "\" y=\"" + num(Y(pts[i].y) - 7) +
           "\" font-size=\"10\" fill=\"#333\">" + html::escape(pointLabel(*r.point)) + "</text>\n";
  }
  // Legend, outside the plot area.
  const double lx = left + plotW + 16;
  double ly = top + 14;
  s += "<g class=\"legend\">\n";
  for (const auto& t : plan.techniques) {
    const std::string color = techniqueColor(plan, t);
    s += "<line x1=\"" + num(lx) + "\" y1=\"" + num(ly - 4) + "\" x2=\"" + num(lx + 16) + "\" y2=\"" + num(ly - 4) +
         "\" stroke=\"" + color + "\" stroke-width=\"1.5\"/>";
    s += "<circle cx=\"" + num(lx + 8) + "\" cy=\"" + num(ly - 4) + "\" r=\"5\" fill=\"" + color + "\"/>";
    s += "<text x=\"" + num(lx + 22) + "\" y=\"" + num(ly) + "\" font-size=\"12\">" + html::escape(t) + "</text>\n";
    ly += 18;
  }
  s += "<line x1=\"" + num(lx) + "\" y1=\"" + num(ly - 4) + "\" x2=\"" + num(lx + 16) + "\" y2=\"" + num(ly - 4) +
       "\" stroke=\"#222\" stroke-width=\"1.5\" stroke-dasharray=\"5 3\"/>";
  s += "<text x=\"" + num(lx + 22) + "\" y=\"" + num(ly) + "\" font-size=\"12\">Pareto front</text>\n";
  ly += 24;
  if (!plan.axes.empty()) {
    s += "<text x=\"" + num(lx) + "\" y=\"" + num(ly) + "\" font-size=\"11\" fill=\"#555\">labels: values of</text>\n";
    for (const auto& a : plan.axes) {
      ly += 14;
      s += "<text x=\"" + num(lx + 8) + "\" y=\"" + num(ly) + "\" font-size=\"11\" fill=\"#555\">" + html::escape(a.key) +
           "</text>\n";
    }
  }
  s += "</g>\n";
  return s + "</svg>";
}

std::string sweepPageCss() {
  return "img.thumb{max-width:112px;min-width:64px}td img{display:block}td{white-space:nowrap}\n"
         ".scroll{overflow-x:auto}\n"
         ".swatch{display:inline-block;width:.8em;height:.8em;border-radius:50%;margin-right:.4em}\n"
         ".front{color:#222}svg.chart{max-width:100%;height:auto;font-family:system-ui,sans-serif}\n"
         ".warning{border:2px solid #c0392b;background:#fdecea;padding:.6em .9em;color:#611}\n"
         "pre.command{background:#f6f6f6;padding:.5em .8em;white-space:pre-wrap;word-break:break-all}\n"
         ".heatscale{display:flex;align-items:center;gap:.5em;font-size:.85em}"
         "img.colorbar{width:256px;height:12px;border:1px solid #999}\n";
}

std::string sweepTimingWarning(const SweepPlan& plan, const SweepReportInfo& info) {
  if (!info.software || (plan.jobs <= 1 && info.concurrentPoints == 0)) return "";
  std::string why = plan.jobs > 1 ? "with --jobs " + std::to_string(plan.jobs) : "by jobs that ran at the same time";
  if (info.concurrentPoints > 0)
    why += " (" + std::to_string(info.concurrentPoints) + " of " + std::to_string(plan.points.size()) +
           " points measured while another point was)";
  return "These timings were taken " + why + " on a software rasterizer (" + info.renderer +
         "): the points shared the CPU cores that draw them, so their times are inflated and scattered, not the "
         "techniques' own. Re-run with --jobs 1 for timings to report; the errors are unaffected.";
}

std::vector<std::string> sweepNotes(const SweepPlan& plan) {
  std::vector<std::string> notes;
  const bool resolutionVaries =
      std::any_of(plan.axes.begin(), plan.axes.end(), [](const SweepAxis& a) { return a.key == "shadow.resolution"; });
  if (!resolutionVaries) return notes;
  for (const auto& id : plan.techniques) {
    const auto& info = TechniqueRegistry::instance().get(id).info;
    std::string keys;
    for (const auto& spec : info.params)
      if (spec.unit == "texels") keys += (keys.empty() ? "" : ", ") + spec.key;
    if (keys.empty()) continue;
    notes.push_back(id + " declares " + keys + " in shadow-map texels: the same value covers less of the scene at a "
                    "higher shadow.resolution (texels / resolution of the map's extent), so its filter narrows as the "
                    "resolution rises. Against an area light's reference, whose penumbrae do not depend on the map, "
                    "its error can rise with resolution instead of falling (techniques/" + id + "/README.md).");
  }
  return notes;
}

std::string heatScaleHtml(const SweepPlan& plan, const SweepReportInfo& info) {
  return "<div class=\"heatscale\"><span>0</span><img class=\"colorbar\" src=\"data:image/png;base64," +
         info.colorBarPng + "\" alt=\"colour bar from 0 to " + html::escape(formatMetric(info.heatScale)) +
         "\"><span>&ge; " + html::escape(formatMetric(info.heatScale)) + "</span></div>\n<p class=\"meta\">Heat maps: |" +
         html::escape(plan.aov) + " &minus; reference| per pixel (mean over channels) through the magma colormap, on one "
         "scale for every point: 0 (black) to " + html::escape(formatMetric(info.heatScale)) +
         ", the 99th percentile of the nonzero per-pixel errors over all points, rounded up to two digits; " +
         (info.heatMax > info.heatScale ? "larger errors (up to " + html::escape(formatMetric(info.heatMax)) +
                                              " here) are drawn saturated (light yellow)"
                                        : "no error is larger (the largest: " + html::escape(formatMetric(info.heatMax)) + ")") +
         ". Gray: background, not measured. Click a heat map for its full-size image.</p>\n";
}

std::string referenceSamplesText(const SweepPlan& plan) {
  const ReferenceEntry* reference = ReferenceRegistry::instance().findAov(plan.aov);
  return reference && !reference->samples() ? "exact" : std::to_string(plan.spp) + " spp";
}

std::string sweepReportHtml(const SweepPlan& plan, const std::vector<SweepResult>& results,
                            const SweepReportInfo& info) {
  std::string techniques;
  for (const auto& t : plan.techniques) techniques += (techniques.empty() ? "" : ", ") + t;
  std::string body = "<h1>rtlab sweep: " + html::escape(techniques) + " (stage " + html::escape(plan.stage) + ")</h1>\n";
  body += "<p class=\"meta\">" + std::to_string(results.size()) + " points, error of the <code>" + html::escape(plan.aov) +
          "</code> AOV against the reference (" + referenceSamplesText(plan) + ") over the surface pixels.</p>\n";

  // What decided the timings, next to the chart they are plotted on.
  const std::string size = std::to_string(plan.width) + "x" + std::to_string(plan.height);
  const std::string jobs = plan.jobs > 0 ? std::to_string(plan.jobs) + (plan.jobs == 1 ? " (one point at a time)" : " at a time")
                                         : "not recorded (planned with --emit-jobs; run as scheduled)";
  const std::string warmup = std::to_string(sweepWarmupFrames(plan)) + " unmeasured, then " +
                             std::to_string(plan.frames) + " measured (per pass, the median)";
  std::vector<std::vector<std::string>> timingRows = {
      {"jobs", jobs},
      {"frames", warmup},
      {"timing method", info.timing + (plan.timing == "auto" ? " (--timing auto)" : "")},
      {"renderer", info.renderer + (info.software ? " (software rasterizer)" : "")},
      {"backend", info.backend},
      {"size", size},
  };
  body += "<h2 id=\"chart\">Error against time</h2>\n";
  const std::string warning = sweepTimingWarning(plan, info);
  if (!warning.empty()) body += "<p class=\"warning\" role=\"alert\"><strong>Warning:</strong> " + html::escape(warning) + "</p>\n";
  body += "<div class=\"timings\"><p class=\"meta\">How the times were taken:</p>" + html::table({"", ""}, timingRows) + "</div>\n";
  body += sweepChartSvg(plan, results) + "\n";
  body += "<p class=\"meta\">Each technique's points are joined in the order of their values and labelled with them; "
          "ringed points and the dashed step line: the Pareto front (no other point is both faster and more accurate). "
          "Hover a point for its values; click it for its row.</p>\n";
  if (!plan.command.empty())
    body += "<p class=\"meta\">Reproduce (given in <code>" + html::escape(plan.cwd) + "</code>; add <code>--force</code> "
            "to replace this folder's sweep):</p>\n<pre class=\"command\"><code>" + html::escape(plan.command) + "</code></pre>\n";
  const auto notes = sweepNotes(plan);
  if (!notes.empty()) {
    body += "<h2 id=\"notes\">Notes</h2>\n<ul class=\"notes\">";
    for (const auto& n : notes) body += "<li>" + html::escape(n) + "</li>";
    body += "</ul>\n";
  }

  // Points.
  std::vector<std::string> header = {"#", "technique"};
  for (const auto& a : plan.axes) header.push_back(a.key);
  for (const char* h : {"ms", "frame ms", "RMSE", "PSNR", "SSIM", "FLIP", plan.aov.c_str(), "error"})
    header.push_back(h);
  std::vector<ChartPoint> pts;
  for (const auto& r : results) pts.push_back({r.ms, r.metrics.rmse});
  std::set<std::size_t> front;
  for (std::size_t i : paretoFront(pts)) front.insert(i);
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    const SweepPoint& p = *r.point;
    std::vector<std::string> row;
    row.push_back("<span id=\"point-" + std::to_string(p.index) + "\">" + pointName(p.index) + "</span>" +
                  (front.count(i) ? " <span class=\"front\" title=\"on the Pareto front\">&#9679;</span>" : ""));
    row.push_back("<span class=\"swatch\" style=\"background:" + techniqueColor(plan, p.technique) + "\"></span>" +
                  html::escape(p.technique));
    for (const auto& a : plan.axes) row.push_back(html::escape(valueOf(p, a.key)));
    row.push_back(html::formatMs(r.ms));
    row.push_back(html::formatMs(r.frameMs));
    row.push_back(formatMetric(r.metrics.rmse));
    row.push_back(r.metrics.psnr ? formatMetric(*r.metrics.psnr) : "identical");
    row.push_back(formatMetric(r.metrics.ssim));
    row.push_back(formatMetric(r.metrics.flip));
    const std::string what = "point " + pointName(p.index) + " ";
    row.push_back(linked(r.aovFile, image(r.aovPng, what + plan.aov)));
    row.push_back(linked(r.heatFile, image(r.heatPng, what + "error heat map")));
    rows.push_back(std::move(row));
  }
  body += "<h2 id=\"points\">Points</h2>\n" + heatScaleHtml(plan, info) + "<div class=\"scroll\">" +
          html::tableHtml(header, rows) + "</div>\n";

  // References.
  std::string refs;
  for (const auto& [hash, png, file] : info.references)
    refs += "<figure>" + linked(file, image(png, "reference " + hash)) + "<figcaption><code>" + html::escape(hash) +
            "</code></figcaption></figure>";
  body += "<h2 id=\"references\">References</h2>\n<p class=\"meta\">Computed on the CPU from the frame's own surface "
          "points, cached by content hash (scene, AOV, size, spp, seed, " +
          definingKeysText(sweepReference(plan)) + ").</p>\n" + refs + "\n";

  // Parameters.
  std::vector<std::vector<std::string>> axes;
  for (const auto& a : plan.axes) {
    std::string values, applies;
    for (const auto& v : a.values) values += (values.empty() ? "" : ", ") + v;
    for (const auto& t : plan.techniques)
      if (sweepKeyApplies(a.key, {t, plan.stage})) applies += (applies.empty() ? "" : ", ") + t;
    axes.push_back({a.key, a.spec, values, applies, sweepReference(plan).definesKey(a.key) ? "yes" : "no"});
  }
  body += "<h2 id=\"parameters\">Parameters</h2>\n";
  body += html::table({"varied key", "--vary", "values", "applies to", "defines the reference"}, axes) + "\n";
  std::vector<std::vector<std::string>> fixed;
  for (const auto& [key, value] : plan.baseParams.items()) fixed.push_back({key, value.dump()});
  if (!fixed.empty()) body += "<p>Set for every point (differing from the defaults):</p>\n" + html::table({"key", "value"}, fixed) + "\n";

  // Run.
  std::vector<std::vector<std::string>> meta = {
      {"rtlab", plan.version + " (commit " + plan.commit + ")"},
      {"renderer", info.renderer},
      {"backend", info.backend},
      {"timing method", info.timing},
      {"scene", plan.scene},
      {"size", size},
      {"measured frames per point", std::to_string(plan.frames)},
      {"warm-up frames per point", std::to_string(sweepWarmupFrames(plan))},
      {"jobs", jobs},
      {"command", plan.command},
      {"seed", std::to_string(plan.seed)},
      {"reference spp", std::to_string(plan.spp)},
      {"stage / AOV", plan.stage + " / " + plan.aov},
      {"other techniques active", plan.baseTechniques.empty() ? "none" : [&] {
         std::string s;
         for (const auto& t : plan.baseTechniques) s += (s.empty() ? "" : ", ") + t;
         return s;
       }()},
      {"plan", plan.id},
  };
  body += "<h2 id=\"run\">Run</h2>\n" + html::table({"", ""}, meta) + "\n";
  return html::page("rtlab sweep: " + techniques, body, "body{max-width:1600px}" + sweepPageCss());
}

} // namespace rtlab
