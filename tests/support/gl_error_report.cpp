#include "gl_error_report.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace rtlab::test {
namespace {
std::atomic<std::int64_t> g_deliberate{0};
std::atomic<std::int64_t> g_children{0};
} // namespace

void addDeliberateGlErrors(std::int64_t count) { g_deliberate += count; }
std::int64_t deliberateGlErrors() { return g_deliberate.load(); }
void addChildGlErrors(std::int64_t count) { g_children += count; }
std::int64_t childGlErrors() { return g_children.load(); }

std::int64_t parseGlErrorReport(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::int64_t sum = -1;
  const std::string key = "gl_errors: ";
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) != 0) continue;
    sum = std::max<std::int64_t>(sum, 0) + std::strtoll(line.c_str() + key.size(), nullptr, 10);
  }
  return sum;
}

bool writeTestBinaryGlErrorReport(const std::string& binary, std::int64_t ownErrors,
                                  const std::vector<std::string>& messages) {
  const std::int64_t total = ownErrors + childGlErrors();
  std::printf("GL errors in %s: %lld (%lld made on purpose and checked)\n", binary.c_str(),
              static_cast<long long>(total), static_cast<long long>(deliberateGlErrors()));
  std::fflush(stdout);
  const std::string pid = std::to_string(::getpid());
  std::string report = "gl_errors: " + std::to_string(total) + " " + binary + " (pid " + pid + ")\n";
  for (const std::string& m : messages) report += "  " + m + "\n";
  // A test binary run by another test's runProcess reports to that test, not to the suite's folder.
  std::string path;
  std::ios::openmode mode = std::ios::out;
  if (const char* file = std::getenv("RTLAB_GL_ERRORS_FILE"); file && *file) {
    path = file;
    mode |= std::ios::app;
  } else if (const char* dir = std::getenv("RTLAB_TEST_GL_ERRORS_DIR"); dir && *dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    path = std::string(dir) + "/" + binary + "-" + pid + ".txt";
  } else {
    return true;
  }
  std::ofstream out(path, mode);
  out << report;
  out.close();
  if (!out) std::fprintf(stderr, "could not write the GL error report %s\n", path.c_str());
  return static_cast<bool>(out);
}

} // namespace rtlab::test
