// glTF 2.0 (.gltf with embedded or external buffers, .glb) via tinygltf, followed by rtlab's own
// validation (accessor bounds, index and texture references, node cycles) before anything reaches
// the GPU. Every failure throws Error(Input) with one line naming the file and the problem.
#pragma once
#include "scene/scene.h"

#include <string>

namespace rtlab {

Scene loadGltf(const std::string& path);

} // namespace rtlab
