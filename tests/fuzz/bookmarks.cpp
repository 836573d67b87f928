// Fuzz target: lecture bookmarks (viewer/bookmarks.h): parsed, checked against a frame, their
// notes exported and each written back as JSON and parsed again (the round trip must succeed).
#include "viewer/bookmarks.h"

#include "fuzz_frame.h"
#include "fuzz_target.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rtlab;
  if (size > fuzz::kMaxInputBytes) return -1;
  fuzz::expectOnlyErrors([&] {
    const auto bookmarks = parseBookmarks(std::string(fuzz::text(data, size)), "talk.json");
    (void)bookmarkNotesMarkdown(bookmarks, "talk.json");
    nlohmann::json file = {{"schema", 1}, {"bookmarks", nlohmann::json::array()}};
    for (const auto& b : bookmarks) file["bookmarks"].push_back(bookmarkToJson(b));
    // What saveBookmarks writes must load again, to as many bookmarks.
    if (parseBookmarks(file.dump(), "round-trip.json").size() != bookmarks.size()) std::abort();
    validateBookmarks(bookmarks, fuzz::params(), fuzz::registry(), "talk.json", "contact");
  });
  return 0;
}

// Every key a bookmark file can hold: those bookmarkToJson writes for a bookmark with every field.
std::vector<std::string> rtlabFuzzDictionaryWords() {
  rtlab::Bookmark b;
  b.name = "n";
  b.scene = "contact";
  b.techniques = std::vector<std::string>{"sh"};
  b.cameraPosition = b.cameraTarget = glm::vec3(0.0f);
  b.cameraFov = 45.0f;
  b.notes = "n";
  b.panel = true;
  b.params = {{"k", 1}};
  b.view = {{"aov", "visibility"}};
  b.compare = {{"mode", "reference"}};
  b.sections = {{"s", true}};
  std::vector<std::string> words = {"schema", "bookmarks"};
  const nlohmann::json j = rtlab::bookmarkToJson(b);
  for (const auto& [key, value] : j.items()) {
    words.push_back(key);
    if (key == "camera")
      for (const auto& [field, v] : value.items()) words.push_back(field);
  }
  return words;
}
