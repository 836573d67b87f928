// rtlab list: stages, techniques with their parameters and debug views, scenes, AOVs; with
// --scene also the scene's light and camera parameters. --json gives docs/contract.md's schema.
#include "app/args.h"
#include "app/commands.h"
#include "frame/aovs.h"
#include "frame/registry.h"
#include "frame/stages.h"
#include "params/param_spec.h"
#include "scene/builtin.h"
#include "scene/load.h"
#include "scene/scene_params.h"
#include "util/version.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace rtlab {
namespace {

void printParams(const std::vector<ParamSpec>& params, const char* indent) {
  for (const auto& p : params) {
    std::cout << indent << p.key << " = " << formatParamValue(p, p.def) << "  (" << paramTypeName(p.type) << ", "
              << describeRange(p) << (p.unit.empty() ? "" : ", " + p.unit) << (p.scale == ParamScale::Log ? ", log" : "")
              << ")  " << p.help << "\n";
  }
}

} // namespace

int runList(int argc, char** argv) {
  const std::vector<OptionSpec> specs = {
      {"--json", "", false, "", "machine-readable output (docs/contract.md schema)"},
      {"--scene", "", true, "S", "also list this scene's light and camera parameters"},
  };
  Args args("list", specs, argc, argv, 2);
  if (args.help()) {
    std::cout << formatHelp("rtlab list [--json] [--scene S]",
                            "Lists stages, techniques, parameters, debug views, built-in scenes and AOVs.", specs);
    return 0;
  }
  const auto& registry = TechniqueRegistry::instance();
  std::vector<ParamSpec> sceneParams;
  if (args.has("--scene")) sceneParams = sceneParamSpecs(loadScene(args.get("--scene")));

  const std::vector<std::string> aovs = knownAovNames(registry);

  if (args.has("--json")) {
    nlohmann::ordered_json j;
    j["schema"] = 1;
    j["version"] = versionString();
    auto stageArray = nlohmann::ordered_json::array();
    for (const auto& s : stages()) {
      nlohmann::ordered_json sj;
      sj["id"] = s.id;
      sj["slot"] = s.exclusive ? "exclusive" : "stack";
      sj["output"] = s.output;
      sj["params"] = nlohmann::ordered_json::array();
      for (const auto& p : s.params) sj["params"].push_back(paramSpecToJson(p));
      // Extensions (docs/stages.md): the rest of the stage's declaration.
      sj["order"] = s.order;
      sj["predicate"] = predicateName(s.predicate);
      sj["lighting"] = lightingEffectName(s.lighting);
      if (s.feedsLighting()) sj["neutral"] = s.neutral;
      else sj["neutral"] = nullptr; // colour stages: identity, their version aliases the input
      sj["color_version"] = s.colorVersion;
      sj["fallback"] = s.fallback;
      if (s.aov.name.empty()) sj["aov"] = nullptr;
      else {
        nlohmann::ordered_json aj;
        aj["name"] = s.aov.name;
        aj["channels"] = s.aov.channels;
        aj["rule"] = aovRuleName(s.aov.rule);
        switch (s.aov.rule) { // docs/stages.md "Stage AOVs"
        case AovRule::OutputOrNeutral: aj["neutral"] = s.neutral; break;
        case AovRule::TechniqueResource: aj["neutral"] = s.aov.neutral; break;
        case AovRule::ColorVersionCoverage: aj["neutral"] = nullptr; break; // always the colour version
        }
        sj["aov"] = aj;
      }
      stageArray.push_back(sj);
    }
    j["stages"] = stageArray;
    auto techArray = nlohmann::ordered_json::array();
    for (const auto& e : registry.entries()) {
      nlohmann::ordered_json tj;
      tj["id"] = e.info.id;
      tj["stage"] = e.info.stage;
      tj["title"] = e.info.title;
      tj["summary"] = e.info.summary;
      tj["params"] = nlohmann::ordered_json::array();
      for (const auto& p : e.info.params) tj["params"].push_back(paramSpecToJson(p));
      tj["aovs"] = nlohmann::ordered_json::array();
      for (const auto& v : e.info.debugViews) tj["aovs"].push_back(v.name);
      tj["showcase_scene"] = e.info.showcaseScene;
      techArray.push_back(tj);
    }
    j["techniques"] = techArray;
    j["scenes"] = builtinSceneNames();
    j["aovs"] = aovs;
    auto tonemap = nlohmann::ordered_json::array();
    for (const auto& p : tonemapParams()) tonemap.push_back(paramSpecToJson(p));
    j["tonemap_params"] = tonemap;
    if (args.has("--scene")) {
      auto sp = nlohmann::ordered_json::array();
      for (const auto& p : sceneParams) sp.push_back(paramSpecToJson(p));
      j["scene_params"] = sp;
    }
    std::cout << j.dump(2) << "\n";
    return 0;
  }

  std::cout << "rtlab " << versionString() << "\n\nStages (in frame order):\n";
  for (const auto& s : stages()) {
    std::cout << "  " << s.id << " (" << (s.exclusive ? "exclusive" : "stack") << ", output " << s.output << ")\n";
    printParams(s.params, "      ");
    for (const auto& e : registry.entries()) {
      if (e.info.stage != s.id) continue;
      std::cout << "    " << e.info.id << ": " << e.info.title << "\n";
      printParams(e.info.params, "      ");
      for (const auto& v : e.info.debugViews) std::cout << "      debug view " << v.name << ": " << v.help << "\n";
    }
  }
  std::cout << "\nTone mapping:\n";
  printParams(tonemapParams(), "  ");
  std::cout << "\nScenes:";
  for (const auto& s : builtinSceneNames()) std::cout << " " << s;
  std::cout << "  (or a .gltf/.glb file)\n\nAOVs:\n";
  for (const auto& a : builtinAovs()) std::cout << "  " << a.name << ": " << a.help << "\n";
  if (args.has("--scene")) {
    std::cout << "\nScene parameters of '" << args.get("--scene") << "':\n";
    printParams(sceneParams, "  ");
  }
  return 0;
}

} // namespace rtlab
