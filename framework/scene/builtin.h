// Built-in procedural scenes, each made to show specific techniques (DESIGN.md "Scenes").
#pragma once
#include "scene/scene.h"

#include <string>
#include <vector>

namespace rtlab {

// Names in the order `rtlab list` prints them: contact, stacked, cornell, panes, arealight.
const std::vector<std::string>& builtinSceneNames();
bool isBuiltinScene(const std::string& name);
// Throws Error(Usage) naming the scene if unknown.
Scene makeBuiltinScene(const std::string& name);

} // namespace rtlab
