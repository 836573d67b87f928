// Bookmarks files (docs/viewer-scripts.md "Bookmarks"): parsed with the typed getters of
// json_fields.h, so a malformed file is exit 3 naming the file and the bookmark, and written
// atomically in the same shape, so save then load gives back the same bookmarks.
#include "viewer/bookmarks.h"

#include "util/atomic_file.h"
#include "util/error.h"
#include "viewer/json_fields.h"
#include "viewer/view_fields.h"

#include <climits>
#include <filesystem>

namespace rtlab {
namespace {

using nlohmann::json;

std::string fileName(const std::string& source) {
  return "bookmarks '" + source + "'";
}

void parseCamera(const json& camera, Bookmark& b, const std::string& where) {
  requireObject(camera, where);
  rejectUnknownFields(camera, {"position", "target", "fov"}, where);
  b.cameraPosition = optionalVec3(camera, "position", where);
  b.cameraTarget = optionalVec3(camera, "target", where);
  if (auto fov = optionalNumber(camera, "fov", where)) {
    requireRange(*fov, 1.0, 170.0, "fov", where); // camera.fov's range (scene/scene_params.cpp)
    b.cameraFov = float(*fov);
  }
  if (b.cameraPosition && b.cameraTarget && glm::length(*b.cameraTarget - *b.cameraPosition) < 1e-6f)
    usageError(where + ": \"target\" must differ from \"position\"");
}

Bookmark parseBookmark(const json& j, const std::string& at) {
  requireObject(j, at);
  Bookmark b;
  b.name = requireString(j, "name", at);
  const std::string where = at + " ('" + b.name + "')";
  if (b.name.empty()) usageError(where + ": \"name\" must not be empty");
  rejectUnknownFields(j, {"name", "scene", "techniques", "params", "camera", "view", "compare", "notes", "panel", "sections"},
                      where);
  b.scene = optionalString(j, "scene", where);
  b.techniques = optionalStringList(j, "techniques", where);
  if (j.contains("params")) {
    const json& params = j["params"];
    requireObject(params, where + ": \"params\"");
    for (const auto& [key, value] : params.items())
      requireParamValueShape(value, "\"params\" value of '" + key + "'", where);
    b.params = params;
  }
  if (j.contains("camera")) parseCamera(j["camera"], b, where + ": \"camera\"");
  if (j.contains("view")) {
    const std::string w = where + ": \"view\"";
    requireObject(j["view"], w);
    rejectUnknownFields(j["view"], {"aov", "mode", "min", "max", "false_color"}, w);
    checkViewFields(j["view"], w);
    b.view = j["view"];
  }
  if (j.contains("compare")) {
    const std::string w = where + ": \"compare\"";
    requireObject(j["compare"], w);
    rejectUnknownFields(j["compare"], {"mode", "divider"}, w);
    checkCompareFields(j["compare"], w);
    b.compare = j["compare"];
  }
  b.notes = optionalString(j, "notes", where).value_or("");
  b.panel = optionalBool(j, "panel", where);
  if (j.contains("sections")) {
    checkSectionsField(j["sections"], where + ": \"sections\"");
    b.sections = j["sections"];
  }
  return b;
}

// Field order as documented (nlohmann::json would sort the keys).
nlohmann::ordered_json orderedBookmark(const Bookmark& b) {
  nlohmann::ordered_json j;
  j["name"] = b.name;
  if (b.scene) j["scene"] = *b.scene;
  if (b.techniques) j["techniques"] = *b.techniques;
  if (!b.params.empty()) j["params"] = b.params;
  if (b.cameraPosition || b.cameraTarget || b.cameraFov) {
    nlohmann::ordered_json c = nlohmann::ordered_json::object();
    if (b.cameraPosition) c["position"] = jsonFromVec3(*b.cameraPosition);
    if (b.cameraTarget) c["target"] = jsonFromVec3(*b.cameraTarget);
    if (b.cameraFov) c["fov"] = jsonNumberFromFloat(*b.cameraFov);
    j["camera"] = c;
  }
  if (!b.view.empty()) j["view"] = b.view;
  if (!b.compare.empty()) j["compare"] = b.compare;
  if (b.panel) j["panel"] = *b.panel;
  if (!b.sections.empty()) j["sections"] = b.sections;
  if (!b.notes.empty()) j["notes"] = b.notes;
  return j;
}

} // namespace

std::vector<Bookmark> parseBookmarks(const std::string& text, const std::string& sourceName) {
  const std::string name = fileName(sourceName);
  const json j = parseJsonText(text, name);
  requireObject(j, name);
  rejectUnknownFields(j, {"schema", "bookmarks"}, name);
  if (auto schema = optionalInteger(j, "schema", name); schema && *schema != 1)
    inputError(name + " has unsupported schema " + std::to_string(*schema) + " (expected 1)");
  if (!j.contains("bookmarks")) inputError(name + ": missing field \"bookmarks\"");
  const json& list = j["bookmarks"];
  if (!list.is_array()) inputError(name + ": \"bookmarks\" must be an array, got " + std::string(list.type_name()));
  std::vector<Bookmark> out;
  for (std::size_t i = 0; i < list.size(); ++i)
    out.push_back(parseBookmark(list[i], name + " bookmark " + std::to_string(i)));
  return out;
}

std::vector<Bookmark> loadBookmarks(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) inputError("cannot read bookmarks '" + path + "': it is a directory");
  return parseBookmarks(readFileOrThrow(path, "bookmarks"), path);
}

nlohmann::json bookmarkToJson(const Bookmark& bookmark) {
  // Same content as the saved form; nlohmann::json keeps keys sorted.
  return json(orderedBookmark(bookmark));
}

std::string bookmarkNotesMarkdown(const std::vector<Bookmark>& bookmarks, const std::string& sourceName) {
  std::string md = "# Speaker notes: " + std::filesystem::path(sourceName).filename().string() + "\n";
  for (std::size_t i = 0; i < bookmarks.size(); ++i) {
    const Bookmark& b = bookmarks[i];
    md += "\n## " + std::to_string(i + 1) + ". " + b.name + "\n\n";
    std::string setup;
    auto add = [&](const std::string& part) { setup += (setup.empty() ? "" : "; ") + part; };
    if (b.scene) add("scene `" + *b.scene + "`");
    if (b.techniques) {
      std::string list;
      for (const auto& id : *b.techniques)
        list += (list.empty() ? "`" : ", `") + id + "`";
      add("techniques " + (list.empty() ? std::string("none") : list));
    }
    if (b.compare.contains("mode") && b.compare["mode"] != "off")
      add("compare " + b.compare["mode"].get<std::string>());
    if (b.view.contains("mode") && b.view["mode"] != "off" && b.view.contains("aov"))
      add("view `" + b.view["aov"].get<std::string>() + "` (" + b.view["mode"].get<std::string>() + ")");
    if (!setup.empty()) md += "*" + setup + "*\n\n";
    md += (b.notes.empty() ? std::string("(no notes)") : b.notes) + "\n";
  }
  return md;
}

void saveBookmarks(const std::string& path, const std::vector<Bookmark>& bookmarks) {
  nlohmann::ordered_json j;
  j["schema"] = 1;
  j["bookmarks"] = nlohmann::ordered_json::array();
  for (const auto& b : bookmarks)
    j["bookmarks"].push_back(orderedBookmark(b));
  // Names are the user's text: invalid UTF-8 is replaced rather than failing the save.
  writeTextAtomically(path, j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
}

} // namespace rtlab
