#include "app/frame_options.h"

#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "frame/selection.h"
#include "params/preset.h"
#include "scene/load.h"
#include "scene/scene_params.h"
#include "util/error.h"

namespace rtlab {

ResolvedFrame resolveFrame(const Args& args) {
  ResolvedFrame f;
  FrameOptions& o = f.options;
  if (args.has("--size")) parseSize(args.get("--size"), o.width, o.height);
  if (args.has("--frames")) o.frames = int(parseIntOption("--frames", args.get("--frames"), 1, 100000));
  if (args.has("--seed")) o.seed = unsigned(parseIntOption("--seed", args.get("--seed"), 0, 4294967295LL));
  if (args.has("--backend")) o.backend = parseBackend(args.get("--backend"));
  if (args.has("--timing")) o.timing = parseTimingChoice(args.get("--timing"));
  o.savePreset = args.get("--save-preset");

  const TechniqueRegistry& registry = TechniqueRegistry::instance();
  Preset preset;
  const std::string presetPath = args.get("--preset");
  if (!presetPath.empty()) preset = loadPreset(presetPath);
  o.sceneSpec = args.get("--scene", preset.scene.value_or("contact"));
  f.scene = loadScene(o.sceneSpec);
  f.params = makeParamSet(f.scene, registry);

  TechniqueSelection selection(registry);
  if (preset.techniques) {
    for (const auto& id : *preset.techniques) {
      try {
        selection.activate(id);
      } catch (const Error& e) {
        throw Error(e.code(), std::string(e.what()) + " in preset '" + presetPath + "'");
      }
    }
  }
  applyPreset(preset, f.params, presetPath);
  for (const auto& [name, value] : args.ordered())
    if (name == "--technique") selection.activateList(value);
  for (const auto& [name, value] : args.ordered())
    if (name == "--set") f.params.setAssignment(value);
  f.techniques = selection.ordered();
  applySceneParams(f.params, f.scene); // validates camera/light values now, before any GL work
  return f;
}

ResolvedFrame makeResolvedFrame(const std::string& sceneSpec, const std::string& techniques,
                                const FrameOptions& options) {
  ResolvedFrame f;
  f.options = options;
  f.options.sceneSpec = sceneSpec;
  f.scene = loadScene(sceneSpec);
  f.params = makeParamSet(f.scene, TechniqueRegistry::instance());
  TechniqueSelection selection(TechniqueRegistry::instance());
  if (!techniques.empty()) selection.activateList(techniques);
  f.techniques = selection.ordered();
  applySceneParams(f.params, f.scene);
  return f;
}

void saveRequestedPreset(const ResolvedFrame& frame) {
  if (frame.options.savePreset.empty()) return;
  savePreset(frame.options.savePreset, frame.options.sceneSpec, frame.techniques, frame.params);
}

} // namespace rtlab
