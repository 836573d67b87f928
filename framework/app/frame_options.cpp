#include "app/frame_options.h"

#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "frame/selection.h"
#include "params/preset.h"
#include "scene/load.h"
#include "scene/scene_params.h"
#include "util/error.h"

#include <charconv>

namespace rtlab {

std::vector<OptionSpec> frameOptionSpecs() {
  return {
      {"--scene", "", true, "S", "scene file (.gltf/.glb) or built-in name (default contact)"},
      {"--technique", "-t", true, "ID[,ID]", "activate techniques (repeatable); 'none' deactivates all"},
      {"--set", "", true, "KEY=VALUE", "set any parameter (repeatable); see 'rtlab list'"},
      {"--preset", "", true, "FILE", "preset file, applied before -t and --set"},
      {"--save-preset", "", true, "FILE", "write the resolved state as a preset"},
      {"--size", "", true, "WxH", "frame size in pixels, each 1..8192 (default 640x360)"},
      {"--frames", "", true, "N", "measured frames, after 2 warm-up frames when N > 1 (default 1)"},
      {"--seed", "", true, "N", "seed of every stochastic part (default 1)"},
      {"--backend", "", true, "B", "headless context: auto|egl|osmesa (default auto)"},
      {"--timing", "", true, "M", "pass timing: auto|gpu-query|cpu-finish (default auto)"},
  };
}

void parseSize(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  auto parse = [&](std::string_view s, int& out) {
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return !s.empty() && ec == std::errc() && ptr == s.data() + s.size() && out >= 1 && out <= 8192;
  };
  if (x == std::string::npos || !parse(std::string_view(text).substr(0, x), width) ||
      !parse(std::string_view(text).substr(x + 1), height))
    usageError("invalid --size '" + text + "': expected WxH with each in 1..8192");
}

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
