// GLSL source loading with #include resolution. Each file gets a source-string number in #line
// directives so the driver's error log can be mapped back to the original file:line.
#pragma once
#include <string>
#include <vector>

namespace rtlab::gl {

struct ShaderSource {
  std::string text;                 // ready for glShaderSource
  std::vector<std::string> files;   // index = the source-string number used in #line
};

// Loads `path` (absolute, or relative to shaders/), resolving `#include "file"` relative to the
// including file and then to shaders/. `defines` ("NAME VALUE" or "NAME") are inserted after
// #version. A missing file, a missing #version, or an include cycle is Error(Shader) naming the
// file and line.
ShaderSource loadShaderSource(const std::string& path, const std::vector<std::string>& defines = {});

// Rewrites a driver info log (Mesa "0:12(5): error: ...", NVIDIA "0(12) : error ...") into
// "file:line: error: ..." lines using the source's file table.
std::string mapInfoLog(const std::string& log, const std::vector<std::string>& files);

} // namespace rtlab::gl
