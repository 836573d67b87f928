// rtlab view: the lecture viewer (docs/viewer.md). Everything the command line names is checked
// before the window opens — the frame options, the --script actions and the --bookmarks file —
// so a bad input exits 2/3 with one line and never half-runs; the window itself needs a display
// (exit 4 otherwise, suggesting xvfb-run or rtlab render).
#include "app/exercise_option.h"
#include "app/commands.h"
#include "app/frame_options.h"
#include "frame/registry.h"
#include "image/image.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "viewer/window/viewer_app.h"

#include <cstdlib>
#include <iostream>

namespace rtlab {
namespace {

bool hasDisplay() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY"})
    if (const char* v = std::getenv(name); v && *v) return true;
  return false;
}

} // namespace

int runView(int argc, char** argv) {
  auto specs = frameOptionSpecs();
  specs.push_back(
      {"--screenshot", "", true, "FILE", "after --frames N frames, save the window (UI included) as PNG and exit"});
  specs.push_back(exerciseOptionSpec());
  specs.push_back({"--script", "", true, "FILE", "run a JSON list of actions (docs/viewer-scripts.md)"});
  specs.push_back(
      {"--bookmarks", "", true, "FILE", "lecture bookmarks, stepped with the arrow keys (docs/viewer-scripts.md)"});
  specs.push_back({"--export-notes", "", true, "FILE",
                   "write the --bookmarks file's speaker notes as Markdown and exit (no window)"});
  Args args("view", specs, argc, argv, 2);
  if (args.help()) {
    std::cout << formatHelp("rtlab view [scene and frame options] [--frames N --screenshot FILE] [--script FILE] "
                            "[--bookmarks FILE [--export-notes OUT.md]]",
                            "The lecture viewer (needs a display; docs/viewer.md). Esc or closing the window quits.\n"
                            "--size is the window's initial size; --backend applies to headless commands only.",
                            specs);
    return 0;
  }
  ViewerOptions options;
  options.frame = resolveFrame(args);
  options.exercise = applyExerciseOption(args, options.frame);
  const TechniqueRegistry& registry = TechniqueRegistry::instance();
  options.screenshot = args.get("--screenshot");
  if (!options.screenshot.empty()) {
    requirePngPath(options.screenshot, "--screenshot");
    checkOutputPath(options.screenshot);
  }
  options.bookmarksSource = args.get("--bookmarks");
  if (!options.bookmarksSource.empty()) {
    options.bookmarks = loadBookmarks(options.bookmarksSource);
    validateBookmarks(options.bookmarks, options.frame.params, registry, options.bookmarksSource,
                      options.frame.options.sceneSpec);
  }
  if (args.has("--export-notes")) {
    const std::string out = args.get("--export-notes");
    if (options.bookmarksSource.empty()) usageError("--export-notes needs --bookmarks FILE (the notes' source)");
    checkOutputPath(out);
    writeTextAtomically(out, bookmarkNotesMarkdown(options.bookmarks, options.bookmarksSource));
    return 0;
  }
  if (args.has("--script")) {
    options.script = loadScript(args.get("--script"));
    validateScript(*options.script, options.frame.params, registry);
    validateScriptBookmarks(*options.script, options.bookmarks.size());
  }
  saveRequestedPreset(options.frame);
  if (!hasDisplay())
    throw Error(ExitCode::NoContext, "rtlab view needs a display (DISPLAY or WAYLAND_DISPLAY is unset): run it under "
                                     "'xvfb-run -a rtlab view ...', or render headless with 'rtlab render'");
  return runViewer(std::move(options));
}

} // namespace rtlab
