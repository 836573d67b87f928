#include "app/showcase_atlas.h"

#include "app/html.h"
#include "app/sweep_command.h"
#include "app/sweep_report.h"
#include "frame/registry.h"
#include "frame/stages.h"
#include "params/sweep_spec.h"
#include "reference/reference_registry.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>

namespace rtlab {
namespace {

// "KEY=LOW,DEFAULT" for an integer key: a quarter of the default, within the key's range.
std::string lowAndDefault(const ParamSpec& spec) {
  const int def = int(spec.def.v[0]);
  const int low = std::max(int(spec.min), def / 4);
  return spec.key + "=" + std::to_string(low) + "," + std::to_string(def);
}

bool isCountKey(const ParamSpec& spec) {
  return spec.type == ParamType::Int && spec.scale == ParamScale::Log && spec.def.v[0] / 4 >= spec.min;
}

// The scene most of the stage's techniques name as their showcase scene (the first on a tie).
std::string stageScene(const std::vector<std::string>& techniques) {
  std::map<std::string, int> votes;
  std::string best;
  for (const auto& id : techniques) {
    const std::string& scene = TechniqueRegistry::instance().get(id).info.showcaseScene;
    const int n = ++votes[scene];
    if (best.empty() || n > votes[best]) best = scene;
  }
  return best;
}

std::string figure(const std::string& file, const std::string& caption, const std::string& figures = "") {
  return "<figure><a href=\"" + html::escape(file) + "\"><img src=\"" + html::escape(file) + "\" alt=\"" +
         html::escape(caption) + "\"></a>" + figures + "<figcaption>" + caption + "</figcaption></figure>";
}

std::string join(const std::vector<std::string>& items, const std::string& sep) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : sep) + i;
  return s;
}

std::string stageSection(const StageInfo& stage, const std::string& scene, const std::string& folder,
                         const SweepCollection& c) {
  const SweepPlan& plan = c.plan;
  std::string s = "<p class=\"meta\">Scene <code>" + html::escape(scene) + "</code>, the <code>" + html::escape(plan.aov) +
                  "</code> AOV of every " + html::escape(stage.id) + " technique against the stage's reference (" +
                  referenceSamplesText(plan) + ", computed on the CPU), at each technique's defaults; errors over "
                  "the surface pixels (docs/metrics.md). Full sweep: <a href=\"" + html::escape(folder) +
                  "/report.html\">" + html::escape(folder) + "/report.html</a>.</p>\n";
  const std::string warning = sweepTimingWarning(plan, c.info);
  if (!warning.empty()) s += "<p class=\"warning\" role=\"alert\"><strong>Warning:</strong> " + html::escape(warning) + "</p>\n";

  // Each technique at its defaults (its last point) beside the reference.
  std::string row;
  for (const auto& r : c.info.references)
    if (r.hash == plan.points.back().reference)
      row += figure(folder + "/" + r.file, "<strong>reference</strong><br>" + referenceSamplesText(plan));
  for (const auto& technique : plan.techniques) {
    const SweepResult* at = nullptr;
    for (const auto& r : c.results)
      if (r.point->technique == technique) at = &r;
    if (!at) continue;
    const std::string figures = "<a href=\"" + html::escape(folder + "/" + at->heatFile) + "\"><img class=\"heat\" src=\"" +
                                html::escape(folder + "/" + at->heatFile) + "\" alt=\"" + html::escape(technique) +
                                " error heat map\"></a>";
    const std::string caption = "<strong>" + html::escape(technique) + "</strong><br><span class=\"figures\">RMSE " +
                                html::escape(formatMetric(at->metrics.rmse)) + " &middot; FLIP " +
                                html::escape(formatMetric(at->metrics.flip)) + " &middot; " + html::formatMs(at->ms) +
                                " ms</span>";
    row += figure(folder + "/" + at->aovFile, caption, figures);
  }
  s += "<div class=\"atlas\">" + row + "</div>\n" + heatScaleHtml(plan, c.info);
  s += "<h3>Error against time</h3>\n" + sweepChartSvg(plan, c.results, folder + "/report.html#point-") + "\n";
  s += "<p class=\"meta\">" + std::to_string(plan.points.size()) + " points, " + std::to_string(plan.frames) +
       " measured frames each after " + std::to_string(sweepWarmupFrames(plan)) + " unmeasured, one job at a time; " +
       "timing " + html::escape(c.info.timing) + " on " + html::escape(c.info.renderer) +
       ". Click a point for its row in the sweep's report. Reproduce:</p>\n<pre class=\"command\"><code>" +
       html::escape(plan.command) + "</code></pre>\n";
  const auto notes = sweepNotes(plan);
  if (!notes.empty()) {
    s += "<ul class=\"notes\">";
    for (const auto& n : notes) s += "<li>" + html::escape(n) + "</li>";
    s += "</ul>\n";
  }
  return s;
}

} // namespace

std::vector<std::string> atlasVaries(const std::string& stageId, const std::vector<std::string>& techniques) {
  std::vector<std::string> varies;
  const StageInfo* stage = findStage(stageId);
  const ReferenceEntry* reference = ReferenceRegistry::instance().findStage(stageId);
  if (stage)
    for (const auto& spec : stage->params)
      if (isCountKey(spec) && !(reference && reference->definesKey(spec.key))) varies.push_back(lowAndDefault(spec));
  if (!varies.empty()) return varies;
  for (const auto& id : techniques)
    for (const auto& spec : TechniqueRegistry::instance().get(id).info.params)
      if (isCountKey(spec)) {
        varies.push_back(lowAndDefault(spec));
        break;
      }
  return varies;
}

std::vector<AtlasStage> buildAtlas(const AtlasOptions& options) {
  std::vector<AtlasStage> sections;
  const auto& registry = TechniqueRegistry::instance();
  for (const auto& stage : stages()) {
    if (!ReferenceRegistry::instance().findStage(stage.id)) continue; // no reference to measure against
    std::vector<std::string> techniques;
    for (const auto& e : registry.entries())
      if (e.info.stage == stage.id) techniques.push_back(e.info.id);
    if (techniques.empty()) continue;
    const std::string scene = stageScene(techniques);
    const std::string folder = "sweeps/" + stage.id;
    // --spp is the sampling references' count; a reference that does not sample takes 1.
    const int spp = std::min(options.spp, ReferenceRegistry::instance().findStage(stage.id)->maxSpp);
    std::vector<std::string> args = {"--scene", scene, "--size", std::to_string(options.width) + "x" + std::to_string(options.height),
                                     "--frames", std::to_string(options.frames), "--spp", std::to_string(spp)};
    args.insert(args.end(), options.frameArgs.begin(), options.frameArgs.end());
    args.insert(args.end(), {"-t", join(techniques, ",")});
    for (const auto& v : atlasVaries(stage.id, techniques)) args.insert(args.end(), {"--vary", v});
    // One job at a time: the atlas reports the times. --force: the showcase owns this folder.
    args.insert(args.end(), {"--out", options.outDir + "/" + folder, "--jobs", "1", "--force"});
    std::cerr << "showcase: stage " << stage.id << ": sweeping " << join(techniques, ", ") << " on " << scene << "\n";
    const SweepCollection c = runSweepCommand(args);
    AtlasStage section;
    section.stage = stage.id;
    section.anchor = "atlas-" + stage.id;
    section.title = "Stage " + stage.id + ": each technique against the reference";
    section.html = stageSection(stage, scene, folder, c);
    sections.push_back(std::move(section));
  }
  return sections;
}

} // namespace rtlab
