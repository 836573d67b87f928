// rtlab reference through the binary (docs/contract.md): images with the background masked, exit codes
// for bad input, determinism for a seed, and Ctrl-C leaving no file.
#include "image/image.h"
#include "process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;
using rtlab::test::runProcess;

namespace {

fs::path testDir(const std::string& name) {
  fs::path d = fs::path(RTLAB_TEST_TMP) / "cli-reference" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(CliReference, ExrHasTheSurfaceMaskAndZeroBackground) {
  const fs::path dir = testDir("exr");
  const fs::path out = dir / "ao.exr";
  // contact's camera sees sky above the ground: background pixels exist.
  const auto r = runProcess(RTLAB_BINARY, {"reference", "--scene", "contact", "--size", "48x32", "--aov", "ao", "--spp",
                                          "4", "--out", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  const rtlab::Image im = rtlab::readImage(out.string());
  EXPECT_EQ(im.width, 48);
  EXPECT_EQ(im.height, 32);
  EXPECT_EQ(im.channels, 1);
  ASSERT_TRUE(im.hasMask());
  int surface = 0, background = 0;
  for (std::size_t i = 0; i < im.pixelCount(); ++i) {
    EXPECT_TRUE(im.mask[i] == 0.0f || im.mask[i] == 1.0f) << im.mask[i];
    if (im.mask[i] == 0.0f) {
      ++background;
      EXPECT_EQ(im.pixels[i], 0.0f);
    } else {
      ++surface;
      EXPECT_GE(im.pixels[i], 0.0f);
      EXPECT_LE(im.pixels[i], 1.0f);
    }
  }
  EXPECT_GT(surface, 0);
  EXPECT_GT(background, 0);
}

TEST(CliReference, EveryAovAndFormat) {
  const fs::path dir = testDir("formats");
  for (const auto& [aov, file, channels] : {std::tuple{"visibility", "v.pfm", 1}, std::tuple{"indirect", "i.pfm", 3},
                                            std::tuple{"indirect", "i.exr", 3}, std::tuple{"visibility", "v.png", 1}}) {
    const auto r = runProcess(RTLAB_BINARY, {"reference", "--scene", "cornell", "--size", "24x16", "--aov", aov,
                                            "--spp", "2", "--out", (dir / file).string()});
    ASSERT_EQ(r.exitCode, 0) << aov << " " << file << ": " << r.err;
    if (std::string(file).ends_with(".png")) continue;
    EXPECT_EQ(rtlab::readImage((dir / file).string()).channels, channels) << file;
  }
}

TEST(CliReference, DefaultOutputNameAndDeterminism) {
  const fs::path dir = testDir("default");
  const fs::path old = fs::current_path();
  fs::current_path(dir);
  const std::vector<std::string> args = {"reference", "--scene", "cornell", "--size", "32x24", "--aov", "visibility",
                                         "--spp", "8", "--seed", "5", "--frames", "3"};
  const auto r = runProcess(RTLAB_BINARY, args);
  fs::current_path(old);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_TRUE(fs::exists(dir / "cornell_visibility_ref.exr"));
  // Same seed, same file; another seed, another image.
  auto again = args;
  again.insert(again.end(), {"--out", (dir / "again.exr").string()});
  ASSERT_EQ(runProcess(RTLAB_BINARY, again).exitCode, 0);
  EXPECT_EQ(slurp(dir / "cornell_visibility_ref.exr"), slurp(dir / "again.exr"));
  auto other = again;
  other[10] = "6"; // --seed
  other.back() = (dir / "other.exr").string();
  ASSERT_EQ(runProcess(RTLAB_BINARY, other).exitCode, 0);
  EXPECT_NE(rtlab::readImage((dir / "other.exr").string()).pixels, rtlab::readImage((dir / "again.exr").string()).pixels);
}

TEST(CliReference, BadInputExitsWithTheContractCodes) {
  const fs::path dir = testDir("bad");
  const std::string out = (dir / "x.exr").string();
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string mention;
  };
  const std::vector<Case> cases = {
      {{"reference", "--out", out}, 2, "--aov"},
      {{"reference", "--aov", "color", "--out", out}, 2, "color"},
      {{"reference", "--aov", "depth", "--out", out}, 2, "depth"},
      {{"reference", "--aov", "ao", "--spp", "0", "--out", out}, 2, "--spp"},
      {{"reference", "--aov", "ao", "--spp", "65537", "--out", out}, 2, "--spp"},
      {{"reference", "--aov", "ao", "--spp", "many", "--out", out}, 2, "many"},
      {{"reference", "--aov", "ao", "--out", (dir / "x.tiff").string()}, 2, "x.tiff"},
      {{"reference", "--aov", "ao", "--scene", "nosuchscene", "--out", out}, 2, "nosuchscene"},
      {{"reference", "--aov", "ao", "--scene", (dir / "missing.gltf").string(), "--out", out}, 3, "missing.gltf"},
      {{"reference", "--aov", "ao", "--set", "ao.radius=0", "--out", out}, 2, "ao.radius"},
      {{"reference", "--aov", "ao", "--size", "8x8", "--out", (dir / "no" / "such" / "dir.exr").string()}, 6, "dir.exr"},
  };
  for (const auto& c : cases) {
    const auto r = runProcess(RTLAB_BINARY, c.args);
    EXPECT_EQ(r.exitCode, c.code) << c.args[1] << " " << c.args.back() << ": " << r.err;
    EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("rtlab: error:", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.mention), std::string::npos) << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
  const auto help = runProcess(RTLAB_BINARY, {"reference", "--help"});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("--spp"), std::string::npos);
}

// The choices, the suggestion and the help come from the reference registry (docs/measuring.md
// "References per stage"): every registered reference is listed with its one-line description.
TEST(CliReference, UnknownAovNamesTheRegisteredChoices) {
  const fs::path dir = testDir("choices");
  const std::string out = (dir / "x.exr").string();
  const auto bogus = runProcess(RTLAB_BINARY, {"reference", "--aov", "bogus", "--size", "8x8", "--out", out});
  EXPECT_EQ(bogus.exitCode, 2) << bogus.err;
  EXPECT_EQ(rtlab::test::lineCount(bogus.err), 1) << bogus.err;
  EXPECT_NE(bogus.err.find("rtlab: error: unknown reference AOV 'bogus' (choices: visibility, ao, indirect, transparency, arealight, bloom)"),
            std::string::npos)
      << bogus.err;
  const auto typo = runProcess(RTLAB_BINARY, {"reference", "--aov", "visibilty", "--size", "8x8", "--out", out});
  EXPECT_EQ(typo.exitCode, 2) << typo.err;
  EXPECT_NE(typo.err.find("did you mean 'visibility'"), std::string::npos) << typo.err;
  EXPECT_TRUE(fs::is_empty(dir));
  const auto help = runProcess(RTLAB_BINARY, {"reference", "--help"});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("--aov visibility|ao|indirect"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("ao: ambient occlusion within ao.radius"), std::string::npos) << help.out;
}

TEST(CliReference, InterruptLeavesNoFile) {
  // Minutes of indirect light at this size: interrupted while casting rays.
  const fs::path dir = testDir("interrupt");
  const auto r = runProcess(RTLAB_BINARY, {"reference", "--scene", "cornell", "--size", "1024x1024", "--aov", "indirect",
                                          "--spp", "4096", "--out", (dir / "i.exr").string()},
                            120, 1500);
  EXPECT_EQ(r.exitCode, 130) << r.err;
  EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err; // no progress bar: stderr is not a terminal
  EXPECT_TRUE(fs::is_empty(dir));
}

} // namespace

namespace {

// `rtlab reference --aov bloom` is the exact convolution of the frame's colour before post: every
// pixel valid (A = 1), no --spp beyond 1, and the gaussian method's AOV of the same frame agrees:
// with 32-bit storage to 1e-4 of the peak (fp32 sums), with the default 16-bit storage to 5e-3
// (measured 2.9e-3: the bright pass, each octave's blur and the running sum are each rounded to
// 11 significant bits).
TEST(CliReference, BloomIsTheExactConvolutionTheGaussianMethodMatches) {
  const fs::path dir = testDir("bloom");
  const std::vector<std::string> frame = {"--scene", "contact", "--size", "96x64", "--set", "bloom.threshold=0.5",
                                          "--set", "bloom.intensity=1"};
  auto with = [&](std::vector<std::string> args) {
    args.insert(args.end(), frame.begin(), frame.end());
    return args;
  };
  const fs::path ref = dir / "ref.exr", gpu = dir / "gpu.exr";
  const auto r = runProcess(RTLAB_BINARY, with({"reference", "--aov", "bloom", "--out", ref.string()}));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const rtlab::Image a = rtlab::readImage(ref.string());
  ASSERT_EQ(a.channels, 3);
  ASSERT_TRUE(a.hasMask());
  for (const auto& [format, bound] : {std::pair{"rgba32f", 1e-4}, std::pair{"rgba16f", 5e-3}}) {
    const auto g = runProcess(RTLAB_BINARY, with({"render", "-t", "bloom", "--set", "bloom.method=gaussian", "--set",
                                                  std::string("bloom.format=") + format, "--aov", "bloom", "--out",
                                                  gpu.string()}));
    ASSERT_EQ(g.exitCode, 0) << g.err;
    const rtlab::Image b = rtlab::readImage(gpu.string());
    double maxValue = 0, maxDiff = 0;
    for (std::size_t i = 0; i < a.pixelCount(); ++i) {
      EXPECT_EQ(a.mask[i], 1.0f);
      for (int c = 0; c < 3; ++c) {
        maxValue = std::max(maxValue, double(a.pixels[i * 3 + c]));
        maxDiff = std::max(maxDiff, std::abs(double(a.pixels[i * 3 + c]) - double(b.pixels[i * 3 + c])));
      }
    }
    EXPECT_GT(maxValue, 0.05) << "the lit floor blooms at threshold 0.5";
    EXPECT_LT(maxDiff, bound * maxValue) << format;
  }
  const auto spp = runProcess(RTLAB_BINARY, with({"reference", "--aov", "bloom", "--spp", "4", "--out", (dir / "x.exr").string()}));
  EXPECT_EQ(spp.exitCode, 2);
  EXPECT_NE(spp.err.find("--spp"), std::string::npos) << spp.err;
  EXPECT_FALSE(fs::exists(dir / "x.exr"));
}


// `rtlab reference --aov transparency` (docs/contract.md "Transparency"): on a scene without
// transparent layers it is the frame's colour (the stage AOV's neutral value); on `panes` it agrees
// with the built-in fallback, which sorts whole objects back to front (exact Over wherever objects
// do not intersect), except where the yellow pane cuts through the green one.
TEST(CliReference, TransparencyIsExactOverAndTheOpaqueColourWithoutLayers) {
  const fs::path dir = testDir("transparency");
  auto both = [&](const std::string& scene) {
    const std::vector<std::string> frame = {"--scene", scene, "--size", "96x64", "--aov", "transparency"};
    std::vector<std::string> ref = {"reference"}, render = {"render"};
    ref.insert(ref.end(), frame.begin(), frame.end());
    render.insert(render.end(), frame.begin(), frame.end());
    ref.insert(ref.end(), {"--out", (dir / (scene + "_ref.exr")).string()});
    render.insert(render.end(), {"--out", (dir / (scene + "_gpu.exr")).string()});
    const auto r = runProcess(RTLAB_BINARY, ref);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const auto g = runProcess(RTLAB_BINARY, render);
    EXPECT_EQ(g.exitCode, 0) << g.err;
    return std::pair{rtlab::readImage((dir / (scene + "_ref.exr")).string()),
                     rtlab::readImage((dir / (scene + "_gpu.exr")).string())};
  };
  const auto [contactRef, contactGpu] = both("contact");
  ASSERT_EQ(contactRef.channels, 3);
  EXPECT_EQ(contactRef.pixels, contactGpu.pixels);
  EXPECT_EQ(contactRef.mask, contactGpu.mask);

  const auto [panesRef, panesGpu] = both("panes");
  ASSERT_EQ(panesRef.pixelCount(), panesGpu.pixelCount());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < panesRef.pixelCount(); ++i) {
    EXPECT_EQ(panesRef.mask[i], panesGpu.mask[i]) << "pixel " << i;
    double d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(double(panesRef.pixels[i * 3 + c]) - panesGpu.pixels[i * 3 + c]));
    differing += d > 2e-3 ? 1 : 0;
  }
  EXPECT_GT(differing, 0u) << "the intersecting panes are sorted per object by the fallback";
  EXPECT_LT(double(differing), 0.05 * double(panesRef.pixelCount()));
  const auto spp = runProcess(RTLAB_BINARY, {"reference", "--scene", "panes", "--aov", "transparency", "--spp", "2",
                                             "--out", (dir / "x.exr").string()});
  EXPECT_EQ(spp.exitCode, 2);
  EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

// `--aov arealight` (docs/contract.md "Area lights", docs/measuring.md "The arealight reference"):
// three channels, 0 with A = 0 on the background, the same file for the same seed, another image for
// another seed, 0 on every pixel of a scene without a rectangular light, and --spp outside 1..131072
// refused with one line and no file.
std::vector<std::string> arealightArgs(const std::string& scene, const std::string& seed, const fs::path& out) {
  return {"reference", "--scene", scene, "--size", "48x27", "--aov", "arealight", "--spp", "16", "--seed", seed, "--out",
          out.string()};
}

TEST(CliArealightReference, DeterministicMaskedAndZeroWithoutARectLight) {
  const fs::path dir = testDir("arealight-run");
  ASSERT_EQ(runProcess(RTLAB_BINARY, arealightArgs("arealight", "3", dir / "a.exr")).exitCode, 0);
  ASSERT_EQ(runProcess(RTLAB_BINARY, arealightArgs("arealight", "3", dir / "b.exr")).exitCode, 0);
  ASSERT_EQ(runProcess(RTLAB_BINARY, arealightArgs("arealight", "4", dir / "c.exr")).exitCode, 0);
  EXPECT_EQ(slurp(dir / "a.exr"), slurp(dir / "b.exr"));
  const rtlab::Image a = rtlab::readImage((dir / "a.exr").string());
  const rtlab::Image c = rtlab::readImage((dir / "c.exr").string());
  EXPECT_NE(a.pixels, c.pixels);
  ASSERT_EQ(a.channels, 3);
  ASSERT_TRUE(a.hasMask());
  int surface = 0, lit = 0;
  for (std::size_t i = 0; i < a.pixelCount(); ++i) {
    const float sum = a.pixels[i * 3] + a.pixels[i * 3 + 1] + a.pixels[i * 3 + 2];
    if (a.mask[i] < 0.5f) {
      EXPECT_EQ(sum, 0.0f) << i;
      continue;
    }
    ++surface;
    lit += sum > 0.0f ? 1 : 0;
  }
  EXPECT_GT(surface, 48 * 27 / 3); // the floor, the sphere and the box (the sky above them: background)
  EXPECT_GT(lit, surface / 2); // the floor, the sphere and the box face the light

  // cornell has no rectangular light: the stage's neutral value, 0, on every surface pixel.
  ASSERT_EQ(runProcess(RTLAB_BINARY, arealightArgs("cornell", "1", dir / "cornell.exr")).exitCode, 0);
  const rtlab::Image none = rtlab::readImage((dir / "cornell.exr").string());
  for (float v : none.pixels) ASSERT_EQ(v, 0.0f);
  int covered = 0;
  for (float m : none.mask) covered += m > 0.5f ? 1 : 0;
  EXPECT_GT(covered, 0);
}

TEST(CliArealightReference, SppOutsideItsRangeIsAUsageError) {
  const fs::path dir = testDir("arealight-bad");
  for (const char* spp : {"0", "131073"}) {
    auto a = arealightArgs("arealight", "1", dir / "x.exr");
    a[8] = spp;
    const auto r = runProcess(RTLAB_BINARY, a);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("rtlab: error:", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("--spp"), std::string::npos) << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

} // namespace
