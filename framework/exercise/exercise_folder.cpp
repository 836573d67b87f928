#include "exercise/exercise_folder.h"

#include "exercise/assignment.h"
#include "exercise/regions.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/paths.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>

namespace rtlab {
namespace fs = std::filesystem;
using nlohmann::json;
namespace {

[[noreturn]] void notExercise(const std::string& dir, const std::string& why) {
  inputError(dir + " is not an exercise folder: " + why);
}

std::string shaderRelative(const std::string& file) {
  const std::string prefix = "shaders/";
  return file.rfind(prefix, 0) == 0 ? file.substr(prefix.size()) : file;
}

} // namespace

ExerciseFolder readExerciseFolder(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) notExercise(dir, "no such directory");
  const fs::path manifest = fs::path(dir) / "exercise.json";
  if (!fs::is_regular_file(manifest, ec)) notExercise(dir, "no exercise.json (make one with 'rtlab exercise new ID --out DIR')");
  json j;
  try {
    j = json::parse(readFileOrThrow(manifest.string(), "exercise.json"));
  } catch (const json::parse_error& e) {
    notExercise(dir, std::string("exercise.json is not valid JSON: ") + e.what());
  }
  if (!j.is_object() || !j.contains("schema") || j["schema"] != 1) notExercise(dir, "exercise.json needs \"schema\": 1");
  if (!j.contains("exercise") || !j["exercise"].is_string()) notExercise(dir, "exercise.json needs \"exercise\": ID");
  if (!j.contains("files") || !j["files"].is_array()) notExercise(dir, "exercise.json needs \"files\": [PATH...]");
  ExerciseFolder folder;
  folder.dir = dir;
  const std::string id = j["exercise"].get<std::string>();
  try {
    folder.def = &findExercise(id);
  } catch (const Error& e) {
    notExercise(dir, e.what());
  }
  const std::set<std::string> expected(folder.def->files.begin(), folder.def->files.end());
  for (const auto& f : j["files"]) {
    if (!f.is_string()) notExercise(dir, "\"files\" must be paths");
    const std::string file = f.get<std::string>();
    if (!expected.count(file)) notExercise(dir, "'" + file + "' is not a file of exercise '" + id + "'");
    if (!fs::is_regular_file(fs::path(dir) / file, ec)) notExercise(dir, "missing " + file);
    folder.files.push_back(file);
  }
  if (folder.files.size() != expected.size()) notExercise(dir, "exercise.json must list every file of exercise '" + id + "'");
  return folder;
}

std::string stubbedFile(const ExerciseDef& def, const std::string& file) {
  const std::string text = readFileOrThrow((fs::path(dataDir()) / file).string(), "shader");
  return studentCopy(text, file, std::set<std::string>(def.regions.begin(), def.regions.end()));
}

std::map<std::string, std::string> newExerciseFiles(const ExerciseDef& def, const std::vector<ParamSpec>& params) {
  std::map<std::string, std::string> out;
  json manifest = {{"schema", 1}, {"exercise", def.id}, {"technique", def.technique}, {"files", def.files}};
  out["exercise.json"] = manifest.dump(2) + "\n";
  for (const auto& file : def.files) out[file] = stubbedFile(def, file);
  out["README.md"] = assignmentMarkdown(def, params);
  return out;
}

std::vector<ShaderFileReplacement> folderReplacements(const ExerciseFolder& folder) {
  std::vector<ShaderFileReplacement> out;
  for (const auto& file : folder.files)
    out.push_back({shaderRelative(file), fs::absolute(fs::path(folder.dir) / file).lexically_normal().string(), "", false});
  return out;
}

std::vector<ShaderFileReplacement> stubReplacements(const ExerciseDef& def) {
  std::vector<ShaderFileReplacement> out;
  for (const auto& file : def.files) out.push_back({shaderRelative(file), "stub:" + file, stubbedFile(def, file), true});
  return out;
}

} // namespace rtlab
