// rtlab sweep: error against time over a grid of parameter values, for one or more techniques of
// one stage (docs/contract.md, docs/sweeps.md). Planning validates everything and writes
// DIR/sweep.json and DIR/jobs.txt; every reference and point is then rendered by a job, a child
// process `rtlab sweep --run-reference|--run-point DIR K` (N at a time with --jobs N, or
// elsewhere from --emit-jobs FILE), and --collect merges the finished points into
// DIR/results.csv and DIR/report.html.
#include "app/commands.h"
#include "app/frame_options.h"
#include "app/sweep_collect.h"
#include "app/sweep_command.h"
#include "app/sweep_folder.h"
#include "app/sweep_jobs.h"
#include "app/sweep_plan.h"
#include "util/atomic_file.h"
#include "util/error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;

namespace rtlab {
namespace {

std::vector<OptionSpec> sweepOptions() {
  auto specs = frameOptionSpecs();
  for (auto& s : specs)
    if (s.name == "--technique") s.help = "the techniques to sweep, all of one stage with a reference (shadow, ao, indirect, transparency, post): A,B,...";
  specs.push_back({"--vary", "", true, "KEY=SPEC", "a sweep axis (repeatable; several make a cross product): "
                                                   "KEY=V1,V2,... or KEY=LO:HI:N (linear or log by the key's scale)"});
  specs.push_back({"--out", "", true, "DIR", "output folder: sweep.json, jobs.txt, points/, reference/, results.csv, report.html"});
  specs.push_back({"--force", "", false, "", "replace the sweep that --out DIR holds (refused without it, exit 6)"});
  specs.push_back({"--jobs", "", true, "N", "render N points at a time, each in its own process (default 1)"});
  specs.push_back({"--emit-jobs", "", true, "FILE", "plan only: write one shell command per job to FILE and exit"});
  specs.push_back({"--spp", "", true, "N", "reference samples per pixel, 1..65536 (default: the reference's, 64 for visibility, ao and indirect; bloom's does not sample: 1)"});
  specs.push_back({"--collect", "", true, "DIR", "merge a planned sweep's finished jobs into results.csv and report.html"});
  return specs;
}

int runJobMode(int argc, char** argv) {
  const std::string mode = argv[2];
  if (argc != 5) usageError("usage: rtlab sweep " + mode + " DIR " + (mode == "--run-point" ? "N" : "K"));
  const SweepPlan plan = readSweepPlan(argv[3]);
  const long long max = mode == "--run-point" ? (long long)plan.points.size() - 1 : (long long)plan.references.size() - 1;
  const int index = int(parseIntOption(mode, argv[4], 0, std::max(0LL, max)));
  if (mode == "--run-point") runPointJob(plan, index);
  else runReferenceJob(plan, index);
  return 0;
}

// The command; a direct sweep's collection goes to `collected` when given.
int sweepMain(int argc, char** argv, SweepCollection* collected) {
  if (argc >= 3 && (std::string(argv[2]) == "--run-point" || std::string(argv[2]) == "--run-reference"))
    return runJobMode(argc, argv);
  const auto specs = sweepOptions();
  Args args("sweep", specs, argc, argv, 2);
  if (args.help()) {
    std::cout << formatHelp(
        "rtlab sweep [scene and frame options] -t ID[,ID...] --vary KEY=SPEC [--vary ...] --out DIR\n"
        "                   [--jobs N] [--emit-jobs FILE] [--spp N] [--force]\n"
        "       rtlab sweep --collect DIR",
        "Renders every point of a parameter grid for each technique (all of one stage), measures its\n"
        "time and its error against the stage's reference (rendered once per scene and\n"
        "reference-defining values, cached in ${RTLAB_CACHE_DIR:-~/.cache/rtlab}), and writes\n"
        "DIR/results.csv and DIR/report.html. See docs/sweeps.md.",
        specs);
    return 0;
  }

  if (args.has("--collect")) {
    for (const auto& [name, value] : args.ordered())
      if (name != "--collect") usageError("--collect DIR takes no other option (got '" + name + "')");
    const std::string dir = args.get("--collect");
    if (dir.empty()) usageError("--collect needs a folder");
    collectSweep(dir);
    std::fprintf(stderr, "sweep: wrote %s and %s\n", (fs::path(dir) / "results.csv").c_str(),
                 (fs::path(dir) / "report.html").c_str());
    return 0;
  }

  SweepRequest request;
  request.techniques = args.all("--technique");
  request.varies = args.all("--vary");
  if (args.has("--spp")) request.spp = int(parseIntOption("--spp", args.get("--spp"), 1, 65536));
  const int jobs = args.has("--jobs") ? int(parseIntOption("--jobs", args.get("--jobs"), 1, 256)) : 1;
  request.command = "rtlab sweep";
  for (int i = 2; i < argc; ++i) request.command += " " + shellQuote(argv[i]);
  if (request.techniques.empty()) usageError("sweep needs -t ID[,ID...]: the techniques to sweep, all of one stage");
  request.dir = args.get("--out");
  if (request.dir.empty()) usageError("sweep needs --out DIR");
  const std::string emit = args.get("--emit-jobs");
  if (args.has("--emit-jobs") && emit.empty()) usageError("--emit-jobs needs a file name");
  request.jobs = emit.empty() ? jobs : 0; // emitted jobs run where and how the user decides

  // The scene and frame options alone (no -t: the swept techniques are not one frame's).
  std::vector<std::string> frameArgv = {"rtlab", "sweep"};
  const auto frameSpecs = frameOptionSpecs();
  for (const auto& [name, value] : args.ordered()) {
    if (name == "--technique") continue;
    const bool isFrameOption =
        std::any_of(frameSpecs.begin(), frameSpecs.end(), [&](const OptionSpec& s) { return s.name == name; });
    if (isFrameOption) frameArgv.insert(frameArgv.end(), {name, value});
  }
  std::vector<char*> cargv;
  for (auto& a : frameArgv) cargv.push_back(a.data());
  const Args frameArgs("sweep", frameSpecs, int(cargv.size()), cargv.data(), 2);

  const SweepPlan plan = planSweep(frameArgs, request);
  // Every output is checked before anything changes: a refused sweep leaves everything as it was.
  std::error_code ec;
  const fs::path emitDir = fs::path(emit).parent_path().empty() ? fs::path(".") : fs::path(emit).parent_path();
  const bool emitDirExists = !emit.empty() && fs::is_directory(emitDir, ec); // else DIR itself, created below
  if (emitDirExists) checkOutputPath(emit);
  if (frameArgs.has("--save-preset")) checkOutputPath(frameArgs.get("--save-preset"));
  prepareSweepFolder(plan.dir, args.has("--force")); // exit 6 unless new, empty, or a sweep with --force
  fs::create_directories(plan.dir, ec);
  if (ec || !fs::is_directory(plan.dir)) outputError("cannot create '" + plan.dir + "'" + (ec ? ": " + ec.message() : ""));
  if (!emit.empty() && !emitDirExists) checkOutputPath(emit);
  if (frameArgs.has("--save-preset")) saveRequestedPreset(resolveFrame(frameArgs));
  writeSweepPlan(plan);

  if (!emit.empty()) {
    std::string lines;
    for (const auto& line : sweepJobLines(plan)) lines += line + "\n";
    writeTextAtomically(emit, lines);
    std::fprintf(stderr,
                 "sweep: planned %zu points and %zu references in %s; wrote %zu jobs to %s (references first).\n"
                 "sweep: when every job has finished: rtlab sweep --collect %s\n",
                 plan.points.size(), plan.references.size(), plan.dir.c_str(),
                 plan.points.size() + plan.references.size(), emit.c_str(), shellQuote(plan.dir).c_str());
    return 0;
  }

  std::vector<int> references;
  for (int k = 0; k < int(plan.references.size()); ++k)
    if (!referenceFromCache(plan, k)) references.push_back(k);
  runSweepJobs(plan, references, jobs);
  SweepCollection collection = collectSweep(plan.dir);
  if (collected) *collected = std::move(collection);
  std::fprintf(stderr, "sweep: wrote %s and %s\n", (fs::path(plan.dir) / "results.csv").c_str(),
               (fs::path(plan.dir) / "report.html").c_str());
  return 0;
}

} // namespace

int runSweep(int argc, char** argv) { return sweepMain(argc, argv, nullptr); }

SweepCollection runSweepCommand(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"rtlab", "sweep"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  SweepCollection collection;
  sweepMain(int(all.size()), argv.data(), &collection);
  if (collection.results.empty() && collection.plan.points.empty())
    throw Error(ExitCode::Internal, "runSweepCommand: not a direct sweep");
  return collection;
}

} // namespace rtlab
