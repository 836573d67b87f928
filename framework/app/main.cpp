// rtlab: the command-line entry point. Every failure is one line on stderr beginning
// "rtlab: error:" and a documented exit code (docs/contract.md "Exit codes").
#include "app/commands.h"
#include "gl/debug.h"
#include "util/interrupt.h"
#include "util/error.h"
#include "util/version.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

namespace {

const char* kUsage =
    "Usage: rtlab <command> [options]\n\n"
    "An OpenGL 4.5 teaching sandbox for real-time rendering techniques.\n\n"
    "Commands:\n"
    "  list       stages, techniques, parameters, scenes and AOVs (--json for scripts)\n"
    "  render     render headless to an image, with --stats timings\n"
    "  reference  ground truth on the CPU (Embree) for visibility, ao or indirect\n"
    "  view       show the frame in a window\n"
    "  showcase   render every scene and technique, with stats, into a folder with index.html\n"
    "  compare    error metrics of image B against image A (RMSE, PSNR, SSIM, FLIP)\n"
    "  sweep      error against time over parameter grids, to results.csv and report.html\n"
    "  exercise   course exercises: list, new (a student's folder), grade (against the solution)\n"
    "  --version  version and git commit\n\n"
    "'rtlab <command> --help' describes a command's options.\n";

std::string g_glErrorsFile; // RTLAB_GL_ERRORS_FILE
std::string g_glErrorsWho;  // "rtlab <command> (pid N)"

void reportGlErrors() {
  if (!rtlab::appendGlErrorReport(g_glErrorsFile, g_glErrorsWho))
    std::fprintf(stderr, "rtlab: warning: could not append the GL error report to %s\n", g_glErrorsFile.c_str());
}

// RTLAB_GL_ERRORS_FILE=PATH: the process appends its GL error total to PATH when it exits
// (docs/contract.md "GL error report"; the CLI tests use it, docs/testing.md "GL errors").
void reportGlErrorsAtExit(int argc, char** argv) {
  const char* path = std::getenv("RTLAB_GL_ERRORS_FILE");
  if (!path || !*path) return;
  g_glErrorsFile = path;
  g_glErrorsWho = std::string("rtlab ") + (argc > 1 ? argv[1] : "") + " (pid " + std::to_string(::getpid()) + ")";
  std::atexit(reportGlErrors);
}

} // namespace

int main(int argc, char** argv) {
  rtlab::installInterruptHandler();
  reportGlErrorsAtExit(argc, argv);
  using namespace rtlab;
  try {
    if (argc < 2) {
      std::fputs(kUsage, stderr);
      return int(ExitCode::Usage);
    }
    const std::string command = argv[1];
    if (command == "--version" || command == "version") {
      std::printf("rtlab %s (commit %s)\n", versionString(), gitCommit());
      return 0;
    }
    if (command == "--help" || command == "-h" || command == "help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (command == "list") return runList(argc, argv);
    if (command == "render") return runRender(argc, argv);
    if (command == "reference") return runReference(argc, argv);
    if (command == "view") return runView(argc, argv);
    if (command == "showcase") return runShowcase(argc, argv);
    if (command == "compare") return runCompare(argc, argv);
    if (command == "sweep") return runSweep(argc, argv);
    if (command == "exercise") return runExercise(argc, argv);
    usageError("unknown command '" + command + "' (commands: list, render, reference, view, showcase, compare, sweep, exercise; see 'rtlab --help')");
  } catch (const Error& e) {
    std::fprintf(stderr, "rtlab: error: %s\n", e.what());
    return int(e.code());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "rtlab: error: out of memory\n");
    return int(ExitCode::Internal);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rtlab: error: internal: %s\n", e.what());
    return int(ExitCode::Internal);
  }
}
