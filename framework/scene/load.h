// `--scene S` resolution (docs/contract.md): an existing file, or a name ending in .gltf/.glb, is a file
// (missing or invalid: exit 3); otherwise a built-in scene name (unknown: exit 2).
#pragma once
#include "scene/scene.h"

#include <string>

namespace rtlab {

Scene loadScene(const std::string& spec);

} // namespace rtlab
