#include "app/exercise_grade.h"

#include "app/exercise_runner.h"
#include "image/metrics.h"
#include "util/error.h"

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

double rmse(const Image& a, const Image& b) {
  const Metrics m = computeMetrics(a, b);
  return m.rmse;
}

} // namespace

GradeResult gradeExercise(const ExerciseFolder& folder, const GradeOptions& options) {
  // The solution and the stubs are rtlab's own code: a generous limit only guards against a hang.
  const double trustedLimit = std::max(300.0, 10.0 * options.timeLimitSeconds);
  // The solution (with the references) first; then the student's files, alone, so that their time
  // limit and `ms` are not shared with other work.
  const auto solution = run(folder, options, options.views, WorkerFiles::Solution, trustedLimit, "the solution");
  for (std::size_t i = 0; i < solution.size(); ++i)
    if (solution[i].status != ViewRunStatus::Ok) {
      const ExitCode code = solution[i].code > 1 ? ExitCode(solution[i].code) : ExitCode::Internal;
      throw Error(code, "view '" + options.views[i].name + "': the solution did not render: " + solution[i].message);
    }
  const auto student = run(folder, options, options.views, WorkerFiles::Student, options.timeLimitSeconds, "the student's files");

  // Judged without the stubs first; only the views that failed over finite values render with the
  // stubs, to tell "the stub is still there" from other differences (a passing folder renders none).
  const std::size_t n = options.views.size();
  std::vector<ViewComparison> comparisons(n);
  std::vector<std::size_t> needStub;
  for (std::size_t i = 0; i < n; ++i) {
    if (student[i].status != ViewRunStatus::Ok) continue;
    comparisons[i] = compareWithSolution(student[i].image, solution[i].image, nullptr, options.tolerance);
    if (!comparisons[i].passed && comparisons[i].nonFinite == 0) needStub.push_back(i);
  }
  if (!needStub.empty()) {
    std::vector<ExerciseView> views;
    for (std::size_t i : needStub) views.push_back(options.views[i]);
    const auto stub = run(folder, options, views, WorkerFiles::Stub, trustedLimit, "the stubs");
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
