#include "app/exercise_option.h"

#include "exercise/exercise_folder.h"
#include "frame/registry.h"
#include "frame/selection.h"
#include "frame/stages.h"
#include "frame/param_catalog.h"
#include "gl/shader_overlay.h"
#include "scene/load.h"

#include <algorithm>

namespace rtlab {

OptionSpec exerciseOptionSpec() {
  return {"--exercise", "", true, "DIR",
          "run with an exercise folder's files in place of the shipped ones (activates its technique without -t)"};
}

std::string applyExerciseOption(const Args& args, ResolvedFrame& frame) {
  if (!args.has("--exercise")) return "";
  const ExerciseFolder folder = readExerciseFolder(args.get("--exercise"));
  installShaderReplacements(folderReplacements(folder));
  if (!args.has("--technique")) {
    TechniqueSelection selection(TechniqueRegistry::instance());
    for (const auto& id : frame.techniques) selection.activate(id);
    selection.activate(folder.def->technique);
    frame.techniques = selection.ordered();
  }
  return "exercise " + folder.def->id + " (" + folder.dir + ")";
}

void installShaderReplacements(const std::vector<ShaderFileReplacement>& files) {
  gl::ShaderOverlay overlay;
  for (const auto& f : files) overlay[f.shaderRelative] = gl::ShaderReplacement{f.path, f.text, f.inMemory};
  gl::setShaderOverlay(std::move(overlay));
}

std::vector<ParamSpec> exerciseParams(const ExerciseDef& def) {
  const TechniqueRegistry& registry = TechniqueRegistry::instance();
  const TechniqueEntry& entry = registry.get(def.technique);
  std::vector<ParamSpec> out = entry.info.params;
  if (const StageInfo* stage = findStage(entry.info.stage)) out.insert(out.end(), stage->params.begin(), stage->params.end());
  // And every other key a view sets (a light's radius, another technique's key), as that view's
  // scene declares it.
  auto listed = [&](const std::string& key) {
    return std::any_of(out.begin(), out.end(), [&](const ParamSpec& p) { return p.key == key; });
  };
  for (const auto& view : def.views) {
    if (view.set.empty()) continue;
    const ParamSet params = makeParamSet(loadScene(view.scene), registry);
    for (const auto& [key, value] : view.set)
      if (!listed(key) && params.has(key)) out.push_back(params.spec(key));
  }
  return out;
}

} // namespace rtlab
