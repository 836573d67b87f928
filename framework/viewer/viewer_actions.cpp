#include "viewer/viewer_actions.h"

#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "frame/stages.h"
#include "params/preset.h"
#include "scene/load.h"
#include "scene/scene_params.h"
#include "util/error.h"
#include "viewer/json_fields.h"
#include "viewer/script.h"
#include "viewer/view_fields.h"

namespace rtlab {
namespace {

bool isSceneKey(const std::string& key) {
  return key.rfind("light", 0) == 0 || key.rfind("camera.", 0) == 0 || key.rfind("scene.", 0) == 0;
}

void applyScene(ViewerState& state) {
  applySceneParams(state.params, state.scene);
  syncCameraFromParams(state);
}

void applyBookmark(ViewerState& state, const Bookmark& b) {
  if (b.scene && *b.scene != state.sceneSpec) loadSceneAction(state, *b.scene);
  if (b.techniques) {
    TechniqueSelection selection(*state.registry);
    for (const auto& id : *b.techniques)
      selection.activate(id);
    state.selection = selection;
    state.techniquesChanged = true;
  }
  for (const auto& [key, value] : b.params.items())
    state.params.setJson(key, value); // on the caller's copy of the state (bookmarkAction)
  applyScene(state);
  if (b.cameraPosition || b.cameraTarget || b.cameraFov)
    cameraAction(state, b.cameraPosition, b.cameraTarget, b.cameraFov);
  if (!b.view.empty()) viewAction(state, b.view);
  if (!b.compare.empty()) compareAction(state, b.compare);
  if (b.panel) state.showPanel = *b.panel;
  for (const auto& [name, open] : b.sections.items())
    sectionAction(state, name, open.get<bool>());
}

} // namespace

void setStatus(ViewerState& state, std::string message, bool transient) {
  state.status = std::move(message);
  state.statusTransient = transient;
}

const char* debugModeName(DebugMode mode) {
  switch (mode) {
  case DebugMode::Full:
    return "full";
  case DebugMode::Pip:
    return "pip";
  default:
    return "off";
  }
}

const char* compareModeName(CompareMode mode) {
  switch (mode) {
  case CompareMode::Reference:
    return "reference";
  case CompareMode::Snapshot:
    return "snapshot";
  case CompareMode::Difference:
    return "difference";
  default:
    return "off";
  }
}

DebugMode parseDebugMode(const std::string& name) {
  if (name == "full") return DebugMode::Full;
  if (name == "pip") return DebugMode::Pip;
  if (name == "off") return DebugMode::Off;
  usageError("unknown view mode '" + name + "' (full, pip, off)");
}

CompareMode parseCompareMode(const std::string& name) {
  if (name == "reference") return CompareMode::Reference;
  if (name == "snapshot") return CompareMode::Snapshot;
  if (name == "difference") return CompareMode::Difference;
  if (name == "off") return CompareMode::Off;
  usageError("unknown compare mode '" + name + "' (reference, snapshot, difference, off)");
}

void loadSceneAction(ViewerState& state, const std::string& spec) {
  Scene scene = loadScene(spec); // Error(Usage) or Error(Input): the state is untouched
  ParamSet params = makeParamSet(scene, *state.registry);
  for (const auto& s : state.params.specs())
    if (!isSceneKey(s.key) && params.has(s.key)) params.set(s.key, state.params.value(s.key));
  state.scene = std::move(scene);
  state.params = std::move(params);
  state.sceneSpec = spec;
  state.camera.setHome(state.scene.camera);
  applyScene(state);
  state.sceneChanged = true;
  ++state.sceneGeneration;
}

void selectTechniqueAction(ViewerState& state, const std::string& stage, const std::string& id) {
  if (!findStage(stage)) usageError("unknown stage '" + stage + "'");
  if (id == "off" || id == "none") { // "none" as `-t none` and 'rtlab list' spell it
    for (const auto& active : state.selection.ordered())
      if (state.registry->get(active).info.stage == stage) state.selection.deactivate(active);
  } else {
    const auto& entry = state.registry->get(id);
    if (entry.info.stage != stage)
      usageError("technique '" + id + "' belongs to stage '" + entry.info.stage + "', not '" + stage + "'");
    state.selection.activate(id);
  }
  state.techniquesChanged = true;
}

void setTechniqueActiveAction(ViewerState& state, const std::string& id, bool on) {
  state.registry->get(id); // Error(Usage) naming an unknown id, also when switching off
  if (on)
    state.selection.activate(id);
  else
    state.selection.deactivate(id);
  state.techniquesChanged = true;
}

void setParamAction(ViewerState& state, const std::string& key, const nlohmann::json& value) {
  ParamSet copy = state.params; // a camera key is checked with the scene before it is kept
  copy.setJson(key, value);
  if (isSceneKey(key)) applySceneParams(copy, state.scene);
  state.params = std::move(copy);
  if (isSceneKey(key)) syncCameraFromParams(state);
}

void setParamValueAction(ViewerState& state, const std::string& key, const ParamValue& value) {
  setParamAction(state, key, paramValueToJson(state.params.spec(key), value));
}

void resetParamAction(ViewerState& state, const std::string& key) {
  const ParamSpec& spec = state.params.spec(key);
  setParamAction(state, key, paramValueToJson(spec, spec.def));
}

void cameraAction(ViewerState& state, const std::optional<glm::vec3>& position, const std::optional<glm::vec3>& target,
                  const std::optional<float>& fov) {
  ParamSet copy = state.params;
  if (position) copy.set("camera.position", ParamValue::vec3(*position));
  if (target) copy.set("camera.target", ParamValue::vec3(*target));
  if (fov) copy.set("camera.fov", ParamValue::scalar(*fov));
  applySceneParams(copy, state.scene); // Error(Usage) when the target equals the position
  state.params = std::move(copy);
  syncCameraFromParams(state);
}

void resetCameraAction(ViewerState& state) {
  state.camera.reset();
  syncCameraToParams(state);
}

void frameSceneAction(ViewerState& state) {
  glm::vec3 lo, hi;
  sceneBounds(state.scene, lo, hi);
  state.camera.frame(lo, hi);
  syncCameraToParams(state);
}

void viewAction(ViewerState& state, const nlohmann::json& fields) {
  const std::string where = "view";
  checkViewFields(fields, where);
  DebugViewSettings v = state.view;
  if (auto aov = optionalString(fields, "aov", where)) {
    checkViewAov(*aov, *state.registry);
    v.aov = *aov;
  }
  if (auto mode = optionalString(fields, "mode", where)) v.mode = parseDebugMode(*mode);
  if (auto lo = optionalNumber(fields, "min", where)) v.min = float(*lo);
  if (auto hi = optionalNumber(fields, "max", where)) v.max = float(*hi);
  if (auto fc = optionalBool(fields, "false_color", where)) v.falseColor = *fc;
  if (!(v.min < v.max))
    usageError("view range: min (" + shortestDecimal(v.min) + ") must be less than max (" + shortestDecimal(v.max) +
               ")");
  state.view = v;
}

void compareAction(ViewerState& state, const nlohmann::json& fields) {
  const std::string where = "compare";
  checkCompareFields(fields, where);
  if (auto mode = optionalString(fields, "mode", where)) state.compare.mode = parseCompareMode(*mode);
  if (auto divider = optionalNumber(fields, "divider", where)) state.compare.divider = float(*divider);
}

void panelAction(ViewerState& state, bool shown) {
  state.showPanel = shown;
}

void sectionAction(ViewerState& state, const std::string& name, bool open) {
  checkSectionName(name, "section");
  state.sectionRequests.emplace_back(name, open);
}

double rampValue(double from, double to, long step, long frames) {
  if (step >= frames) return to; // the last frame holds exactly the end value
  return from + (to - from) * double(step) / double(frames);
}

void renderScaleAction(ViewerState& state, double scale) {
  requireRange(scale, kRenderScaleMin, kRenderScaleMax, "render scale", "render_scale");
  state.renderScale = float(scale);
}

void savePresetAction(const ViewerState& state, const std::string& path) {
  savePreset(path, state.sceneSpec, state.selection.ordered(), state.params);
}

void loadPresetAction(ViewerState& state, const std::string& path) {
  const Preset preset = loadPreset(path);
  TechniqueSelection selection = state.selection;
  if (preset.techniques) {
    selection.clear();
    for (const auto& id : *preset.techniques)
      selection.activate(id);
  }
  ParamSet copy = state.params;
  applyPreset(preset, copy, path);
  applySceneParams(copy, state.scene);
  state.params = std::move(copy);
  state.selection = selection;
  state.techniquesChanged = true;
  syncCameraFromParams(state);
}

void bookmarkAction(ViewerState& state, int index) {
  if (index < 0 || std::size_t(index) >= state.bookmarks.size())
    usageError("bookmark " + std::to_string(index) + " does not exist (" + std::to_string(state.bookmarks.size()) +
               " bookmarks)");
  const Bookmark& b = state.bookmarks[std::size_t(index)];
  // Applied to a copy and kept only when every part succeeded, as the other actions: a bookmark
  // of another scene is validated at start without that scene, so a part may still fail here.
  ViewerState next = state;
  applyBookmark(next, b);
  next.bookmark = index;
  setStatus(next, "bookmark " + std::to_string(index + 1) + "/" + std::to_string(next.bookmarks.size()) + ": " + b.name,
            true);
  state = std::move(next);
}

void syncCameraToParams(ViewerState& state) {
  const Camera& c = state.camera.camera();
  if (state.params.getVec3("camera.position") != c.position)
    state.params.set("camera.position", ParamValue::vec3(c.position));
  if (state.params.getVec3("camera.target") != c.target) state.params.set("camera.target", ParamValue::vec3(c.target));
  if (state.params.getFloat("camera.fov") != c.fovY) state.params.set("camera.fov", ParamValue::scalar(c.fovY));
}

void syncCameraFromParams(ViewerState& state) {
  Camera c = state.camera.camera();
  c.position = state.params.getVec3("camera.position");
  c.target = state.params.getVec3("camera.target");
  c.fovY = state.params.getFloat("camera.fov");
  state.camera.setCamera(c);
}

} // namespace rtlab
