// rtlab sweep through the binary (docs/sweeps.md): a 3-point sweep writes 3 CSV rows and a
// self-contained report (HTML that parses, a well-formed SVG, nothing referenced outside the
// page); --emit-jobs, running the jobs, then --collect gives the same CSV as a direct sweep
// (except the timing columns); the report opens in headless Chromium without console errors and
// its screenshot is not blank (kept as RTLAB_TEST_TMP/sweep/report.png); bad input fails early.
#include "chromium.h"
#include "process.h"

#include "image/image.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using rtlab::test::runProcess;

namespace {

const fs::path kRoot = fs::path(RTLAB_TEST_TMP) / "sweep";

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) out.push_back(line);
  return out;
}

std::vector<std::string> splitCsv(const std::string& line) { // no quoted fields in these sweeps
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

// The CSV without the measured-time columns (ms, frame_ms), which differ between runs.
std::vector<std::vector<std::string>> csvWithoutTimes(const fs::path& path) {
  const auto rows = lines(slurp(path));
  std::vector<std::vector<std::string>> out;
  if (rows.empty()) return out;
  const auto header = splitCsv(rows[0]);
  for (const auto& row : rows) {
    const auto cells = splitCsv(row);
    std::vector<std::string> kept;
    for (std::size_t i = 0; i < cells.size() && i < header.size(); ++i)
      if (header[i] != "ms" && header[i] != "frame_ms") kept.push_back(cells[i]);
    out.push_back(kept);
  }
  return out;
}

// The sweep every test shares: shadow_map at three shadow-map resolutions, 32x32, 16 spp.
const std::vector<std::string> kSweepArgs = {"sweep", "--scene", "contact", "--size", "32x32", "--spp", "16",
                                             "-t", "shadow_map", "--vary", "shadow.resolution=256,512,1024"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

const char* kReportChecker = R"PY(
import html.parser, os, re, sys, xml.etree.ElementTree as ET
text = open(sys.argv[1], encoding='utf-8').read()
folder = os.path.dirname(os.path.abspath(sys.argv[1]))
VOID = {'area', 'base', 'br', 'col', 'embed', 'hr', 'img', 'input', 'link', 'meta', 'source', 'track', 'wbr'}
errors = []
class Checker(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack, self.refs, self.imgs = [], [], 0
    def handle_starttag(self, tag, attrs):
        for k, v in attrs:
            v = v or ''
            if k in ('src', 'href', 'srcset', 'action', 'data', 'poster', 'xlink:href', 'background'):
                self.refs.append((tag, k, v))
            if 'url(' in v:
                errors.append('url() in attribute of <%s>' % tag)
        if tag == 'img':
            self.imgs += 1
        if tag in ('script', 'link', 'iframe', 'object', 'embed'):
            errors.append('<%s> element' % tag)
        if tag not in VOID:
            self.stack.append(tag)
    def handle_endtag(self, tag):
        if tag in VOID:
            return
        if not self.stack or self.stack[-1] != tag:
            errors.append('unbalanced </%s> (open: %s)' % (tag, self.stack[-3:]))
        else:
            self.stack.pop()
c = Checker()
c.feed(text)
c.close()
if c.stack:
    errors.append('unclosed: %s' % c.stack)
if not text.startswith('<!DOCTYPE html>'):
    errors.append('no doctype')
for tag, k, v in c.refs:
    if v.startswith('data:') or v.startswith('#'):
        continue
    # A relative link to a file of the sweep folder (a full-size image): inside it, and there.
    target = v.split('#')[0]
    if ':' in target or target.startswith('/') or '..' in target.split('/'):
        errors.append('external reference %s=%r on <%s>' % (k, v[:60], tag))
    elif not os.path.isfile(os.path.join(folder, target)):
        errors.append('broken link %s=%r on <%s>' % (k, v[:60], tag))
for bad in ('http://', 'https://', '@import', 'url('):
    if bad in text:
        errors.append('%r in the page' % bad)
svgs = re.findall(r'<svg\b.*?</svg>', text, re.S)
if len(svgs) != 1:
    errors.append('%d svg elements' % len(svgs))
for svg in svgs:
    try:
        root = ET.fromstring(svg)
        circles = [e for e in root.iter() if e.tag == 'circle' and e.get('class') == 'point']
        if len(circles) != int(sys.argv[2]):
            errors.append('%d points in the chart' % len(circles))
        if not [e for e in root.iter() if e.tag == 'path' and e.get('class') == 'pareto']:
            errors.append('no Pareto front')
        # Each point labelled with its value; the technique's points joined in value order.
        labels = [e.text for e in root.iter() if e.tag == 'text' and e.get('class') == 'label']
        if labels != sys.argv[3].split(','):
            errors.append('point labels %s' % labels)
        series = [e for e in root.iter() if e.tag == 'polyline' and e.get('class') == 'series']
        if len(series) != 1 or len(series[0].get('points').split()) != int(sys.argv[2]):
            errors.append('%d joining lines' % len(series))
        else:
            xs = [float(p.split(',')[0]) for p in series[0].get('points').split()]
            cx = [float(e.get('cx')) for e in circles]
            if sorted(xs) != sorted(cx):
                errors.append('the line does not join the points')
        # The legend lies outside the plot area (the first rect).
        plot = next(e for e in root.iter() if e.tag == 'rect')
        right = float(plot.get('x')) + float(plot.get('width'))
        legend = [e for e in root.iter() if e.tag == 'g' and e.get('class') == 'legend']
        xs = [float(e.get(a)) for g in legend for e in g.iter() for a in ('x', 'x1', 'cx') if e.get(a) is not None]
        if not xs or min(xs) < right:
            errors.append('legend inside the plot (x %s, plot right %s)' % (min(xs) if xs else None, right))
    except StopIteration:
        errors.append('no plot area')
    except ET.ParseError as e:
        errors.append('svg not well-formed: %s' % e)
if c.imgs < 2 * int(sys.argv[2]) + 1:
    errors.append('%d images' % c.imgs)
print('\n'.join(errors) if errors else 'ok')
sys.exit(1 if errors else 0)
)PY";

// A folder of its own for each test: ctest runs every test in its own process, in parallel.
fs::path testDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir = kRoot / info->test_suite_name() / info->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

class Sweep : public ::testing::Test {
protected:
  // The direct sweep runs once per process, into the folder of the first test that needs it.
  void SetUp() override {
    if (s_direct.empty()) {
      const fs::path dir = testDir();
      setenv("RTLAB_CACHE_DIR", (dir / "cache-direct").c_str(), 1);
      s_result = runProcess(RTLAB_BINARY, with(kSweepArgs, {"--out", (dir / "direct").string(), "--jobs", "2"}), 120);
      s_direct = dir / "direct";
    }
    ASSERT_EQ(s_result.exitCode, 0) << s_result.err;
  }
  static fs::path s_direct;
  static rtlab::test::ProcessResult s_result;
};
fs::path Sweep::s_direct;
rtlab::test::ProcessResult Sweep::s_result;

TEST_F(Sweep, ThreePointsWriteThreeCsvRows) {
  const fs::path dir = s_direct;
  const auto rows = lines(slurp(dir / "results.csv"));
  ASSERT_EQ(rows.size(), 4u) << slurp(dir / "results.csv");
  EXPECT_EQ(rows[0], "technique,shadow.resolution,ms,frame_ms,rmse,psnr,ssim,flip,timing");
  const char* resolutions[] = {"256", "512", "1024"};
  for (int i = 0; i < 3; ++i) {
    const auto cells = splitCsv(rows[std::size_t(i) + 1]);
    ASSERT_EQ(cells.size(), 9u) << rows[std::size_t(i) + 1];
    EXPECT_EQ(cells[0], "shadow_map");
    EXPECT_EQ(cells[1], resolutions[i]);
    EXPECT_GT(std::stod(cells[2]), 0.0) << "the technique's passes take time";
    const double rmse = std::stod(cells[4]);
    EXPECT_TRUE(rmse >= 0 && rmse < 1) << rows[std::size_t(i) + 1];
    EXPECT_TRUE(cells[8] == "cpu-finish" || cells[8] == "gpu-query") << cells[8];
  }
  // Each point's outputs, one reference (resolution does not define it), and its cache entry.
  for (const char* p : {"000", "001", "002"})
    for (const char* f : {"aov.exr", "color.png", "stats.json", "done.json", "error.png"})
      EXPECT_TRUE(fs::is_regular_file(dir / "points" / p / f)) << p << "/" << f;
  const auto plan = nlohmann::json::parse(slurp(dir / "sweep.json"));
  EXPECT_EQ(plan["schema"], 1);
  ASSERT_EQ(plan["references"].size(), 1u);
  const std::string hash = plan["references"][0]["hash"];
  EXPECT_TRUE(fs::is_regular_file(dir / "reference" / (hash + ".exr")));
  EXPECT_TRUE(fs::is_regular_file(dir.parent_path() / "cache-direct" / "reference" / (hash + ".exr")));
  EXPECT_EQ(lines(slurp(dir / "jobs.txt")).size(), 4u);
  // The point's AOV has the mask, and the reference matches its size.
  const rtlab::Image aov = rtlab::readImage((dir / "points" / "000" / "aov.exr").string());
  EXPECT_EQ(aov.width, 32);
  EXPECT_TRUE(aov.hasMask());
}

TEST_F(Sweep, ReportIsSelfContainedHtmlWithWellFormedSvg) {
  const fs::path report = s_direct / "report.html";
  ASSERT_TRUE(fs::is_regular_file(report));
  const auto r = runProcess("/usr/bin/python3", {"-c", kReportChecker, report.string(), "3", "256,512,1024"});
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  const std::string html = slurp(report);
  for (const char* needle : {"cpu-finish", "shadow.resolution", "Pareto front", "seed", "commit"})
    EXPECT_NE(html.find(needle), std::string::npos) << needle;
  // The command that reproduces it, shell-quoted as given.
  EXPECT_NE(html.find("<pre class=\"command\"><code>rtlab sweep --scene contact --size 32x32 --spp 16 -t shadow_map "
                      "--vary shadow.resolution=256,512,1024 --out "),
            std::string::npos);
  // Heat maps on one stated scale with a colour bar, each linked to its full-size image.
  EXPECT_NE(html.find("class=\"colorbar\""), std::string::npos);
  EXPECT_NE(html.find("99th percentile"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"points/000/error.png\">"), std::string::npos);
}

// sweep.json and the page record what decided the timings: jobs, frames, warm-up, timing,
// renderer, backend, size.
TEST_F(Sweep, RecordsWhatDecidedTheTimingsAndWarnsOfParallelJobs) {
  const auto plan = nlohmann::json::parse(slurp(s_direct / "sweep.json"));
  EXPECT_EQ(plan["schema"], 1);
  EXPECT_EQ(plan["jobs"], 2);
  EXPECT_EQ(plan["frames"], 1);
  EXPECT_EQ(plan["warmup_frames"], 1) << "--frames 1: one unmeasured frame first";
  EXPECT_EQ(plan["size"], nlohmann::json({32, 32}));
  EXPECT_EQ(plan["timing"], "auto");
  EXPECT_NE(plan["command"].get<std::string>().find("rtlab sweep --scene contact"), std::string::npos) << plan["command"];
  const auto& measured = plan["measured"];
  ASSERT_TRUE(measured.is_object()) << plan.dump(2);
  ASSERT_EQ(measured["renderer"].size(), 1u);
  EXPECT_FALSE(measured["renderer"][0].get<std::string>().empty());
  EXPECT_EQ(measured["backend"].size(), 1u);
  ASSERT_EQ(measured["timing"].size(), 1u);
  EXPECT_TRUE(measured["timing"][0] == "cpu-finish" || measured["timing"][0] == "gpu-query");
  EXPECT_TRUE(measured["software"].is_boolean());
  const std::string html = slurp(s_direct / "report.html");
  for (const char* needle : {"jobs", "2 at a time", "1 unmeasured, then 1 measured", "timing method", "renderer", "backend"})
    EXPECT_NE(html.find(needle), std::string::npos) << needle;

  // Two jobs at a time on a software rasterizer: the page says the timings are not to be
  // trusted, near the chart (before it); sweep.json carries the same warning. (With --jobs 1:
  // FolderHoldingASweepIsRefusedUnlessForced.)
  // On a hardware GPU the jobs do not share the rasterizer's CPU cores: no warning.
  const auto warning = html.find("<p class=\"warning\"");
  if (!measured["software"].get<bool>()) {
    EXPECT_EQ(warning, std::string::npos) << "hardware renderer " << measured["renderer"];
    EXPECT_TRUE(plan["measured"]["warning"].is_null());
    return;
  }
  ASSERT_NE(warning, std::string::npos);
  EXPECT_LT(warning, html.find("<svg")) << "the warning comes before the chart";
  EXPECT_NE(html.find("--jobs 2", warning), std::string::npos);
  EXPECT_TRUE(plan["measured"]["warning"].is_string());
}

TEST_F(Sweep, EmitJobsThenCollectGivesTheDirectSweepsCsv) {
  const fs::path root = s_direct.parent_path() / "emit-jobs";
  fs::remove_all(root);
  const fs::path dir = root / "emitted";
  const fs::path jobs = root / "jobs.txt";
  setenv("RTLAB_CACHE_DIR", (root / "cache-emitted").c_str(), 1); // a cold cache: the reference job renders
  const auto plan = runProcess(RTLAB_BINARY, with(kSweepArgs, {"--out", dir.string(), "--emit-jobs", jobs.string()}));
  ASSERT_EQ(plan.exitCode, 0) << plan.err;
  EXPECT_FALSE(fs::exists(dir / "points")) << "--emit-jobs renders nothing";
  const auto commands = lines(slurp(jobs));
  ASSERT_EQ(commands.size(), 4u);
  EXPECT_NE(commands[0].find("--run-reference"), std::string::npos) << commands[0];
  for (const auto& c : commands) EXPECT_EQ(c.front(), '/') << "absolute commands: " << c;

  // Collecting before the jobs ran names what is missing.
  const auto early = runProcess(RTLAB_BINARY, {"sweep", "--collect", dir.string()});
  EXPECT_EQ(early.exitCode, 3) << early.err;
  EXPECT_EQ(rtlab::test::lineCount(early.err), 1) << early.err;
  EXPECT_NE(early.err.find("points/000"), std::string::npos) << early.err;
  EXPECT_FALSE(fs::exists(dir / "results.csv"));

  // The points first, then the reference: points do not depend on it, only --collect does.
  for (std::size_t i = 1; i <= commands.size(); ++i) {
    const auto& c = commands[i % commands.size()];
    const auto r = runProcess("/bin/sh", {"-c", c}, 120);
    ASSERT_EQ(r.exitCode, 0) << c << "\n" << r.err;
  }
  const auto collect = runProcess(RTLAB_BINARY, {"sweep", "--collect", dir.string()});
  ASSERT_EQ(collect.exitCode, 0) << collect.err;
  EXPECT_EQ(csvWithoutTimes(dir / "results.csv"), csvWithoutTimes(s_direct / "results.csv"));
  EXPECT_TRUE(fs::is_regular_file(root / "cache-emitted" / "reference" /
                                  (nlohmann::json::parse(slurp(dir / "sweep.json"))["references"][0]["hash"].get<std::string>() +
                                   ".exr")));
  EXPECT_TRUE(fs::is_regular_file(dir / "report.html"));
}

// Every file under a folder with its content: "nothing changed" compares two of these.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return files;
}

// A folder that holds a sweep is refused (exit 6, one line naming it, nothing changed) unless
// --force, which replaces the sweep wholly: no point of the earlier sweep survives.
TEST_F(Sweep, FolderHoldingASweepIsRefusedUnlessForced) {
  const fs::path dir = s_direct.parent_path() / "folder-rule" / "sweep";
  fs::remove_all(dir.parent_path());
  fs::create_directories(dir.parent_path());
  fs::copy(s_direct, dir, fs::copy_options::recursive);
  const auto before = snapshot(dir);
  ASSERT_TRUE(before.count("points/002/done.json"));

  for (const auto& extra : std::vector<std::vector<std::string>>{
           {}, {"--emit-jobs", (dir.parent_path() / "jobs.txt").string()}}) {
    const auto r = runProcess(RTLAB_BINARY, with(with(kSweepArgs, {"--out", dir.string()}), extra));
    EXPECT_EQ(r.exitCode, 6) << r.err;
    EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("rtlab: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(dir.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
    EXPECT_TRUE(snapshot(dir) == before) << "a refused sweep changed its folder";
    EXPECT_FALSE(fs::exists(dir.parent_path() / "jobs.txt"));
  }

  // --force never deletes what is not a sweep's: a folder with a foreign file is refused.
  const fs::path mixed = dir.parent_path() / "mixed";
  fs::create_directories(mixed / "points");
  { std::ofstream(mixed / "notes.txt") << "mine"; }
  const auto foreign = runProcess(RTLAB_BINARY, with(kSweepArgs, {"--out", mixed.string(), "--force"}));
  EXPECT_EQ(foreign.exitCode, 6) << foreign.err;
  EXPECT_EQ(rtlab::test::lineCount(foreign.err), 1) << foreign.err;
  EXPECT_NE(foreign.err.find("notes.txt"), std::string::npos) << foreign.err;
  EXPECT_EQ(slurp(mixed / "notes.txt"), "mine");
  EXPECT_TRUE(fs::is_directory(mixed / "points"));

  // --force with one point, one job: the earlier three points are gone.
  const auto forced = runProcess(RTLAB_BINARY, {"sweep", "--scene", "contact", "--size", "32x32", "--spp", "16", "-t",
                                                "shadow_map", "--vary", "shadow.resolution=512", "--out", dir.string(),
                                                "--force"},
                                 120);
  ASSERT_EQ(forced.exitCode, 0) << forced.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "points" / "000" / "done.json"));
  EXPECT_FALSE(fs::exists(dir / "points" / "001")) << "stale point of the earlier sweep";
  EXPECT_FALSE(fs::exists(dir / "points" / "002")) << "stale point of the earlier sweep";
  EXPECT_EQ(lines(slurp(dir / "results.csv")).size(), 2u);
  const auto plan = nlohmann::json::parse(slurp(dir / "sweep.json"));
  EXPECT_EQ(plan["points"].size(), 1u);
  EXPECT_EQ(plan["jobs"], 1);
  // One job at a time: no warning about parallel timings.
  EXPECT_TRUE(plan["measured"]["warning"].is_null()) << plan["measured"];
  EXPECT_EQ(slurp(dir / "report.html").find("class=\"warning\""), std::string::npos);
}

TEST_F(Sweep, ReportInHeadlessChromium) {
  // Chromium is a test dependency (scripts/setup.sh --test-deps installs it): without it the
  // report is untested, so the test fails rather than skips.
  std::string why;
  ASSERT_TRUE(rtlab::test::chromiumAvailable(why)) << why;
  const fs::path shot = kRoot / "report.png"; // kept as the test's artifact
  fs::remove(shot);
  const auto r = rtlab::test::runChromium(s_direct / "report.html", s_direct.parent_path() / "chromium-profile", shot);
  ASSERT_FALSE(r.timedOut);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  for (const auto& line : rtlab::test::consoleMessages(r.err)) ADD_FAILURE() << "console message: " << line;
  ASSERT_TRUE(fs::is_regular_file(shot)) << r.err;
  rtlab::test::expectNotBlank(rtlab::readImage(shot.string()));
}

// ---- bad input: exit 2 or 3 before anything is rendered or written ----

struct BadSweep {
  std::vector<std::string> args;
  int exitCode;
  std::string mentions;
};

void PrintTo(const BadSweep& b, std::ostream* os) {
  for (const auto& a : b.args) *os << a << " ";
  *os << "-> " << b.exitCode;
}

class SweepBadInput : public ::testing::TestWithParam<BadSweep> {};

TEST_P(SweepBadInput, FailsEarlyWithOneLine) {
  const fs::path dir = testDir() / "out";
  std::vector<std::string> args = GetParam().args;
  for (auto& a : args)
    if (a == "DIR") a = dir.string();
  const auto r = runProcess(RTLAB_BINARY, args);
  EXPECT_EQ(r.exitCode, GetParam().exitCode) << r.err;
  EXPECT_EQ(rtlab::test::lineCount(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("rtlab: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(GetParam().mentions), std::string::npos) << r.err;
  if (GetParam().args.size() > 2 && GetParam().args[1] != "--collect") {
    EXPECT_FALSE(fs::exists(dir / "sweep.json"));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Sweep, SweepBadInput,
    ::testing::Values(
        BadSweep{{"sweep", "-t", "shadow_map", "--vary", "shadow.resolution=100,512", "--out", "DIR"}, 2, "[256, 4096]"},
        BadSweep{{"sweep", "-t", "shadow_map", "--vary", "shadow.resolution=256:8192:3", "--out", "DIR"}, 2, "shadow.resolution"},
        BadSweep{{"sweep", "-t", "shadow_map", "--vary", "shadow.resoltion=256", "--out", "DIR"}, 2, "did you mean"},
        BadSweep{{"sweep", "-t", "shadow_map", "--vary", "ao.radius=0.1,1", "--out", "DIR"}, 2, "ao.radius"},
        BadSweep{{"sweep", "-t", "shadow_map", "--vary", "shadow.depth_format=16:32f:2", "--out", "DIR"}, 2, "shadow.depth_format"},
        BadSweep{{"sweep", "-t", "shadow_map", "--vary", "shadow.resolution", "--out", "DIR"}, 2, "KEY="},
        BadSweep{{"sweep", "-t", "none", "--out", "DIR"}, 2, "none"},
        BadSweep{{"sweep", "-t", "nope", "--out", "DIR"}, 2, "nope"},
        BadSweep{{"sweep", "--vary", "shadow.resolution=256", "--out", "DIR"}, 2, "-t"},
        BadSweep{{"sweep", "-t", "shadow_map"}, 2, "--out"},
        BadSweep{{"sweep", "-t", "shadow_map", "--out", "DIR", "--jobs", "0"}, 2, "--jobs"},
        BadSweep{{"sweep", "-t", "shadow_map", "--out", "DIR", "--scene", "missing.gltf"}, 3, "missing.gltf"},
        BadSweep{{"sweep", "--collect", "DIR"}, 3, "sweep"},
        BadSweep{{"sweep", "--collect", "DIR", "-t", "shadow_map"}, 2, "--collect"},
        BadSweep{{"sweep", "--run-point", "DIR"}, 2, "--run-point"}));

TEST(SweepPlan, ReferenceDefiningKeysGetTheirOwnReferences) {
  const fs::path dir = testDir() / "plan";
  const fs::path jobs = dir.parent_path() / "jobs.txt";
  const auto r = runProcess(RTLAB_BINARY, {"sweep", "--size", "32x32", "-t", "shadow_map", "--vary",
                                           "light0.radius=0.05,0.1", "--vary", "shadow.resolution=256:1024:3",
                                           "--out", dir.string(), "--emit-jobs", jobs.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto plan = nlohmann::json::parse(slurp(dir / "sweep.json"));
  EXPECT_EQ(plan["points"].size(), 6u);
  ASSERT_EQ(plan["references"].size(), 2u) << "light0.radius defines the reference, shadow.resolution does not";
  EXPECT_EQ(plan["points"][0]["reference"], plan["points"][2]["reference"]);
  EXPECT_NE(plan["points"][0]["reference"], plan["points"][3]["reference"]);
  EXPECT_EQ(plan["vary"][1]["values"], nlohmann::json({"256", "512", "1024"})); // log scale
  EXPECT_EQ(lines(slurp(jobs)).size(), 8u);
  // A point index out of range is a usage error.
  const auto bad = runProcess(RTLAB_BINARY, {"sweep", "--run-point", dir.string(), "6"});
  EXPECT_EQ(bad.exitCode, 2) << bad.err;
}

// The reference's hash covers exactly the keys the stage's registered reference declares
// (docs/measuring.md "References per stage"): ao.radius for ao gives one reference per value; a
// technique key (pcf.samples, ssao.samples) shares one.
TEST(SweepPlan, OnlyTheReferencesDeclaredKeysSplitIt) {
  struct Case {
    std::vector<std::string> args;
    std::size_t points, references;
  };
  const std::vector<Case> cases = {
      {{"-t", "ssao", "--scene", "cornell", "--vary", "ao.radius=0.3,0.6"}, 2, 2},
      {{"-t", "ssao", "--scene", "cornell", "--vary", "ssao.samples=4,16"}, 2, 1},
      {{"-t", "pcf", "--vary", "pcf.samples=4,16,32"}, 3, 1},
      // bloom's reference does not sample: the sweep takes its spp (1) without --spp; it is
      // defined by bloom.sigma, not by how the technique approximates it (method, format).
      {{"-t", "bloom", "--vary", "bloom.sigma=1,2"}, 2, 2},
      {{"-t", "bloom", "--vary", "bloom.method=gaussian,mip", "--vary", "bloom.format=rgba16f,r11g11b10f"}, 4, 1},
  };
  for (const auto& c : cases) {
    const fs::path dir = testDir() / "declared";
    const fs::path jobs = dir.parent_path() / "declared-jobs.txt";
    std::vector<std::string> args = {"sweep", "--size", "32x32", "--out", dir.string(), "--emit-jobs", jobs.string()};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = runProcess(RTLAB_BINARY, args);
    ASSERT_EQ(r.exitCode, 0) << c.args.back() << ": " << r.err;
    const auto plan = nlohmann::json::parse(slurp(dir / "sweep.json"));
    EXPECT_EQ(plan["points"].size(), c.points) << c.args.back();
    EXPECT_EQ(plan["references"].size(), c.references) << c.args.back();
    if (c.args[1] == "bloom") {
      EXPECT_EQ(plan["spp"], 1);
    }
    fs::remove_all(dir);
  }
}

} // namespace
