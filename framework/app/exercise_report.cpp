#include "app/exercise_report.h"

#include "app/html.h"
#include "image/metrics.h"
#include "util/atomic_file.h"
#include "util/base64.h"
#include "util/error.h"
#include "util/number_format.h"

#include <cstdio>
#include <filesystem>

namespace rtlab {
namespace fs = std::filesystem;
namespace {

// The heat map's scale: an absolute difference of this much or more is the top of the colour map.
constexpr float kHeatmapMax = 0.25f;

const char* kCss = R"(
figure.cell img { width: 240px; image-rendering: pixelated; display: block; }
.passed { color: #1a7f37; font-weight: 600; }
.failed, .timeout, .crashed, .compile_error { color: #b42318; font-weight: 600; }
.cause { background: #fff4e5; border-left: 4px solid #f79009; padding: 0.5em 1em; }
.grid { display: flex; flex-wrap: wrap; gap: 1em; }
)";

std::string figure(const Image& image, const std::string& caption, PngEncoding encoding = PngEncoding::Linear01) {
  const auto png = encodePng(image, encoding);
  return "<figure class=\"cell\"><img alt=\"" + html::escape(caption) + "\" src=\"data:image/png;base64," +
         base64Encode(png.data(), png.size()) + "\"><figcaption>" + html::escape(caption) + "</figcaption></figure>";
}

std::string missing(const std::string& caption, const std::string& why) {
  return "<figure class=\"cell\"><div style=\"width:240px;height:135px;background:#eee;display:flex;align-items:center;"
         "justify-content:center\">" + html::escape(why) + "</div><figcaption>" + html::escape(caption) + "</figcaption></figure>";
}

// Figures with 3 significant digits: enough to compare with the bounds.
std::string value(const std::optional<double>& v) {
  if (!v || !std::isfinite(*v)) return "-";
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", *v);
  return text;
}

std::string statusSpan(const std::string& status) {
  return "<span class=\"" + html::escape(status) + "\">" + html::escape(status) + "</span>";
}

// How the student's error against the ground truth compares with the solution's (informative).
std::string againstReference(const ViewGrade& g) {
  const double s = *g.rmseVsReference, r = g.solutionRmseVsReference;
  const std::string figures = "RMSE against the reference " + value(s) + ", the solution's " + value(r);
  if (s < r * 0.98) return figures + ": closer to the ground truth than the solution.";
  if (s <= r * 1.02) return figures + ": as close to the ground truth as the solution.";
  return figures + ": farther from the ground truth than the solution.";
}

std::string pageFile(const ViewGrade& v) { return "view-" + v.name + ".html"; }

std::string viewPage(const ExerciseFolder& folder, const GradeOptions& options, const ExerciseView& view,
                     const ViewGrade& g) {
  std::string body = "<h1>" + html::escape(folder.def->id) + ": view <code>" + html::escape(g.name) + "</code> " +
                     statusSpan(g.status) + "</h1>";
  body += "<p><a href=\"index.html\">all views</a></p>";
  std::string setting = "scene " + view.scene + ", " + viewSize(view);
  for (const auto& [key, val] : view.set) setting += ", " + key + "=" + val;
  body += "<p>" + html::escape(setting) + (view.note.empty() ? "" : " — " + html::escape(view.note)) + "</p>";
  if (!g.cause.empty()) body += "<p class=\"cause\">" + html::escape(g.cause) + "</p>";
  if (g.rmseVsReference) body += "<p>" + html::escape(againstReference(g)) + "</p>";
  body += "<div class=\"grid\">";
  body += g.hasStudent ? figure(g.student, "student") : missing("student", g.status);
  body += figure(g.solution, "solution");
  body += figure(g.reference, "reference (ground truth)");
  if (g.hasStudent)
    body += figure(errorHeatmap(absoluteErrorImage(g.student, g.solution), kHeatmapMax),
                   "|student - solution| (black 0 .. yellow " + formatNumber(double(kHeatmapMax)) + "+)");
  body += "</div>";
  const ExerciseTolerance& t = options.tolerance;
  body += html::table({"figure", "value", "bound"},
                      {{"RMSE vs solution", value(g.rmseVsSolution), "all pixels"},
                       {"differing fraction (|d| > " + formatNumber(t.pixel) + ")", value(g.differingFraction),
                        "<= " + formatNumber(t.fraction)},
                       {"RMSE vs solution of the other pixels", value(g.rmseAgreeing), "<= " + formatNumber(t.rmse)},
                       {"RMSE vs reference (student)", value(g.rmseVsReference), "informative"},
                       {"RMSE vs reference (solution)", value(g.solutionRmseVsReference), "informative"},
                       {"time (student's render)", html::formatMs(g.ms) + " ms", "<= " + formatNumber(options.timeLimitSeconds) + " s"}});
  return html::page(folder.def->id + " — " + g.name, body, kCss);
}

} // namespace

void checkReportFolder(const std::string& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) outputError("--report " + dir + " is not a directory");
  if (fs::is_directory(dir, ec) && !fs::is_empty(dir, ec) && !fs::exists(fs::path(dir) / "grade.json", ec))
    outputError("--report " + dir + " is not empty and holds no earlier report (grade.json); choose another folder");
  fs::create_directories(dir, ec);
  if (ec) outputError("cannot create --report folder " + dir + ": " + ec.message());
  checkOutputPath((fs::path(dir) / "index.html").string());
}

void writeGradeReport(const std::string& dir, const ExerciseFolder& folder, const GradeOptions& options,
                      const GradeResult& result) {
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < result.views.size(); ++i) {
    const ViewGrade& g = result.views[i];
    writeTextAtomically((fs::path(dir) / pageFile(g)).string(), viewPage(folder, options, options.views[i], g));
    rows.push_back({"<a href=\"" + html::escape(pageFile(g)) + "\">" + html::escape(g.name) + "</a>", statusSpan(g.status),
                    html::escape(value(g.rmseVsSolution)), html::escape(value(g.differingFraction)),
                    html::escape(value(g.rmseVsReference)), html::escape(value(g.solutionRmseVsReference)),
                    html::escape(html::formatMs(g.ms) + " ms"), html::escape(g.cause)});
  }
  std::string body = "<h1>Exercise " + html::escape(folder.def->id) + ": " + html::escape(folder.def->title) + "</h1>";
  body += "<p>Folder <code>" + html::escape(folder.dir) + "</code>. Score <b>" + std::to_string(result.score) +
          "</b> (" + (result.passed ? statusSpan("passed") : statusSpan("failed")) + ").</p>";
  if (!result.compileError.empty()) body += "<p class=\"cause\">" + html::escape(result.compileError) + "</p>";
  body += html::tableHtml({"view", "status", "RMSE vs solution", "differing", "RMSE vs reference",
                           "solution vs reference", "time", "cause"}, rows);
  body += "<p>A view passes when at most " + formatNumber(options.tolerance.fraction * 100.0) +
          "% of its pixels differ from the solution by more than " + formatNumber(options.tolerance.pixel) +
          " and the RMSE of the other pixels is at most " + formatNumber(options.tolerance.rmse) + " (docs/exercises.md).</p>";
  writeTextAtomically((fs::path(dir) / "grade.json").string(), gradeJson(result).dump(2) + "\n");
  writeTextAtomically((fs::path(dir) / "index.html").string(), html::page("grade: " + folder.def->id, body, kCss));
}

} // namespace rtlab
