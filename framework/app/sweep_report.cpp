#include "app/sweep_report.h"

#include "app/html.h"
#include "params/sweep_spec.h"
#include "util/chart.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace rtlab {
namespace {

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

std::string techniqueColor(const SweepPlan& plan, const std::string& technique) {
  for (std::size_t i = 0; i < plan.techniques.size(); ++i)
    if (plan.techniques[i] == technique) return kPalette[i % (sizeof kPalette / sizeof *kPalette)];
  return "#444";
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

std::string sweepChartSvg(const SweepPlan& plan, const std::vector<SweepResult>& results) {
  const double width = 760, height = 420, left = 78, right = 24, top = 20, bottom = 56;
  const double plotW = width - left - right, plotH = height - top - bottom;
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
  // Points, each linked to its table row.
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    if (!std::isfinite(pts[i].x) || !std::isfinite(pts[i].y)) continue;
    const std::string title = describePoint(*r.point) + ": " + html::formatMs(r.ms) + " ms, RMSE " + formatMetric(r.metrics.rmse);
    s += "<a href=\"#point-" + std::to_string(r.point->index) + "\"><circle class=\"point\" cx=\"" + num(X(pts[i].x)) +
         "\" cy=\"" + num(Y(pts[i].y)) + "\" r=\"5\" fill=\"" + techniqueColor(plan, r.point->technique) +
         "\" stroke=\"#fff\"><title>" + html::escape(title) + "</title></circle></a>\n";
  }
  // Legend.
  double ly = top + 14;
  const double lx = left + plotW - 170;
  s += "<rect x=\"" + num(lx - 8) + "\" y=\"" + num(top + 2) + "\" width=\"176\" height=\"" +
       num(18.0 * double(plan.techniques.size() + 1) + 8) + "\" fill=\"#fff\" fill-opacity=\"0.85\" stroke=\"#ccc\"/>\n";
  for (const auto& t : plan.techniques) {
    s += "<circle cx=\"" + num(lx + 6) + "\" cy=\"" + num(ly - 4) + "\" r=\"5\" fill=\"" + techniqueColor(plan, t) + "\"/>";
    s += "<text x=\"" + num(lx + 18) + "\" y=\"" + num(ly) + "\" font-size=\"12\">" + html::escape(t) + "</text>\n";
    ly += 18;
  }
  s += "<line x1=\"" + num(lx) + "\" y1=\"" + num(ly - 4) + "\" x2=\"" + num(lx + 12) + "\" y2=\"" + num(ly - 4) +
       "\" stroke=\"#222\" stroke-width=\"1.5\" stroke-dasharray=\"5 3\"/>";
  s += "<text x=\"" + num(lx + 18) + "\" y=\"" + num(ly) + "\" font-size=\"12\">Pareto front</text>\n";
  return s + "</svg>";
}

std::string sweepReportHtml(const SweepPlan& plan, const std::vector<SweepResult>& results,
                            const SweepReportInfo& info) {
  std::string techniques;
  for (const auto& t : plan.techniques) techniques += (techniques.empty() ? "" : ", ") + t;
  std::string body = "<h1>rtlab sweep: " + html::escape(techniques) + " (stage " + html::escape(plan.stage) + ")</h1>\n";
  body += "<p class=\"meta\">" + std::to_string(results.size()) + " points, error of the <code>" + html::escape(plan.aov) +
          "</code> AOV against the reference (" + std::to_string(plan.spp) + " spp) over the surface pixels.</p>\n";

  body += "<h2 id=\"chart\">Error against time</h2>\n" + sweepChartSvg(plan, results) + "\n";
  body += "<p class=\"meta\">Ringed points and the dashed step line: the Pareto front (no other point is both faster and "
          "more accurate). Hover a point for its values; click it for its row.</p>\n";

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
    row.push_back(image(r.aovPng, what + plan.aov));
    row.push_back(image(r.heatPng, what + "error heat map"));
    rows.push_back(std::move(row));
  }
  body += "<h2 id=\"points\">Points</h2>\n<div class=\"scroll\">" + html::tableHtml(header, rows) + "</div>\n";
  body += "<p class=\"meta\">Heat maps: |" + html::escape(plan.aov) + " &minus; reference| (mean over channels) through the "
          "magma colormap, from 0 (black) to " + html::escape(formatMetric(info.heatScale)) +
          " (light yellow, the largest error of the sweep), the same scale for every point; gray: background, "
          "not measured.</p>\n";

  // References.
  std::string refs;
  for (const auto& [hash, png] : info.references)
    refs += "<figure>" + image(png, "reference " + hash) + "<figcaption><code>" + html::escape(hash) +
            "</code></figcaption></figure>";
  body += "<h2 id=\"references\">References</h2>\n<p class=\"meta\">Computed on the CPU from the frame's own surface "
          "points, cached by content hash (scene, AOV, size, spp, seed, light and camera values" +
          std::string(plan.stage == "ao" ? ", ao.radius" : "") + ").</p>\n" + refs + "\n";

  // Parameters.
  std::vector<std::vector<std::string>> axes;
  for (const auto& a : plan.axes) {
    std::string values, applies;
    for (const auto& v : a.values) values += (values.empty() ? "" : ", ") + v;
    for (const auto& t : plan.techniques)
      if (sweepKeyApplies(a.key, {t, plan.stage})) applies += (applies.empty() ? "" : ", ") + t;
    axes.push_back({a.key, a.spec, values, applies, isReferenceDefiningKey(a.key, plan.stage) ? "yes" : "no"});
  }
  body += "<h2 id=\"parameters\">Parameters</h2>\n";
  body += html::table({"varied key", "--vary", "values", "applies to", "defines the reference"}, axes) + "\n";
  std::vector<std::vector<std::string>> fixed;
  for (const auto& [key, value] : plan.baseParams.items()) fixed.push_back({key, value.dump()});
  if (!fixed.empty()) body += "<p>Set for every point (differing from the defaults):</p>\n" + html::table({"key", "value"}, fixed) + "\n";

  // Run.
  std::string size = std::to_string(plan.width) + "x" + std::to_string(plan.height);
  std::vector<std::vector<std::string>> meta = {
      {"rtlab", plan.version + " (commit " + plan.commit + ")"},
      {"renderer", info.renderer},
      {"backend", info.backend},
      {"timing method", info.timing},
      {"scene", plan.scene},
      {"size", size},
      {"measured frames per point", std::to_string(plan.frames)},
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
  const std::string css = "body{max-width:1600px}img.thumb{max-width:112px;min-width:64px}td img{display:block}td{white-space:nowrap}\n"
                          ".scroll{overflow-x:auto}\n"
                          ".swatch{display:inline-block;width:.8em;height:.8em;border-radius:50%;margin-right:.4em}\n"
                          ".front{color:#222}svg.chart{max-width:100%;height:auto;font-family:system-ui,sans-serif}\n";
  return html::page("rtlab sweep: " + techniques, body, css);
}

} // namespace rtlab
