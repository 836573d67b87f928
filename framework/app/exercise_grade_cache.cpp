#include "app/exercise_grade_cache.h"

#include "app/exercise_worker.h"
#include "app/sweep_plan.h"
#include "util/error.h"
#include "util/hash.h"
#include "util/paths.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

namespace rtlab {
namespace fs = std::filesystem;
namespace {

void hashFile(Fnv1a64& h, const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ExitCode::Internal, "grade cache: cannot read " + path.string() + " to hash it");
  std::vector<char> chunk(1 << 16);
  std::uint64_t total = 0;
  while (in) {
    in.read(chunk.data(), std::streamsize(chunk.size()));
    const auto got = std::size_t(in.gcount());
    h.bytes(chunk.data(), got);
    total += got;
  }
  h.u64(total);
}

// Every regular file under `root`, by path relative to it (sorted) and content.
void hashTree(Fnv1a64& h, const fs::path& root) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  h.u64(files.size());
  for (const auto& file : files) {
    h.text(fs::relative(file, root).generic_string());
    hashFile(h, file);
  }
}

} // namespace

std::string gradeCacheBase(const ExerciseDef& def, const std::string& backend) {
  Fnv1a64 h;
  h.text("rtlab-grade-cache-key-1");
  hashFile(h, "/proc/self/exe");
  hashTree(h, fs::path(dataDir()) / "shaders");
  hashTree(h, fs::path(dataDir()) / "assets");
  h.text(def.id).text(def.technique).text(def.aov).text(backend);
  return h.hex();
}

std::string gradeCacheKey(const std::string& base, const ExerciseDef& def, const ExerciseView& view,
                          const std::string& backend, const std::string& driver, const char* what) {
  nlohmann::json j = viewsToJson({view}).at(0);
  for (const char* presentational : {"name", "note", "hidden"}) j.erase(presentational);
  const ResolvedFrame frame = resolveViewFrame(view, def.technique, backend);
  return Fnv1a64().text(base).text(j.dump()).text(sceneContentHash(frame.scene)).text(driver).text(what).hex();
}

} // namespace rtlab
