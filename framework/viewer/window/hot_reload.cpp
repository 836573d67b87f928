#include "viewer/window/hot_reload.h"

#include "util/log.h"

namespace rtlab {

bool ShaderWatcher::poll(gl::ProgramCache& programs, std::vector<std::string>& errors) {
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - m_last).count() < kPollSeconds) return false;
  m_last = now;
  // A program that failed keeps its old file times, so it is retried (and reported) until its
  // files compile again.
  std::vector<std::string> failed = programs.reloadChanged();
  if (failed != errors) {
    for (const auto& e : failed)
      logWarn("shader reload: " + e);
    if (failed.empty() && !errors.empty()) logInfo("shader reload: every program compiles again");
  }
  errors = std::move(failed);
  return true;
}

} // namespace rtlab
