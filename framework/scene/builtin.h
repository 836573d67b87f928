// Built-in procedural scenes, each made to show specific techniques (docs/scene-format.md "Built-in scenes").
#pragma once
#include "scene/scene.h"

#include <string>
#include <vector>

namespace rtlab {

// Names in the order `rtlab list` prints them: contact, stacked, cornell, panes, arealight, glow.
const std::vector<std::string>& builtinSceneNames();
bool isBuiltinScene(const std::string& name);
// Throws Error(Usage) naming the scene if unknown.
Scene makeBuiltinScene(const std::string& name);

} // namespace rtlab
