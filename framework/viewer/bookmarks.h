// Lecture bookmarks (`rtlab view --bookmarks FILE`): a JSON file of named viewer states —
// scene, camera, active techniques, parameters, debug view and compare mode — stepped through
// with the arrow keys in lecture mode. GL-free, unit-tested.
//
// File: {"schema": 1, "bookmarks": [{"name": "PCSS vs reference", "scene": "contact",
//   "techniques": ["pcss"], "params": {"pcss.filter_samples": 32},
//   "camera": {"position": [..], "target": [..], "fov": 45},
//   "view": {"aov": "visibility", "mode": "full"}, "compare": {"mode": "reference", "divider": 0.5}}]}
// "notes": speaker notes (shown in lecture mode, exported with --export-notes), "panel": show or
// hide the side panel, "sections": {"Debug view": true} opens or closes panel sections.
// Every field but "name" is optional; params as in presets.
#pragma once
#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rtlab {

struct Bookmark {
  std::string name;
  std::optional<std::string> scene;
  std::optional<std::vector<std::string>> techniques;
  nlohmann::json params = nlohmann::json::object(); // {KEY: value}
  std::optional<glm::vec3> cameraPosition, cameraTarget;
  std::optional<float> cameraFov;
  nlohmann::json view = nlohmann::json::object();    // {"aov", "mode", "min", "max", "false_color"}
  nlohmann::json compare = nlohmann::json::object(); // {"mode", "divider"}
  std::string notes;                                 // speaker notes (may be empty)
  std::optional<bool> panel;                         // show (true) or hide the side panel
  nlohmann::json sections = nlohmann::json::object(); // {SECTION: open}
};

// Error(Input) naming the file and the bookmark for malformed files or fields of the wrong type.
std::vector<Bookmark> loadBookmarks(const std::string& path);
std::vector<Bookmark> parseBookmarks(const std::string& text, const std::string& sourceName);
// Writes atomically (never a half-written file).
void saveBookmarks(const std::string& path, const std::vector<Bookmark>& bookmarks);
nlohmann::json bookmarkToJson(const Bookmark& bookmark);
// The speaker notes of a lecture as Markdown: a title naming the file, then per bookmark a
// heading "N. name", a line with its scene, techniques and compare/debug view, and its notes
// ("(no notes)" when it has none). `rtlab view --bookmarks F --export-notes OUT.md` writes it.
std::string bookmarkNotesMarkdown(const std::vector<Bookmark>& bookmarks, const std::string& sourceName);

class ParamSet;
class TechniqueRegistry;
// Checks the bookmarks against the frame before the first one is shown, as presets are checked:
// technique ids (Error(Usage)), the "view" AOV, and, for bookmarks without a "scene" or with
// scene == currentScene, every "params" key and value and the camera's values against the
// `camera.*` keys, each bookmark on its own copy of `params`. A bookmark of another scene has
// scene-dependent keys (light<N>.*), so the viewer checks its params when it loads that scene.
// Messages name the file, the bookmark's index and its name.
void validateBookmarks(const std::vector<Bookmark>& bookmarks, const ParamSet& params,
                       const TechniqueRegistry& registry, const std::string& sourceName,
                       const std::string& currentScene = "");

} // namespace rtlab
