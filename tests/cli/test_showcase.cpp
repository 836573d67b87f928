// rtlab showcase through the binary (docs/cli.md "rtlab showcase"): the measured atlas. A tiny
// showcase (64x36, one frame, 4 reference spp) writes index.html with, per stage with a
// reference (shadow, ao), each technique's error figures (RMSE, FLIP) and heat map beside the
// reference, and the stage's error-against-time chart from its sweep; every link is relative
// and resolves; the page loads in headless Chromium (its DOM holds the figures and the charts,
// and its screenshot, kept as RTLAB_TEST_TMP/showcase/index.png, is not blank).
#include "chromium.h"
#include "process.h"

#include "image/image.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using rtlab::test::runProcess;

namespace {

const fs::path kRoot = fs::path(RTLAB_TEST_TMP) / "showcase";

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

class Showcase : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    fs::remove_all(kRoot);
    fs::create_directories(kRoot);
    setenv("RTLAB_CACHE_DIR", (kRoot / "cache").c_str(), 1);
    s_result = runProcess(RTLAB_BINARY, {"showcase", "--out", (kRoot / "out").string(), "--size", "64x36", "--frames", "1",
                                         "--spp", "4"},
                          600);
  }
  void SetUp() override { ASSERT_EQ(s_result.exitCode, 0) << s_result.err; }
  static rtlab::test::ProcessResult s_result;
};
rtlab::test::ProcessResult Showcase::s_result;

// One test, so that ctest renders the showcase once.
TEST_F(Showcase, AtlasShowsErrorsAndChartsPerStageAndOpensInChromium) {
  const fs::path out = kRoot / "out";
  const std::string html = slurp(out / "index.html");
  for (const char* stage : {"shadow", "ao", "indirect", "arealight", "transparency", "post"}) {
    SCOPED_TRACE(stage);
    EXPECT_NE(html.find(std::string("id=\"atlas-") + stage + "\""), std::string::npos);
    const fs::path sweep = out / "sweeps" / stage;
    const auto plan = nlohmann::json::parse(slurp(sweep / "sweep.json"));
    EXPECT_EQ(plan["jobs"], 1) << "the atlas's timings are taken one point at a time";
    EXPECT_TRUE(fs::is_regular_file(sweep / "report.html"));
    // Each technique beside the reference: its figures and its heat map, linked relatively.
    for (const auto& t : plan["techniques"]) {
      const std::string id = t.get<std::string>();
      EXPECT_NE(html.find("<strong>" + id + "</strong><br><span class=\"figures\">RMSE "), std::string::npos) << id;
    }
    EXPECT_NE(html.find(std::string("sweeps/") + stage + "/reference/"), std::string::npos);
  }
  EXPECT_GE(count(html, "FLIP "), 8u) << "five shadow, two ao techniques and bloom";
  EXPECT_EQ(count(html, "<svg class=\"chart\""), 6u); // one per stage above
  EXPECT_GE(count(html, "class=\"colorbar\""), 3u);
  EXPECT_NE(html.find("<pre class=\"command\"><code>rtlab sweep --scene contact"), std::string::npos);

  // Every link and image is relative and resolves inside the folder.
  const std::regex ref(R"re((?:src|href)="([^"#]*)(#[^"]*)?")re");
  std::size_t files = 0;
  for (std::sregex_iterator it(html.begin(), html.end(), ref), end; it != end; ++it) {
    const std::string target = (*it)[1];
    if (target.empty() || target.rfind("data:", 0) == 0) continue;
    EXPECT_EQ(target.find(':'), std::string::npos) << target;
    EXPECT_NE(target.front(), '/') << target;
    EXPECT_TRUE(fs::is_regular_file(out / target)) << target;
    ++files;
  }
  EXPECT_GT(files, 20u);

  // In headless Chromium (the same run: ctest runs each test in its own process).
  // Chromium is a test dependency (scripts/setup.sh --test-deps installs it): without it the
  // report is untested, so the test fails rather than skips.
  std::string why;
  ASSERT_TRUE(rtlab::test::chromiumAvailable(why)) << why;
  const fs::path page = kRoot / "out" / "index.html";
  const auto dom = rtlab::test::runChromium(page, kRoot / "chromium-profile");
  ASSERT_FALSE(dom.timedOut);
  EXPECT_EQ(dom.exitCode, 0) << dom.err;
  for (const auto& line : rtlab::test::consoleMessages(dom.err)) ADD_FAILURE() << "console message: " << line;
  // The DOM as Chromium built it: the six stages' figures and charts with their points.
  EXPECT_GE(count(dom.out, "RMSE "), 8u);
  EXPECT_GE(count(dom.out, "FLIP "), 8u);
  EXPECT_EQ(count(dom.out, "<svg class=\"chart\""), 6u);
  EXPECT_GE(count(dom.out, "class=\"point\""), 8u);
  EXPECT_GE(count(dom.out, "class=\"series\""), 4u);

  const fs::path shot = kRoot / "index.png"; // kept as the test's artifact
  const auto r = rtlab::test::runChromium(page, kRoot / "chromium-profile", shot);
  ASSERT_FALSE(r.timedOut);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  ASSERT_TRUE(fs::is_regular_file(shot)) << r.err;
  rtlab::test::expectNotBlank(rtlab::readImage(shot.string()));
}

} // namespace
