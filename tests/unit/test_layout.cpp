// The include direction of docs/layout.md: util <- gl <- frame <- shading <- render, and
// techniques/common/<family>/ and techniques/<id>/ on top of shading (never render/ or app/, never
// another technique's folder). Reads the source tree's #include lines; a file that includes a
// layer above its own is listed with the line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = RTLAB_SOURCE_DIR;

struct Rule {
  std::string folder;                // relative to the root; every .h/.cpp below it
  std::vector<std::string> forbidden; // include prefixes
};

bool isSource(const fs::path& p) { return p.extension() == ".h" || p.extension() == ".cpp"; }

// Quoted includes of every source file under `folder`, as (file relative to the root, include).
std::vector<std::pair<std::string, std::string>> includesUnder(const std::string& folder) {
  static const std::regex kInclude(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& entry : fs::recursive_directory_iterator(kRoot / folder)) {
    if (!entry.is_regular_file() || !isSource(entry.path())) continue;
    std::ifstream in(entry.path());
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
      if (std::regex_search(line, m, kInclude))
        out.emplace_back(fs::relative(entry.path(), kRoot).generic_string(), m[1].str());
  }
  return out;
}

std::vector<std::string> violations(const Rule& rule) {
  std::vector<std::string> out;
  for (const auto& [file, include] : includesUnder(rule.folder))
    for (const auto& prefix : rule.forbidden)
      if (include.rfind(prefix, 0) == 0)
        out.push_back(file + ": #include \"" + include + "\"");
  return out;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += "\n  " + l;
  return s;
}

std::vector<std::string> techniqueIds() {
  std::vector<std::string> ids;
  for (const auto& entry : fs::directory_iterator(kRoot / "techniques"))
    if (entry.is_directory() && entry.path().filename() != "common") ids.push_back(entry.path().filename().string());
  return ids;
}

} // namespace

TEST(Layout, FrameworkLayersIncludeOnlyLayersBelow) {
  const std::vector<Rule> rules = {
      {"framework/util", {"gl/", "frame/", "shading/", "render/", "techniques/", "app/"}},
      {"framework/gl", {"frame/", "shading/", "render/", "techniques/", "app/"}},
      {"framework/frame", {"shading/", "render/", "techniques/", "app/"}},
      {"framework/shading", {"render/", "techniques/", "app/"}},
      {"framework/render", {"techniques/", "app/"}},
      {"framework/exercise", {"gl/", "frame/", "shading/", "render/", "techniques/", "app/"}},
  };
  for (const auto& rule : rules) {
    ASSERT_TRUE(fs::is_directory(kRoot / rule.folder)) << rule.folder;
    const auto bad = violations(rule);
    EXPECT_TRUE(bad.empty()) << rule.folder << " includes a layer above it:" << joined(bad);
  }
}

TEST(Layout, FamilyCodeUsesNoTechniqueAndNoRenderer) {
  Rule rule{"techniques/common", {"render/", "app/"}};
  for (const auto& id : techniqueIds()) rule.forbidden.push_back("techniques/" + id + "/");
  ASSERT_TRUE(fs::is_directory(kRoot / rule.folder));
  const auto bad = violations(rule);
  EXPECT_TRUE(bad.empty()) << "family code includes a technique or the renderer:" << joined(bad);
}

TEST(Layout, TechniquesIncludeNoOtherTechniqueAndNoRenderer) {
  const auto ids = techniqueIds();
  ASSERT_FALSE(ids.empty());
  for (const auto& id : ids) {
    Rule rule{"techniques/" + id, {"render/", "app/"}};
    for (const auto& other : ids)
      if (other != id) rule.forbidden.push_back("techniques/" + other + "/");
    const auto bad = violations(rule);
    EXPECT_TRUE(bad.empty()) << id << " includes another technique or the renderer:" << joined(bad);
  }
}
