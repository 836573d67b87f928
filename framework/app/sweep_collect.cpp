#include "app/sweep_collect.h"

#include "app/html.h"
#include "app/sweep_heat.h"
#include "app/sweep_jobs.h"
#include "frame/aovs.h"
#include "app/sweep_report.h"
#include "image/image.h"
#include "image/metrics.h"
#include "util/atomic_file.h"
#include "util/base64.h"
#include "util/csv.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

namespace fs = std::filesystem;

namespace rtlab {
namespace {

constexpr int kThumbWidth = 160; // shown at most 120 CSS pixels wide

// Box-filtered copy at most maxWidth wide (integer factor; partial blocks averaged).
Image thumbnail(const Image& in, int maxWidth) {
  const int f = std::max(1, (in.width + maxWidth - 1) / maxWidth);
  if (f == 1) return in;
  Image out((in.width + f - 1) / f, (in.height + f - 1) / f, in.channels);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < in.channels; ++c) {
        double sum = 0;
        int n = 0;
        for (int yy = y * f; yy < std::min(in.height, (y + 1) * f); ++yy)
          for (int xx = x * f; xx < std::min(in.width, (x + 1) * f); ++xx) {
            const float v = in.at(xx, yy, c);
            if (std::isfinite(v)) sum += v, ++n;
          }
        out.at(x, y, c) = n ? float(sum / n) : 0.0f;
      }
  return out;
}

std::string pngBase64(const Image& image, PngEncoding encoding = PngEncoding::Linear01) {
  const auto bytes = encodePng(thumbnail(image, kThumbWidth), encoding);
  return base64Encode(bytes.data(), bytes.size());
}

std::vector<std::string> distinct(const std::vector<std::string>& values) {
  std::vector<std::string> seen;
  for (const auto& v : values)
    if (std::find(seen.begin(), seen.end(), v) == seen.end()) seen.push_back(v);
  return seen;
}

std::string joinDistinct(const std::vector<std::string>& values) {
  std::string s;
  for (const auto& v : distinct(values)) s += (s.empty() ? "" : "; ") + v;
  return s;
}

std::string listSome(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size() && i < 5; ++i) s += (i ? ", " : "") + names[i];
  if (names.size() > 5) s += ", ...";
  return s;
}

std::string fixed4(double v) {
  if (!std::isfinite(v)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

} // namespace

std::vector<std::string> sweepCsvHeader(const SweepPlan& plan) {
  std::vector<std::string> h = {"technique"};
  for (const auto& a : plan.axes) h.push_back(a.key);
  for (const char* c : {"ms", "frame_ms", "rmse", "psnr", "ssim", "flip", "timing"}) h.push_back(c);
  return h;
}

SweepCollection collectSweep(const std::string& dirArg) {
  SweepCollection c;
  c.plan = readSweepPlan(dirArg);
  const SweepPlan& plan = c.plan;

  // Everything must be there before anything is written.
  std::vector<std::string> missingPoints, missingRefs;
  for (const auto& p : plan.points)
    if (!pointDone(plan, p.index)) missingPoints.push_back("points/" + pointName(p.index));
  for (const auto& r : plan.references) {
    std::error_code ec;
    if (!fs::is_regular_file(referencePath(plan, r.hash), ec)) missingRefs.push_back("reference/" + r.hash + ".exr");
  }
  if (!missingPoints.empty() || !missingRefs.empty()) {
    std::string what;
    if (!missingPoints.empty())
      what += std::to_string(missingPoints.size()) + " of " + std::to_string(plan.points.size()) + " points (" +
              listSome(missingPoints) + ")";
    if (!missingRefs.empty())
      what += std::string(what.empty() ? "" : " and ") + std::to_string(missingRefs.size()) + " of " +
              std::to_string(plan.references.size()) + " references (" + listSome(missingRefs) + ")";
    inputError("sweep '" + plan.dir + "' is not finished: missing " + what + "; run their jobs (" +
               (fs::path(plan.dir) / "jobs.txt").string() + ") first");
  }

  std::map<std::string, Image> references;
  for (const auto& r : plan.references) references[r.hash] = readImage(referencePath(plan, r.hash));

  // Pass 1: metrics, and the distribution of the per-pixel errors of the whole sweep. Only
  // thumbnails stay in memory, so a sweep of thousands of points does not hold thousands of images.
  std::vector<SweepResult>& results = c.results;
  std::vector<std::string> renderers, backends, timings;
  std::vector<std::pair<double, double>> measured; // each point's measured interval (unix seconds)
  ErrorPercentile errors;
  for (const auto& p : plan.points) {
    const fs::path dir = pointDir(plan, p.index);
    SweepResult r;
    r.point = &p;
    const std::string statsPath = (dir / "stats.json").string();
    try {
      const auto stats = nlohmann::json::parse(readFileOrThrow(statsPath, "point stats"));
      for (const auto& pass : stats.at("passes"))
        if (pass.at("technique").get<std::string>() == p.technique) r.ms += pass.at("ms").get<double>();
      r.frameMs = stats.at("frame_ms").get<double>();
      r.timing = stats.at("timing").get<std::string>();
      renderers.push_back(stats.at("renderer").get<std::string>());
      backends.push_back(stats.at("backend").get<std::string>());
      timings.push_back(r.timing);
    } catch (const nlohmann::json::exception& e) {
      inputError("invalid point stats '" + statsPath + "': " + e.what());
    }
    // done.json's "measured" and "software" (absent in points of an older rtlab).
    const auto done = nlohmann::json::parse(readFileOrThrow((dir / "done.json").string()), nullptr, false);
    if (done.is_object()) {
      if (done.value("software", false)) c.info.software = true;
      const auto it = done.find("measured");
      if (it != done.end() && it->is_array() && it->size() == 2 && (*it)[0].is_number() && (*it)[1].is_number())
        measured.emplace_back((*it)[0].get<double>(), (*it)[1].get<double>());
    }
    const Image aov = readImage((dir / "aov.exr").string());
    const Image& ref = references.at(p.reference);
    r.metrics = computeMetrics(ref, aov); // B (the point) against A (the reference)
    addErrorImage(errors, absoluteErrorImage(ref, aov));
    r.aovPng = pngBase64(aov, pngEncodingForAov(plan.aov));
    r.aovFile = "points/" + pointName(p.index) + "/aov.png";
    r.heatFile = "points/" + pointName(p.index) + "/error.png";
    writeImage((fs::path(plan.dir) / r.aovFile).string(), aov, pngEncodingForAov(plan.aov));
    results.push_back(std::move(r));
  }
  for (std::size_t i = 0; i < measured.size(); ++i)
    for (std::size_t j = 0; j < measured.size(); ++j)
      if (i != j && measured[i].first < measured[j].second && measured[j].first < measured[i].second) {
        ++c.info.concurrentPoints;
        break;
      }

  // Pass 2: heat maps on one scale for the whole sweep, so that they compare (sweep_heat.h).
  const double scale = heatScale(errors);
  for (auto& r : results) {
    const fs::path dir = pointDir(plan, r.point->index);
    const Image error = absoluteErrorImage(references.at(r.point->reference), readImage((dir / "aov.exr").string()));
    const Image heat = errorHeatmap(error, float(scale));
    writeImage((fs::path(plan.dir) / r.heatFile).string(), heat);
    r.heatPng = pngBase64(heat);
  }

  std::string csv = csvLine(sweepCsvHeader(plan));
  for (const auto& r : results) {
    std::vector<std::string> row = {r.point->technique};
    for (const auto& a : plan.axes) {
      std::string v;
      for (const auto& [k, text] : r.point->values)
        if (k == a.key) v = text;
      row.push_back(v);
    }
    row.push_back(fixed4(r.ms));
    row.push_back(fixed4(r.frameMs));
    row.push_back(formatMetric(r.metrics.rmse));
    row.push_back(r.metrics.psnr ? formatMetric(*r.metrics.psnr) : "");
    row.push_back(formatMetric(r.metrics.ssim));
    row.push_back(formatMetric(r.metrics.flip));
    row.push_back(r.timing);
    csv += csvLine(row);
  }

  SweepReportInfo& info = c.info;
  info.renderer = joinDistinct(renderers);
  info.backend = joinDistinct(backends);
  info.timing = joinDistinct(timings);
  info.heatScale = scale;
  info.heatMax = errors.max();
  info.colorBarPng = colorBarPngBase64(scale);
  for (const auto& r : plan.references) {
    const std::string file = "reference/" + r.hash + ".png";
    writeImage((fs::path(plan.dir) / file).string(), references.at(r.hash), pngEncodingForAov(plan.aov));
    info.references.push_back({r.hash, pngBase64(references.at(r.hash), pngEncodingForAov(plan.aov)), file});
  }

  // sweep.json gains what the run measured on, so the plan file says what decided the timings.
  nlohmann::ordered_json planJson = sweepPlanToJson(plan);
  nlohmann::ordered_json run;
  run["renderer"] = distinct(renderers);
  run["backend"] = distinct(backends);
  run["timing"] = distinct(timings);
  run["software"] = info.software;
  run["concurrent_points"] = info.concurrentPoints;
  const std::string warning = sweepTimingWarning(plan, info);
  run["warning"] = warning.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(warning);
  run["heat_scale"] = info.heatScale;
  planJson["measured"] = run;

  writeTextAtomically((fs::path(plan.dir) / "results.csv").string(), csv);
  writeTextAtomically((fs::path(plan.dir) / "sweep.json").string(), planJson.dump(2) + "\n");
  writeTextAtomically((fs::path(plan.dir) / "report.html").string(), sweepReportHtml(plan, results, info));
  return c;
}

} // namespace rtlab
