// The two glTF fuzz targets (gltf.cpp: JSON text, glb.cpp: the binary container): the input is
// written to the scratch directory as scene.gltf / scene.glb and loaded by scene/gltf_loader.h,
// as `--scene FILE` does, so relative buffer and image URIs resolve inside the scratch directory
// (which holds only the input itself). Inputs that could name a file elsewhere are skipped: ".."
// anywhere, a JSON string that begins with "/" or with the escape "\/", a "\u" escape, or a "%"
// (tinygltf percent-decodes URIs). A fuzzed path must not reach /dev/stdin or a FIFO.
#pragma once
#include "scene/gltf_loader.h"
#include "util/log.h"

#include "fuzz_target.h"

namespace rtlab::fuzz {

inline bool mayNameOutsideFiles(std::string_view bytes) {
  for (const char* pattern : {"..", "\"/", "\\/", "\\u", "%"})
    if (bytes.find(pattern) != std::string_view::npos) return true;
  return false;
}

inline int loadGltfInput(const std::uint8_t* data, std::size_t size, const char* fileName) {
  if (size > kMaxInputBytes || mayNameOutsideFiles(text(data, size))) return -1;
  // Warnings (e.g. an unused chunk) are still composed, but not printed for every input.
  static const bool quiet = (setLogLevel(LogLevel::Quiet), true);
  (void)quiet;
  const std::string path = writeScratch(fileName, text(data, size));
  expectOnlyErrors([&] {
    const Scene scene = loadGltf(path);
    if (scene.instances.empty()) std::abort(); // loadGltf promises at least one instance
  });
  return 0;
}

} // namespace rtlab::fuzz
