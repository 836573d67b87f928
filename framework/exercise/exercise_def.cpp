#include "exercise/exercise_def.h"

#include "exercise/regions.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/number_format.h"
#include "util/paths.h"
#include "util/suggest.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>

namespace rtlab {
namespace fs = std::filesystem;
using nlohmann::json;
namespace {

[[noreturn]] void bad(const std::string& source, const std::string& what) { inputError(source + ": " + what); }

const json& member(const json& j, const char* key, const std::string& source, json::value_t type, const char* typeName) {
  auto it = j.find(key);
  if (it == j.end()) bad(source, std::string("missing \"") + key + "\"");
  const bool ok = type == json::value_t::number_float ? it->is_number() : it->type() == type;
  if (!ok) bad(source, std::string("\"") + key + "\" must be " + typeName);
  return *it;
}

std::string stringMember(const json& j, const char* key, const std::string& source) {
  return member(j, key, source, json::value_t::string, "a string").get<std::string>();
}

void checkKeys(const json& j, const std::set<std::string>& known, const std::string& source, const std::string& what) {
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!known.count(it.key())) {
      std::vector<std::string> names(known.begin(), known.end());
      bad(source, "unknown field \"" + it.key() + "\" in " + what + didYouMean(it.key(), names));
    }
}

void checkSchema(const json& j, const std::string& source) {
  if (!j.is_object()) bad(source, "expected a JSON object");
  auto it = j.find("schema");
  if (it == j.end() || !it->is_number_integer() || it->get<int>() != 1) bad(source, "\"schema\" must be 1");
}

ExerciseTolerance parseTolerance(const json& j, const std::string& source) {
  if (!j.is_object()) bad(source, "\"tolerance\" must be an object");
  checkKeys(j, {"pixel", "fraction", "rmse"}, source, "\"tolerance\"");
  ExerciseTolerance t;
  auto number = [&](const char* key, double& out, double lo, double hi) {
    if (!j.contains(key)) return;
    if (!j[key].is_number()) bad(source, std::string("tolerance \"") + key + "\" must be a number");
    out = j[key].get<double>();
    if (!(out >= lo && out <= hi))
      bad(source, std::string("tolerance \"") + key + "\" must be in [" + formatNumber(lo) + ", " + formatNumber(hi) + "]");
  };
  number("pixel", t.pixel, 0.0, 1.0);
  number("fraction", t.fraction, 0.0, 1.0);
  number("rmse", t.rmse, 0.0, 1.0);
  return t;
}

ExerciseView parseView(const json& j, const std::string& source) {
  if (!j.is_object()) bad(source, "each view must be an object");
  checkKeys(j, {"name", "scene", "size", "set", "techniques", "seed", "spp", "hidden", "note"}, source, "a view");
  ExerciseView v;
  v.name = stringMember(j, "name", source);
  static const std::regex nameRe("[a-z0-9_-]+");
  if (!std::regex_match(v.name, nameRe)) bad(source, "view name '" + v.name + "' must match [a-z0-9_-]+");
  const std::string where = source + " (view '" + v.name + "')";
  v.scene = stringMember(j, "scene", where);
  if (j.contains("size")) {
    const std::string size = stringMember(j, "size", where);
    static const std::regex sizeRe("([0-9]{1,4})x([0-9]{1,4})");
    std::smatch m;
    if (!std::regex_match(size, m, sizeRe)) bad(where, "\"size\" must be WxH");
    v.width = std::stoi(m[1].str());
    v.height = std::stoi(m[2].str());
    if (v.width < 1 || v.height < 1 || v.width > 8192 || v.height > 8192) bad(where, "\"size\" must be 1..8192 each");
  }
  if (j.contains("set")) {
    const json& set = j["set"];
    if (!set.is_object()) bad(where, "\"set\" must be an object of KEY: value");
    for (auto it = set.begin(); it != set.end(); ++it) {
      std::string value;
      if (it->is_string()) value = it->get<std::string>();
      else if (it->is_boolean()) value = it->get<bool>() ? "true" : "false";
      else if (it->is_number()) value = it->dump();
      else bad(where, "\"set\" value of '" + it.key() + "' must be a string, number or bool");
      v.set.emplace_back(it.key(), value);
    }
  }
  if (j.contains("techniques")) {
    const json& t = j["techniques"];
    if (!t.is_array()) bad(where, "\"techniques\" must be an array of ids");
    for (const auto& id : t) {
      if (!id.is_string()) bad(where, "\"techniques\" must be an array of ids");
      v.techniques.push_back(id.get<std::string>());
    }
  }
  if (j.contains("seed")) {
    if (!j["seed"].is_number_unsigned()) bad(where, "\"seed\" must be a non-negative integer");
    v.seed = j["seed"].get<unsigned>();
  }
  if (j.contains("spp")) {
    if (!j["spp"].is_number_integer() || j["spp"].get<int>() < 1) bad(where, "\"spp\" must be a positive integer");
    v.spp = j["spp"].get<int>();
  }
  if (j.contains("hidden")) v.hidden = member(j, "hidden", where, json::value_t::boolean, "true or false").get<bool>();
  if (j.contains("note")) v.note = stringMember(j, "note", where);
  return v;
}

std::vector<ExerciseView> parseViews(const json& j, const std::string& source) {
  const json& views = member(j, "views", source, json::value_t::array, "an array");
  if (views.empty()) bad(source, "\"views\" is empty");
  std::vector<ExerciseView> out;
  std::set<std::string> names;
  for (const auto& v : views) {
    out.push_back(parseView(v, source));
    if (!names.insert(out.back().name).second) bad(source, "two views named '" + out.back().name + "'");
  }
  return out;
}

json parseJson(const std::string& text, const std::string& source) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    bad(source, std::string("invalid JSON: ") + e.what());
  }
}

} // namespace

ExerciseDef parseExerciseDef(const std::string& text, const std::string& source) {
  const json j = parseJson(text, source);
  checkSchema(j, source);
  checkKeys(j, {"schema", "id", "technique", "title", "regions", "aov", "background", "tolerance", "time_limit_s", "views"},
            source, "the definition");
  ExerciseDef d;
  d.source = source;
  d.id = stringMember(j, "id", source);
  static const std::regex idRe("[a-z0-9_]+");
  if (!std::regex_match(d.id, idRe)) bad(source, "\"id\" must match [a-z0-9_]+");
  d.technique = stringMember(j, "technique", source);
  d.title = stringMember(j, "title", source);
  d.aov = stringMember(j, "aov", source);
  for (const auto& r : member(j, "regions", source, json::value_t::array, "an array")) {
    if (!r.is_string()) bad(source, "\"regions\" must be an array of names");
    d.regions.push_back(r.get<std::string>());
  }
  if (d.regions.empty()) bad(source, "\"regions\" is empty");
  if (j.contains("background")) {
    for (const auto& p : member(j, "background", source, json::value_t::array, "an array of paragraphs")) {
      if (!p.is_string()) bad(source, "\"background\" must be an array of strings");
      d.background.push_back(p.get<std::string>());
    }
  }
  if (j.contains("tolerance")) d.tolerance = parseTolerance(j["tolerance"], source);
  if (j.contains("time_limit_s")) {
    d.timeLimitSeconds = member(j, "time_limit_s", source, json::value_t::number_float, "a number").get<double>();
    if (!(d.timeLimitSeconds > 0.0 && d.timeLimitSeconds <= 3600.0)) bad(source, "\"time_limit_s\" must be in (0, 3600]");
  }
  d.views = parseViews(j, source);
  return d;
}

ExerciseViews readExerciseViews(const std::string& path) {
  const json j = parseJson(readFileOrThrow(path, "views file"), path);
  checkSchema(j, path);
  checkKeys(j, {"schema", "views", "tolerance"}, path, "the views file");
  ExerciseViews out;
  out.views = parseViews(j, path);
  if (j.contains("tolerance")) {
    out.hasTolerance = true;
    out.tolerance = parseTolerance(j["tolerance"], path);
  }
  return out;
}

std::string viewSize(const ExerciseView& view) { return std::to_string(view.width) + "x" + std::to_string(view.height); }

json viewsToJson(const std::vector<ExerciseView>& views) {
  json out = json::array();
  for (const auto& v : views) {
    json set = json::object();
    for (const auto& [key, value] : v.set) set[key] = value;
    json j = {{"name", v.name}, {"scene", v.scene}, {"size", viewSize(v)}, {"set", set}, {"seed", v.seed}, {"hidden", v.hidden}};
    if (!v.techniques.empty()) j["techniques"] = v.techniques;
    if (v.spp > 0) j["spp"] = v.spp;
    if (!v.note.empty()) j["note"] = v.note;
    out.push_back(std::move(j));
  }
  return out;
}

std::vector<ExerciseView> viewsFromJson(const json& views, const std::string& source) {
  return parseViews(json{{"views", views}}, source);
}

std::vector<RegionLocation> shippedRegions() {
  std::vector<RegionLocation> out;
  const fs::path root = fs::path(dataDir()) / "shaders";
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    const std::string rel = "shaders/" + fs::relative(file, root).generic_string();
    const std::string text = readFileOrThrow(file.string(), "shader");
    if (text.find("exercise") == std::string::npos) continue;
    for (const auto& region : parseExerciseRegions(text, rel)) out.push_back({region.name, rel});
  }
  return out;
}

const std::vector<ExerciseDef>& exerciseCatalog() {
  static const std::vector<ExerciseDef> catalog = [] {
    std::map<std::string, std::string> fileOf;
    for (const auto& loc : shippedRegions())
      if (!fileOf.emplace(loc.region, loc.file).second)
        inputError(loc.file + ": exercise region '" + loc.region + "' is also defined in " + fileOf[loc.region]);
    std::vector<ExerciseDef> defs;
    const fs::path dir = fs::path(dataDir()) / "assets" / "exercises";
    std::error_code ec;
    if (fs::is_directory(dir, ec))
      for (const auto& entry : fs::directory_iterator(dir))
        if (entry.is_regular_file() && entry.path().extension() == ".json") {
          const std::string source = "assets/exercises/" + entry.path().filename().string();
          ExerciseDef def = parseExerciseDef(readFileOrThrow(entry.path().string(), "exercise definition"), source);
          if (def.id != entry.path().stem().string()) bad(source, "\"id\" must equal the file name ('" + entry.path().stem().string() + "')");
          for (const auto& region : def.regions) {
            auto it = fileOf.find(region);
            if (it == fileOf.end()) bad(source, "no shader under shaders/ has the exercise region '" + region + "'");
            if (std::find(def.files.begin(), def.files.end(), it->second) == def.files.end()) def.files.push_back(it->second);
          }
          defs.push_back(std::move(def));
        }
    std::sort(defs.begin(), defs.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    return defs;
  }();
  return catalog;
}

const ExerciseDef& findExercise(const std::string& id) {
  std::vector<std::string> ids;
  for (const auto& def : exerciseCatalog()) {
    if (def.id == id) return def;
    ids.push_back(def.id);
  }
  std::string known;
  for (const auto& k : ids) known += (known.empty() ? "" : ", ") + k;
  usageError("unknown exercise '" + id + "'" + didYouMean(id, ids, " (known: " + known + ")"));
}

} // namespace rtlab
