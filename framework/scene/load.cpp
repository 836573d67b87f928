// `--scene S` resolution (docs/contract.md): file or built-in name.
#include "scene/load.h"

#include "scene/builtin.h"
#include "scene/gltf_loader.h"
#include "util/error.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace rtlab {
namespace {

bool endsWithNoCase(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), s.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                    [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) ==
                             std::tolower(static_cast<unsigned char>(b));
                    });
}

bool isExistingFile(const std::string& spec) {
  std::error_code ec;
  return std::filesystem::is_regular_file(spec, ec);
}

} // namespace

Scene loadScene(const std::string& spec) {
  std::error_code ec;
  const auto status = std::filesystem::status(spec, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    inputError("cannot read scene '" + spec + "': " +
               (std::filesystem::is_directory(status) ? "it is a directory" : "it is not a regular file") +
               " (give a .gltf/.glb file or a built-in scene name)");
  if (isExistingFile(spec) || endsWithNoCase(spec, ".gltf") || endsWithNoCase(spec, ".glb")) {
    return loadGltf(spec); // missing or invalid: Error(Input)
  }
  return makeBuiltinScene(spec); // unknown: Error(Usage)
}

} // namespace rtlab
