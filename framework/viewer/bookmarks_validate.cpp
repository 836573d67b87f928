// Bookmark validation against the frame's registry and parameters (as presets are checked in
// app/frame_options.cpp), so a lecture's bookmarks fail at start, not in front of the audience.
#include "frame/registry.h"
#include "params/param_set.h"
#include "util/error.h"
#include "viewer/bookmarks.h"
#include "viewer/json_fields.h"
#include "viewer/view_fields.h"

namespace rtlab {

void validateBookmarks(const std::vector<Bookmark>& bookmarks, const ParamSet& params,
                       const TechniqueRegistry& registry, const std::string& sourceName,
                       const std::string& currentScene) {
  for (std::size_t i = 0; i < bookmarks.size(); ++i) {
    const Bookmark& b = bookmarks[i];
    const std::string where = "bookmarks '" + sourceName + "' bookmark " + std::to_string(i) + " ('" + b.name + "')";
    try {
      if (b.techniques)
        for (const auto& id : *b.techniques)
          if (id != "none") registry.get(id);
      checkViewFields(b.view, "\"view\""); // types and choices, for bookmarks built in code
      checkCompareFields(b.compare, "\"compare\"");
      checkSectionsField(b.sections, "\"sections\"");
      if (b.view.contains("aov")) checkViewAov(b.view.at("aov").get<std::string>(), registry);
      if (b.scene && *b.scene != currentScene) continue;
      ParamSet copy = params;
      for (const auto& [key, value] : b.params.items())
        copy.setJson(key, value);
      if (b.cameraPosition && copy.has("camera.position"))
        copy.setJson("camera.position", jsonFromVec3(*b.cameraPosition));
      if (b.cameraTarget && copy.has("camera.target")) copy.setJson("camera.target", jsonFromVec3(*b.cameraTarget));
      if (b.cameraFov && copy.has("camera.fov")) copy.setJson("camera.fov", jsonNumberFromFloat(*b.cameraFov));
    } catch (const Error& e) {
      throw Error(e.code(), where + ": " + e.what());
    }
  }
}

} // namespace rtlab
