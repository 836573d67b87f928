#include "app/exercise_grade.h"

#include "app/exercise_grade_cache.h"
#include "app/exercise_runner.h"
#include "image/metrics.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace rtlab {
namespace {

const char* runStatusName(ViewRunStatus s) {
  switch (s) {
  case ViewRunStatus::Ok: return "passed";
  case ViewRunStatus::CompileError: return "compile_error";
  case ViewRunStatus::Error: return "crashed";
  case ViewRunStatus::Timeout: return "timeout";
  case ViewRunStatus::Crashed: return "crashed";
  }
  return "crashed";
}

std::vector<ViewRun> run(const ExerciseFolder& folder, const GradeOptions& options, const std::vector<ExerciseView>& views,
                         WorkerFiles files, double timeLimit, const char* what) {
  if (options.progress) std::cerr << "rtlab: grading " << folder.def->id << ": rendering " << views.size()
                                  << " views with " << what << "\n";
  WorkerRequest request;
  request.exercise = folder.def->id;
  request.files = files;
  request.dir = folder.dir;
  request.aov = folder.def->aov;
  request.backend = options.backend;
  request.references = files == WorkerFiles::Solution;
  request.views = views;
  return runViewsInWorkers(request, timeLimit);
}

// The solution's (with references) or the stubs' renders of the views `which`: from the cache
// where it holds them for `driver` (the student's workers' driver; empty: none is known), the rest
// rendered and stored; `base` is gradeCacheBase's. Without a cache, all rendered.
std::vector<ViewRun> runTrusted(const ExerciseFolder& folder, const GradeOptions& options, const std::vector<std::size_t>& which,
                                WorkerFiles files, const std::string& base, const std::string& driver) {
  // The solution and the stubs are rtlab's own code: a generous limit only guards against a hang.
  const double trustedLimit = std::max(300.0, 10.0 * options.timeLimitSeconds);
  const bool solution = files == WorkerFiles::Solution;
  const char* what = solution ? "the solution" : "the stubs";
  const char* kind = solution ? "solution" : "stub";
  std::vector<ViewRun> runs(which.size());
  std::vector<std::size_t> missing; // positions in `which`
  for (std::size_t k = 0; k < which.size(); ++k) {
    const ExerciseView& view = options.views[which[k]];
    std::optional<std::vector<Image>> images;
    if (options.cache && !driver.empty())
      images = options.cache->load(gradeCacheKey(base, *folder.def, view, options.backend, driver, kind), solution ? 2 : 1,
                                   view.width, view.height);
    if (!images) {
      missing.push_back(k);
      continue;
    }
    runs[k].status = ViewRunStatus::Ok;
    runs[k].driver = driver;
    runs[k].image = std::move((*images)[0]);
    if (solution) runs[k].reference = std::move((*images)[1]);
  }
  if (options.cache && options.progress)
    std::cerr << "rtlab: grading " << folder.def->id << ": " << which.size() - missing.size() << " of " << which.size()
              << " views with " << what << " from the cache " << options.cache->dir() << "\n";
  if (missing.empty()) return runs;
  std::vector<ExerciseView> views;
  for (std::size_t k : missing) views.push_back(options.views[which[k]]);
  auto rendered = run(folder, options, views, files, trustedLimit, what);
  for (std::size_t m = 0; m < missing.size(); ++m) {
    ViewRun& r = rendered[m];
    if (options.cache && r.status == ViewRunStatus::Ok && !r.driver.empty()) {
      std::vector<Image> images = {r.image};
      if (solution) images.push_back(r.reference);
      options.cache->store(gradeCacheKey(base, *folder.def, views[m], options.backend, r.driver, kind), images);
    }
    runs[missing[m]] = std::move(r);
  }
  return runs;
}

double rmse(const Image& a, const Image& b) {
  const Metrics m = computeMetrics(a, b);
  return m.rmse;
}

} // namespace

GradeResult gradeExercise(const ExerciseFolder& folder, const GradeOptions& options) {
  const std::size_t n = options.views.size();
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = i;
  // The student's files run alone, so that their time limit and `ms` are not shared with other
  // work. Without a cache the solution (with the references) renders first: a solution that does
  // not render stops grading before the student's renders. With a cache the student's renders come
  // first: their workers name the driver, which is part of the cache's key.
  std::vector<ViewRun> solution, student;
  auto renderStudent = [&] {
    student = run(folder, options, options.views, WorkerFiles::Student, options.timeLimitSeconds, "the student's files");
  };
  if (options.cache) renderStudent();
  std::string driver;
  for (const auto& s : student)
    if (driver.empty()) driver = s.driver;
  const std::string base = options.cache ? gradeCacheBase(*folder.def, options.backend) : "";
  solution = runTrusted(folder, options, all, WorkerFiles::Solution, base, driver);
  for (std::size_t i = 0; i < solution.size(); ++i)
    if (solution[i].status != ViewRunStatus::Ok) {
      const ExitCode code = solution[i].code > 1 ? ExitCode(solution[i].code) : ExitCode::Internal;
      throw Error(code, "view '" + options.views[i].name + "': the solution did not render: " + solution[i].message);
    }
  if (!options.cache) renderStudent();

  // Judged without the stubs first; only the views that failed over finite values render with the
  // stubs, to tell "the stub is still there" from other differences (a passing folder renders none).
  std::vector<ViewComparison> comparisons(n);
  std::vector<std::size_t> needStub;
  for (std::size_t i = 0; i < n; ++i) {
    if (student[i].status != ViewRunStatus::Ok) continue;
    comparisons[i] = compareWithSolution(student[i].image, solution[i].image, nullptr, options.tolerance);
    if (!comparisons[i].passed && comparisons[i].nonFinite == 0) needStub.push_back(i);
  }
  if (!needStub.empty()) {
    const auto stub = runTrusted(folder, options, needStub, WorkerFiles::Stub, base, driver.empty() ? solution[0].driver : driver);
    for (std::size_t k = 0; k < needStub.size(); ++k) {
      const std::size_t i = needStub[k];
      if (stub[k].status == ViewRunStatus::Ok)
        comparisons[i] = compareWithSolution(student[i].image, solution[i].image, &stub[k].image, options.tolerance);
    }
  }

  GradeResult result;
  result.exercise = folder.def->id;
  int passed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ViewGrade g;
    g.name = options.views[i].name;
    g.ms = student[i].ms;
    g.solutionRmseVsReference = rmse(solution[i].image, solution[i].reference);
    const ViewRun& s = student[i];
    if (s.status == ViewRunStatus::Ok) {
      const ViewComparison& c = comparisons[i];
      g.passed = c.passed;
      g.status = c.passed ? "passed" : "failed";
      g.cause = c.cause;
      g.rmseVsSolution = c.rmseVsSolution;
      g.differingFraction = c.differingFraction;
      g.rmseAgreeing = c.rmseAgreeing;
      g.rmseVsReference = rmse(s.image, solution[i].reference);
    } else {
      g.status = runStatusName(s.status);
      g.cause = s.status == ViewRunStatus::CompileError ? "compile_error: " + s.message
                : s.status == ViewRunStatus::Timeout  ? "timeout: the render " + s.message +
                                                           " (an endless or very long loop?)"
                                                      : "crashed: " + s.message;
      if (s.status == ViewRunStatus::CompileError && result.compileError.empty()) result.compileError = s.message;
    }
    if (options.keepImages) {
      g.solution = solution[i].image;
      g.reference = solution[i].reference;
      g.hasStudent = s.status == ViewRunStatus::Ok;
      if (g.hasStudent) g.student = s.image;
    }
    passed += g.passed ? 1 : 0;
    result.views.push_back(std::move(g));
  }
  const int views = int(result.views.size());
  result.score = result.compileError.empty() ? int(std::lround(100.0 * passed / std::max(views, 1))) : 0;
  result.passed = result.compileError.empty() && passed == views;
  return result;
}

nlohmann::ordered_json gradeJson(const GradeResult& r) {
  nlohmann::ordered_json j;
  j["schema"] = 1;
  j["exercise"] = r.exercise;
  j["passed"] = r.passed;
  j["score"] = r.score;
  j["views"] = nlohmann::ordered_json::array();
  auto number = [](const std::optional<double>& v) -> nlohmann::ordered_json {
    if (!v || !std::isfinite(*v)) return nullptr;
    return *v;
  };
  for (const auto& v : r.views) {
    nlohmann::ordered_json view;
    view["name"] = v.name;
    view["status"] = v.status;
    view["cause"] = v.cause;
    view["passed"] = v.passed;
    view["rmse_vs_solution"] = number(v.rmseVsSolution);
    view["differing_fraction"] = number(v.differingFraction);
    view["rmse_vs_reference"] = number(v.rmseVsReference);
    view["solution_rmse_vs_reference"] = number(v.solutionRmseVsReference);
    view["ms"] = v.ms;
    j["views"].push_back(std::move(view));
  }
  return j;
}

} // namespace rtlab
