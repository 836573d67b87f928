// Files that replace shipped shaders for one process (docs/exercises.md): a student's exercise
// folder (`--exercise DIR`), or in-memory text such as an exercise's stubs. Keys are paths relative
// to shaders/ ("pcss/visibility.frag"); includes resolve through the same keys, so a replaced file
// that includes "../shadow/common/shadow_space.glsl" gets the replacement of that file too, if any.
// Set it before the first program is built: program caches do not key on it.
#pragma once
#include <map>
#include <string>

namespace rtlab::gl {

struct ShaderReplacement {
  std::string path;  // shown in compile errors (file:line) and watched for hot reload
  std::string text;  // used instead of reading `path` when inMemory
  bool inMemory = false;
};

using ShaderOverlay = std::map<std::string, ShaderReplacement>; // by path relative to shaders/

void setShaderOverlay(ShaderOverlay overlay);
const ShaderOverlay& shaderOverlay();

} // namespace rtlab::gl
