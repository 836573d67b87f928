#include "util/paths.h"

#include "util/error.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace rtlab {
namespace fs = std::filesystem;

std::string executableDir() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return ".";
  return exe.parent_path().string();
}

const std::string& dataDir() {
  static const std::string dir = [] {
    std::vector<fs::path> candidates;
    if (const char* env = std::getenv("RTLAB_DATA_DIR")) candidates.emplace_back(env);
    fs::path exeDir = executableDir();
    candidates.push_back(exeDir);
    candidates.push_back(exeDir.parent_path());
    candidates.push_back(exeDir / "../share/rtlab");
    candidates.emplace_back(RTLAB_SOURCE_DIR);
    for (const auto& c : candidates) {
      std::error_code ec;
      if (fs::is_directory(c / "shaders" / "common", ec)) return fs::weakly_canonical(c, ec).string();
    }
    throw Error(ExitCode::Internal, "cannot find rtlab's shaders/ directory (set RTLAB_DATA_DIR)");
  }();
  return dir;
}

std::string shaderPath(const std::string& relative) { return dataDir() + "/shaders/" + relative; }
std::string assetPath(const std::string& relative) { return dataDir() + "/assets/" + relative; }

} // namespace rtlab
