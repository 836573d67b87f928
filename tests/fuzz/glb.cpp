// Fuzz target: the glTF loader on a .glb file (gltf_scene.h: how file references are handled).
#include "gltf_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rtlab::fuzz::loadGltfInput(data, size, "scene.glb");
}
