// Finding rtlab's data (shaders/, assets/) from any working directory: $RTLAB_DATA_DIR, then
// next to the binary (and its parent), then the source tree the binary was built from.
#pragma once
#include <string>

namespace rtlab {

// Directory that contains shaders/ and assets/. Throws Error(Internal) if none is found.
const std::string& dataDir();
std::string shaderPath(const std::string& relative);
std::string assetPath(const std::string& relative);
std::string executableDir();

} // namespace rtlab
