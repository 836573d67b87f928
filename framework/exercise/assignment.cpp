#include "exercise/assignment.h"

#include "exercise/regions.h"
#include "util/atomic_file.h"
#include "util/number_format.h"
#include "util/paths.h"

#include <filesystem>
#include <sstream>

namespace rtlab {
namespace fs = std::filesystem;
namespace {

std::string range(const ParamSpec& p) {
  if (p.type == ParamType::Bool) return "true / false";
  if (p.type == ParamType::Enum) {
    std::string s;
    for (const auto& c : p.choices) s += (s.empty() ? "" : ", ") + c;
    return s;
  }
  return formatParamValue(p, ParamValue::scalar(p.min)) + " .. " + formatParamValue(p, ParamValue::scalar(p.max));
}

// Markdown paragraph wrapped at 100 columns, for reading in a terminal.
std::string wrapped(const std::string& paragraph) {
  std::istringstream words(paragraph);
  std::string word, out, line;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > 100) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

std::string viewCommand(const ExerciseDef& def, const ExerciseView& v, const char* command) {
  std::ostringstream s;
  s << "rtlab " << command << " --exercise . --scene " << v.scene;
  // --exercise activates the exercise's technique; other techniques are named.
  if (!v.techniques.empty() && v.techniques != std::vector<std::string>{def.technique})
    for (const auto& t : v.techniques) s << " -t " << t;
  for (const auto& [key, value] : v.set) s << " --set " << key << "=" << value;
  return s.str();
}

} // namespace

std::string assignmentMarkdown(const ExerciseDef& def, const std::vector<ParamSpec>& params) {
  std::ostringstream md;
  md << "# Exercise `" << def.id << "`: " << def.title << "\n\n";
  md << "Technique: `" << def.technique << "`. This folder holds your copy of the files below; rtlab runs them\n"
        "in place of its own when you pass `--exercise` with this folder.\n\n";
  for (const auto& p : def.background) md << (p.find('\n') == std::string::npos ? wrapped(p) : p) << "\n\n";

  md << "## What to implement\n\n";
  md << "Each part is a region between `// exercise(NAME): begin` and `// exercise: end`. It holds a stub that\n"
        "compiles and returns a neutral value, so everything runs from the start; replace the stub with your\n"
        "code. Leave the rest of the files as they are.\n\n";
  for (const auto& file : def.files) {
    const std::string text = readFileOrThrow((fs::path(dataDir()) / file).string(), "shader");
    const std::string student = studentCopy(text, file, {def.regions.begin(), def.regions.end()});
    for (const auto& region : parseExerciseRegions(student, file, true)) {
      bool ours = false;
      for (const auto& r : def.regions) ours = ours || r == region.name;
      if (!ours) continue;
      md << "### `" << region.name << "` in `" << file << "` (line " << region.beginLine << ")\n\n";
      for (const auto& line : region.task) md << line << "\n";
      md << "\n";
    }
  }

  if (!params.empty()) {
    md << "## Parameters\n\n| key | default | range | meaning |\n|---|---|---|---|\n";
    for (const auto& p : params)
      md << "| `" << p.key << "` | " << formatParamValue(p, p.def) << " | " << range(p) << " | " << p.help << " |\n";
    md << "\nSet them with `--set KEY=VALUE` on `rtlab render` and `rtlab view`, or with the sliders in the viewer.\n\n";
  }

  md << "## Run and view your version\n\n";
  md << "From this folder (so that `--exercise .` names it):\n\n```\n";
  md << "rtlab view --exercise .                     # live, with hot reload: save a file and the frame updates\n";
  md << "rtlab render --exercise . --aov " << def.aov << " --out mine.png\n";
  md << "rtlab render --aov " << def.aov << " -t " << def.technique << " --out solution.png   # rtlab's own version\n";
  md << "rtlab exercise grade . --report report      # grade yourself; open report/index.html\n```\n\n";
  md << "With `--exercise` and no `-t`, the technique `" << def.technique << "` is active. A compile error names\n"
        "your file and line; the viewer keeps the last version that compiled and shows the error.\n\n";

  md << "## How it is graded\n\n";
  int hidden = 0;
  for (const auto& v : def.views) hidden += v.hidden ? 1 : 0;
  std::ostringstream grading;
  grading << "`rtlab exercise grade` renders the `" << def.aov << "` AOV of " << def.views.size()
          << " views with your files and with rtlab's solution on the same machine, and compares them. A pixel differs "
             "when your value and the solution's differ by more than "
          << formatNumber(def.tolerance.pixel) << "; a view passes when at most " << formatNumber(def.tolerance.fraction * 100.0)
          << "% of its pixels (with geometry) differ and the other pixels are within an RMSE of "
          << formatNumber(def.tolerance.rmse) << " (no small error everywhere). Your score is the percentage of views "
             "that pass. Each view also reports your error against the ground-truth reference next to the solution's. "
             "A view that runs longer than "
          << formatNumber(def.timeLimitSeconds) << " s fails (`timeout`).";
  md << wrapped(grading.str()) << "\n\n";
  md << "The views you can see (" << hidden << (hidden == 1 ? " more is" : " more are")
     << " hidden, with other settings):\n\n";
  md << "| view | what it tests | command |\n|---|---|---|\n";
  for (const auto& v : def.views)
    if (!v.hidden)
      md << "| `" << v.name << "` | " << (v.note.empty() ? "-" : v.note) << " | `" << viewCommand(def, v, "render")
         << " --size " << v.width << "x" << v.height << " --aov " << def.aov << "` |\n";
  md << "\n";
  return md.str();
}

} // namespace rtlab
