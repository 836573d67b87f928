// rtlab showcase: the main job. First the measured atlas (showcase_atlas.h): per stage with a
// reference, a small sweep of its techniques, shown as each technique beside the reference with
// its error figures and heat map, and the stage's error-against-time chart. Then the plain lit
// frame of every built-in scene and every registered technique on its showcase scene (color, the
// stage's AOV, its debug views), with stats. All into an output folder, with index.html showing
// them (relative links only). Files are written atomically; index.html comes last.
#include "app/commands.h"
#include "app/frame_options.h"
#include "app/html.h"
#include "app/measure.h"
#include "app/run_info.h"
#include "app/showcase_atlas.h"
#include "app/sweep_report.h"
#include "frame/aovs.h"
#include "frame/registry.h"
#include "frame/stages.h"
#include "scene/builtin.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/version.h"

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

namespace rtlab {
namespace {

struct Job {
  std::string title, scene, technique; // technique "" = the plain frame
};

std::string fileStem(const Job& job) { return job.scene + "_" + (job.technique.empty() ? "plain" : job.technique); }

std::string figure(const std::string& file, const std::string& caption) {
  return "<figure><a href=\"" + html::escape(file) + "\"><img src=\"" + html::escape(file) + "\" alt=\"" +
         html::escape(caption) + "\"></a><figcaption>" + html::escape(caption) + "</figcaption></figure>";
}

} // namespace

int runShowcase(int argc, char** argv) {
  const std::vector<OptionSpec> specs = {
      {"--out", "", true, "DIR", "output folder (default out)"},
      {"--size", "", true, "WxH", "frame size (default 640x360)"},
      {"--frames", "", true, "N", "measured frames per render, after 2 warm-up frames when N > 1 (default 5)"},
      {"--backend", "", true, "B", "headless context: auto|egl|osmesa (default auto)"},
      {"--timing", "", true, "M", "pass timing: auto|gpu-query|cpu-finish (default auto)"},
      {"--spp", "", true, "N", "the atlas references' samples per pixel, 1..65536 (default 32)"},
  };
  Args args("showcase", specs, argc, argv, 2);
  if (args.help()) {
    std::cout << formatHelp("rtlab showcase [--out DIR] [--size WxH] [--frames N] [--spp N]",
                            "The measured atlas: per stage with a reference (shadow, ao), a small sweep of its\n"
                            "techniques into DIR/sweeps/<stage>/, each technique beside the reference with its\n"
                            "RMSE, FLIP and heat map, and the error-against-time chart. Then every built-in scene\n"
                            "and every technique on its showcase scene, with stats. Writes DIR/index.html.",
                            specs);
    return 0;
  }
  FrameOptions options;
  options.frames = 5;
  if (args.has("--size")) parseSize(args.get("--size"), options.width, options.height);
  if (args.has("--frames")) options.frames = int(parseIntOption("--frames", args.get("--frames"), 1, 1000));
  if (args.has("--backend")) options.backend = parseBackend(args.get("--backend"));
  if (args.has("--timing")) options.timing = parseTimingChoice(args.get("--timing"));
  AtlasOptions atlas;
  if (args.has("--spp")) atlas.spp = int(parseIntOption("--spp", args.get("--spp"), 1, 65536));
  for (const char* o : {"--backend", "--timing"})
    if (args.has(o)) atlas.frameArgs.insert(atlas.frameArgs.end(), {o, args.get(o)});
  const std::string outDir = args.get("--out", "out");
  std::error_code ec;
  std::filesystem::create_directories(outDir, ec);
  if (ec) outputError("cannot create '" + outDir + "': " + ec.message());
  checkOutputPath(outDir + "/index.html");
  const auto started = std::chrono::steady_clock::now();

  // The atlas first: its sweeps' jobs are child processes that want the whole machine.
  atlas.outDir = outDir;
  atlas.width = options.width;
  atlas.height = options.height;
  atlas.frames = options.frames;
  const std::vector<AtlasStage> stagesShown = buildAtlas(atlas);

  const TechniqueRegistry& registry = TechniqueRegistry::instance();
  std::vector<Job> jobs;
  for (const auto& scene : builtinSceneNames()) jobs.push_back({"Scene '" + scene + "' (plain lit frame)", scene, ""});
  for (const auto& e : registry.entries()) jobs.push_back({e.info.title, e.info.showcaseScene, e.info.id});

  auto context = createHeadlessContext(options.backend);
  const TimingMethod timing = resolveTiming(options.timing, context->info().software);
  std::map<std::string, std::unique_ptr<Renderer>> renderers; // one per scene: programs and uploads reused
  const bool tty = ::isatty(2);
  std::string body = "<h1>rtlab showcase</h1><p class=\"meta\">rtlab " + html::escape(versionString()) + " (commit " +
                     html::escape(gitCommit()) + ") &middot; " + html::escape(context->info().renderer) + " via " +
                     html::escape(context->backendName()) + " &middot; timing " + timingName(timing) + " &middot; " +
                     std::to_string(options.width) + "x" + std::to_string(options.height) + ", median of " +
                     std::to_string(options.frames) + " frames</p>\n";
  std::string toc = "<h2>Contents</h2><p>The measured atlas</p><ul>";
  std::string sections;
  for (const auto& st : stagesShown) {
    toc += "<li><a href=\"#" + html::escape(st.anchor) + "\">" + html::escape(st.title) + "</a></li>";
    sections += "<h2 id=\"" + html::escape(st.anchor) + "\">" + html::escape(st.title) + "</h2>\n" + st.html;
  }
  toc += "</ul><p>Every scene and technique</p><ul>";
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const Job& job = jobs[k];
    std::cerr << (tty ? "\r" : "") << "[" << k + 1 << "/" << jobs.size() << "] " << fileStem(job) << (tty ? "        " : "\n")
              << std::flush;
    ResolvedFrame frame = makeResolvedFrame(job.scene, job.technique, options);
    auto& renderer = renderers[job.scene];
    if (!renderer) {
      renderer = std::make_unique<Renderer>(registry);
      renderer->setScene(frame.scene);
    }
    std::vector<std::string> aovs;
    std::vector<ParamSpec> shownParams = tonemapParams();
    if (!job.technique.empty()) {
      const auto& info = registry.get(job.technique).info;
      const StageInfo* stage = findStage(info.stage);
      if (!stage->aov.name.empty()) aovs.push_back(stage->aov.name); // the stage's AOV (docs/stages.md "Stage AOVs")
      for (const auto& v : info.debugViews) aovs.push_back(v.name);
      shownParams = stage->params;
      shownParams.insert(shownParams.end(), info.params.begin(), info.params.end());
    }
    FrameOutputs outputs{aovs, true};
    const FrameStats stats = renderMeasured(*renderer, frame, outputs, timing, true);
    const std::string stem = fileStem(job);
    std::string figures;
    writeImage(outDir + "/" + stem + "_color.png", renderer->readDisplayColor(), PngEncoding::Srgb);
    figures += figure(stem + "_color.png", "color");
    for (const auto& aov : aovs) {
      const std::string file = stem + "_" + aov + ".png";
      writeImage(outDir + "/" + file, renderer->readAov(aov), pngEncodingForAov(aov));
      figures += figure(file, aov);
    }
    writeTextAtomically(outDir + "/" + stem + "_stats.json", statsJson(frame, *context, timing, stats).dump(2) + "\n");

    std::vector<std::vector<std::string>> passRows;
    for (const auto& p : stats.passes())
      passRows.push_back({p.name, p.technique.empty() ? "(frame)" : p.technique, html::formatMs(p.ms), html::formatMs(p.msMin),
                          html::formatMs(p.msMax)});
    std::vector<std::vector<std::string>> resRows;
    for (const auto& r : stats.resources()) resRows.push_back({r.name, html::formatBytes(r.bytes)});
    std::vector<std::vector<std::string>> paramRows;
    for (const auto& spec : shownParams)
      paramRows.push_back({spec.key, formatParamValue(spec, frame.params.value(spec.key)), describeRange(spec), spec.unit, spec.help});
    const std::string anchor = stem;
    toc += "<li><a href=\"#" + html::escape(anchor) + "\">" + html::escape(job.title) + "</a></li>";
    sections += "<h2 id=\"" + html::escape(anchor) + "\">" + html::escape(job.title) + "</h2>\n<p class=\"meta\">scene " +
                html::escape(job.scene) + (job.technique.empty() ? "" : ", technique " + html::escape(job.technique)) +
                " &middot; frame " + html::formatMs(stats.frameMs()) + " ms &middot; GPU memory " +
                html::formatBytes(stats.resourceBytes()) + " &middot; GL errors " + std::to_string(stats.glErrors()) +
                " &middot; <a href=\"" + html::escape(stem) + "_stats.json\">stats JSON</a></p>\n" + figures + "\n" +
                "<h3>Passes (ms)</h3>" + html::table({"pass", "technique", "median", "min", "max"}, passRows) +
                "<h3>Parameters</h3>" + html::table({"key", "value", "range", "unit", "help"}, paramRows) +
                "<h3>Resources</h3>" + html::table({"resource", "size"}, resRows) + "\n";
  }
  if (tty) std::cerr << "\n";
  body += toc + "</ul>\n" + sections;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  body += "<p class=\"meta\">Made in " + std::to_string(int(seconds + 0.5)) + " s.</p>\n";
  const std::string css = ".atlas figure{vertical-align:top}.atlas figure img{display:block;width:240px}"
                          ".atlas img.heat{margin-top:2px}.figures{font-variant-numeric:tabular-nums}\n";
  writeTextAtomically(outDir + "/index.html", html::page("rtlab showcase", body, css + sweepPageCss()));
  std::cerr << "wrote " << outDir << "/index.html (" << stagesShown.size() << " stage sweeps, " << jobs.size()
            << " renders) in " << int(seconds + 0.5) << " s\n";
  return 0;
}

} // namespace rtlab
