// The command line's rough edges (issue 12, "Command line"), through the real binary: a directory
// given where a file is expected, "did you mean" for mistyped names, numbers in messages as typed
// or shortest, PNG previews of data (--range, --false-color), compare's heat map and warnings,
// scene.ambient, and the README's example commands that use assets/. docs/cli.md describes them.
#include "process.h"
#include "view_helpers.h"

#include "image/image.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;
using rtlab::test::ProcessResult;
using rtlab::test::runProcess;

namespace {

class CliMessages : public ::testing::Test {
protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = fs::path(RTLAB_TEST_TMP) / "cli_messages" / info->name();
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
  }
  std::string path(const std::string& name) const { return (m_dir / name).string(); }
  std::string dir(const std::string& name) const {
    fs::create_directories(m_dir / name);
    return path(name);
  }

  static ProcessResult rtlab(const std::vector<std::string>& args, int timeout = 120) {
    return runProcess(RTLAB_BINARY, args, timeout);
  }

  // Exit code, exactly one "rtlab: error:" line on stderr naming `mention`.
  static void expectError(const std::vector<std::string>& args, int code, const std::string& mention) {
    const auto r = rtlab(args);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, code) << r.err;
    EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("rtlab: error:", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(mention), std::string::npos) << "expected '" << mention << "' in: " << r.err;
  }

  std::string render(const std::vector<std::string>& extra, const std::string& out) const {
    std::vector<std::string> args = {"render", "--size", "160x90", "--out", path(out)};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = rtlab(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return path(out);
  }

  fs::path m_dir;
};

double meanOfValid(const rtlab::Image& im) {
  double sum = 0.0;
  for (float v : im.pixels) sum += v;
  return im.pixels.empty() ? 0.0 : sum / double(im.pixels.size());
}

double maxAbsDifference(const rtlab::Image& a, const rtlab::Image& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i)
    m = std::max(m, double(std::abs(a.pixels[i] - b.pixels[i])));
  return m;
}

// --- a directory where a file is expected --------------------------------------------------------

TEST_F(CliMessages, DirectoryAsOutputExits6NamingIt) {
  const std::string plain = dir("outdir");    // no extension: was "unsupported image format" (2)
  const std::string dotted = dir("image.png"); // an image extension on a directory
  const std::string r = "render";
  for (const std::string& d : {plain, dotted}) {
    SCOPED_TRACE(d);
    expectError({r, "--size", "32x32", "--out", d}, 6, d + "': it is a directory");
    expectError({r, "--size", "32x32", "--out", path("x.png"), "--stats", d}, 6, d + "': it is a directory");
    expectError({r, "--size", "32x32", "--out", path("x.png"), "--save-preset", d}, 6, d + "': it is a directory");
    expectError({"reference", "--size", "32x32", "--aov", "visibility", "--out", d}, 6, d + "': it is a directory");
    expectError({"view", "--size", "32x32", "--frames", "1", "--screenshot", d}, 6, d + "': it is a directory");
  }
  rtlab::Image im(4, 4, 1);
  rtlab::writeImage(path("a.exr"), im);
  expectError({"compare", path("a.exr"), path("a.exr"), "--heatmap", plain}, 6, plain + "': it is a directory");
  expectError({"compare", path("a.exr"), path("a.exr"), "--heatmap", dotted}, 6, dotted + "': it is a directory");
  EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(CliMessages, DirectoryAsSceneExits3NamingIt) {
  const std::string plain = dir("scenes");       // was "unknown scene" (2)
  const std::string dotted = dir("model.gltf");  // was a glTF read error
  for (const std::string& d : {plain, dotted}) {
    expectError({"render", "--size", "32x32", "--out", path("x.png"), "--scene", d}, 3,
                "scene '" + d + "': it is a directory");
    expectError({"list", "--scene", d}, 3, "it is a directory");
  }
}

// --- did you mean -------------------------------------------------------------------------------

TEST_F(CliMessages, DidYouMeanForTechniquesScenesAndAovs) {
  const std::string out = path("x.png");
  expectError({"render", "--out", out, "-t", "shadowmap"}, 2, "did you mean 'shadow_map'?");
  expectError({"render", "--out", out, "-t", "PCSS"}, 2, "did you mean 'pcss'?");
  expectError({"render", "--out", out, "--scene", "Contact"}, 2, "did you mean 'contact'?");
  expectError({"render", "--out", out, "--aov", "visibilty"}, 2, "did you mean 'visibility'?");
  expectError({"render", "--out", out, "-t", "pcss", "--aov", "pcss.penumbr"}, 2, "did you mean 'pcss.penumbra'?");
  expectError({"render", "--out", out, "--set", "shadow.resoltion=512"}, 2, "did you mean 'shadow.resolution'?");
  // Nothing close: no guess, the list of known names instead.
  const auto r = rtlab({"render", "--out", out, "-t", "no_such_technique"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err.find("did you mean"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("known: "), std::string::npos) << r.err;
}

// --- numbers in messages ------------------------------------------------------------------------

// Digits a person would not type: a number longer than the shortest text of the float it reads
// as (float noise such as 0.100000001 or 8.54400349, printed with 9 significant digits), or an
// integer in exponent form ("1e+05"). Every value `rtlab list` prints is a declared default or
// range: a double literal or a float, so its shortest float text is never longer than it.
bool hasNoisyNumber(const std::string& text, std::string& found) {
  static const std::regex number(R"(-?\d+(\.\d+)?(e[+-]\d+)?)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it) {
    const std::string t = it->str();
    if (t.find_first_of(".e") == std::string::npos) continue; // an integer, as typed
    const double d = std::strtod(t.c_str(), nullptr);
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, static_cast<float>(d));
    const bool integerExponent = t.find("e+") != std::string::npos && d == std::floor(d) && std::abs(d) < 1e15;
    if (integerExponent || t.size() > std::size_t(res.ptr - buf)) {
      found = t;
      return true;
    }
  }
  return false;
}

TEST_F(CliMessages, NumbersAsTypedOrShortest) {
  std::string found;
  // A vec3 range of +-100000 and a float-derived range (light0.radius of contact).
  auto r = rtlab({"render", "--out", path("x.png"), "--set", "camera.position=1,2"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("[-100000, 100000]"), std::string::npos) << r.err;
  EXPECT_FALSE(hasNoisyNumber(r.err, found)) << found << " in " << r.err;
  r = rtlab({"render", "--out", path("x.png"), "--set", "light0.radius=1000"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("value 1000 for 'light0.radius'"), std::string::npos) << r.err;
  EXPECT_FALSE(hasNoisyNumber(r.err, found)) << found << " in " << r.err;
  // rtlab list: every default and range, with the scene's own keys.
  for (const char* scene : {"contact", "stacked", "cornell", "glow", "arealight"}) {
    r = rtlab({"list", "--scene", scene});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_FALSE(hasNoisyNumber(r.out, found)) << scene << ": " << found;
  }
  EXPECT_NE(r.out.find("light0.radius = 0.1 "), std::string::npos) << "arealight's light0.radius is 0.1f";
}

// --- PNG previews of data -----------------------------------------------------------------------

TEST_F(CliMessages, RangeSpreadsADimDebugView) {
  const std::vector<std::string> base = {"-t", "pcss", "--aov", "pcss.penumbra"};
  auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), base.begin(), base.end());
    return extra;
  };
  const rtlab::Image plain = rtlab::readImage(render(base, "plain.png"));
  const rtlab::Image exr = rtlab::readImage(render(base, "raw.exr"));
  const rtlab::Image ranged = rtlab::readImage(render(with({"--range", "0:0.25"}), "ranged.png"));
  const rtlab::Image automatic = rtlab::readImage(render(with({"--range", "auto"}), "auto.png"));
  ASSERT_EQ(ranged.channels, 1);
  // The raw data, and what LO:HI makes of it: (v - 0) / 0.25 per valid pixel, 8-bit.
  double worst = 0.0;
  for (std::size_t i = 0; i < exr.pixels.size(); ++i) {
    const bool valid = !exr.hasMask() || exr.mask[i] > 0.5f;
    const double expected = valid ? std::clamp(exr.pixels[i] / 0.25, 0.0, 1.0) : 0.0;
    worst = std::max(worst, std::abs(expected - ranged.pixels[i]));
  }
  EXPECT_LE(worst, 1.0 / 255.0 + 1e-6);
  EXPECT_GT(meanOfValid(ranged), 2.0 * meanOfValid(plain) + 0.01) << "the range must brighten the preview";
  float top = 0.0f;
  for (float v : automatic.pixels) top = std::max(top, v);
  EXPECT_EQ(top, 1.0f) << "auto: the largest valid value is white";
}

TEST_F(CliMessages, FalseColorIsMagmaWithAStatedScale) {
  const auto r = rtlab({"render", "--size", "160x90", "-t", "pcss", "--aov", "pcss.penumbra", "--false-color",
                        "--range", "0:0.5", "--out", path("fc.png")});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("rtlab: note: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("from 0 (darkest) to 0.5 (brightest, magma)"), std::string::npos) << r.err;
  const rtlab::Image im = rtlab::readImage(path("fc.png"));
  ASSERT_EQ(im.channels, 3);
  // Magma's low end is dark purple: blue above red and green where the value is 0 (background
  // pixels are mid gray), and there is colour somewhere.
  bool purple = false, gray = false;
  for (std::size_t p = 0; p < im.pixelCount(); ++p) {
    const float* c = &im.pixels[p * 3];
    purple = purple || (c[2] > c[0] && c[2] > c[1] && c[2] < 0.2f);
    gray = gray || (std::abs(c[0] - 0.5f) < 0.01f && c[0] == c[1] && c[1] == c[2]);
  }
  EXPECT_TRUE(purple);
  EXPECT_TRUE(gray);
}

TEST_F(CliMessages, PreviewFlagsRefusedWhereTheyCannotApply) {
  const std::string png = path("x.png");
  const std::vector<std::string> pen = {"render", "--size", "32x32", "-t", "pcss", "--aov", "pcss.penumbra"};
  auto plus = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = pen;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  expectError(plus({"--out", png, "--range", "0.5:0.1"}), 2, "'0.5:0.1'");
  expectError(plus({"--out", png, "--range", "0.5:0.5"}), 2, "LO (0.5) must be less than HI (0.5)");
  expectError(plus({"--out", png, "--range", "a:b"}), 2, "'a:b'");
  expectError(plus({"--out", png, "--range", "0.5"}), 2, "expected LO:HI");
  expectError(plus({"--out", path("x.exr"), "--range", "0:1"}), 2, "EXR and PFM outputs hold the raw data");
  expectError(plus({"--out", path("x.pfm"), "--false-color"}), 2, "EXR and PFM outputs hold the raw data");
  expectError({"render", "--size", "32x32", "--out", png, "--range", "0:1"}, 2, "'color' is tone-mapped");
  expectError({"render", "--size", "32x32", "--out", png, "--aov", "normal", "--false-color"}, 2,
              "'normal' has 3 channels");
  EXPECT_FALSE(fs::exists(png));
}

// --- compare: heat map and warnings -------------------------------------------------------------

TEST_F(CliMessages, CompareHeatmapOnAStatedScale) {
  rtlab::Image a(8, 4, 1), b(8, 4, 1);
  for (int x = 0; x < 8; ++x)
    for (int y = 0; y < 4; ++y) b.at(x, y, 0) = 0.05f * x; // error grows to the right, 0.35 at most
  rtlab::writeImage(path("a.exr"), a);
  rtlab::writeImage(path("b.exr"), b);
  auto r = rtlab({"compare", path("a.exr"), path("b.exr"), "--heatmap", path("h.png"), "--heatmap-max", "0.2"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err; // same kind: no warning
  EXPECT_NE(r.out.find("heatmap"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" .. 0.2 brightest"), std::string::npos) << r.out;
  const rtlab::Image h = rtlab::readImage(path("h.png"));
  ASSERT_EQ(h.channels, 3);
  ASSERT_EQ(h.width, 8);
  auto luma = [&](int x) { return h.at(x, 1, 0) + h.at(x, 1, 1) + h.at(x, 1, 2); };
  for (int x = 1; x <= 4; ++x) EXPECT_GT(luma(x), luma(x - 1)) << x; // brighter with the error
  EXPECT_EQ(luma(5), luma(4)); // 0.25 and 0.2: both at the top of the scale
  // Default scale: max_abs, reported in JSON.
  r = rtlab({"compare", path("a.exr"), path("b.exr"), "--heatmap", path("h2.png"), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j.at("heatmap").at("max").get<double>(), j.at("max_abs").get<double>(), 1e-12);
  EXPECT_EQ(j.at("heatmap").at("file").get<std::string>(), path("h2.png"));
  expectError({"compare", path("a.exr"), path("b.exr"), "--heatmap", path("h.exr")}, 2, "must be a .png");
  expectError({"compare", path("a.exr"), path("b.exr"), "--heatmap", path("h3.png"), "--heatmap-max", "0"}, 2,
              "--heatmap-max");
}

TEST_F(CliMessages, CompareWarnsOnInputsOfDifferentKinds) {
  rtlab::Image gray(8, 4, 1), rgb(8, 4, 3);
  rtlab::writeImage(path("g.exr"), gray);
  rtlab::writeImage(path("g.png"), gray);
  rtlab::writeImage(path("c.exr"), rgb);
  auto r = rtlab({"compare", path("g.png"), path("g.exr")});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("rtlab: warning: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("linear float data"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("rmse"), std::string::npos);
  r = rtlab({"compare", path("g.exr"), path("c.exr")});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("rtlab: warning: '" + path("g.exr") + "' has 1 channel and '" + path("c.exr") +
                       "' has 3 channels"),
            std::string::npos)
      << r.err;
}

// --- scene.ambient ------------------------------------------------------------------------------

TEST_F(CliMessages, SceneAmbientChangesColor) {
  const rtlab::Image base = rtlab::readImage(render({"--scene", "cornell"}, "base.exr"));
  const rtlab::Image lit = rtlab::readImage(render({"--scene", "cornell", "--set", "scene.ambient=0.6,0.6,0.6"}, "lit.exr"));
  const rtlab::Image dark = rtlab::readImage(render({"--scene", "cornell", "--set", "scene.ambient=0,0,0"}, "dark.exr"));
  EXPECT_GT(meanOfValid(lit), meanOfValid(base) + 0.05);
  EXPECT_LT(meanOfValid(dark), meanOfValid(base));
  expectError({"render", "--out", path("x.png"), "--set", "scene.ambient=-1,0,0"}, 2, "'scene.ambient'");
  expectError({"render", "--out", path("x.png"), "--set", "scene.ambient=0.5"}, 2, "'scene.ambient'");
  const auto r = rtlab({"list", "--json", "--scene", "cornell"});
  ASSERT_EQ(r.exitCode, 0);
  const auto j = nlohmann::json::parse(r.out);
  bool listed = false;
  for (const auto& p : j.at("scene_params"))
    if (p.at("key") == "scene.ambient") listed = p.at("type") == "color";
  EXPECT_TRUE(listed);
}

TEST_F(CliMessages, SsaoIsVisibleInColorOnCornell) {
  // The AO scene's default ambient makes AO visible in the frame: with the old 0.03, toggling
  // ssao changed the linear colour by at most 0.011 (0.0107 at 640x360); with 0.2, 0.072. Bound:
  // 0.04 on the linear colour (EXR), and the tone-mapped frame changes somewhere by 0.08 or more.
  const std::vector<std::string> size = {"--size", "320x180", "--scene", "cornell"};
  auto args = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), size.begin(), size.end());
    return extra;
  };
  const rtlab::Image off = rtlab::readImage(render(args({}), "off.exr"));
  const rtlab::Image on = rtlab::readImage(render(args({"-t", "ssao"}), "on.exr"));
  EXPECT_GE(maxAbsDifference(off, on), 0.04);
  const rtlab::Image offPng = rtlab::readImage(render(args({}), "off.png"));
  const rtlab::Image onPng = rtlab::readImage(render(args({"-t", "ssao"}), "on.png"));
  EXPECT_GE(maxAbsDifference(offPng, onPng), 0.08);
}

// --- the README's examples ----------------------------------------------------------------------

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line.substr(0, line.find(" #")));
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

TEST_F(CliMessages, ReadmeExamplesWithTheSampleSceneRun) {
  // Every README command that uses a file under assets/ runs as written (from the repository
  // root; outputs redirected to a scratch folder, and a small frame). `rtlab view` runs under
  // Xvfb until its first frame is saved (--frames 1 --screenshot), which it draws only after
  // loading and checking the files it was given.
  std::ifstream readme(fs::path(RTLAB_SOURCE_DIR) / "README.md");
  ASSERT_TRUE(readme.good());
  int ran = 0;
  for (std::string line; std::getline(readme, line);) {
    if (line.rfind("build/rtlab ", 0) != 0 || line.find("assets/") == std::string::npos) continue;
    SCOPED_TRACE(line);
    std::vector<std::string> args = words(line);
    args.erase(args.begin()); // build/rtlab
    for (std::size_t i = 0; i < args.size(); ++i) {
      if (args[i].rfind("assets/", 0) == 0) args[i] = (fs::path(RTLAB_SOURCE_DIR) / args[i]).string();
      if ((args[i] == "--out" || args[i] == "--save-preset" || args[i] == "--stats") && i + 1 < args.size())
        args[i + 1] = path(args[i + 1]);
    }
    args.insert(args.end(), {"--size", "160x90"});
    if (std::find(args.begin(), args.end(), "--out") == args.end() && args[0] == "render")
      args.insert(args.end(), {"--out", path("default.png")});
    const bool view = args[0] == "view";
    if (view) {
      args.erase(args.begin());
      args.insert(args.end(), {"--frames", "1", "--screenshot", path("view.png")});
    }
    const auto r = view ? rtlab::test::runView(args) : rtlab(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    if (view) {
      EXPECT_TRUE(fs::exists(path("view.png")));
    }
    for (std::size_t i = 0; i + 1 < args.size(); ++i)
      if (args[i] == "--out" || args[i] == "--save-preset") {
        EXPECT_TRUE(fs::exists(args[i + 1])) << args[i + 1];
      }
    ++ran;
    // "then: --preset p.json": the saved preset renders the same scene again.
    const auto preset = std::find(args.begin(), args.end(), "--save-preset");
    if (preset != args.end()) {
      const auto again = rtlab({"render", "--preset", *(preset + 1), "--size", "160x90", "--out", path("again.png")});
      EXPECT_EQ(again.exitCode, 0) << again.err;
    }
  }
  EXPECT_GE(ran, 1) << "the README shows no command with a scene under assets/";
}

} // namespace
