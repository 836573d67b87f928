// Hot reload of shaders (docs/viewer.md "Hot reload"): a few times a second the viewer asks the program
// cache to rebuild every program whose files (the stage files and everything they #include)
// changed on disk. A rebuild that fails keeps the last good program running and its file:line
// messages are shown in the UI and reported (shader_errors) until a later save compiles.
#pragma once
#include "gl/program_cache.h"

#include <chrono>
#include <string>
#include <vector>

namespace rtlab {

class ShaderWatcher {
public:
  static constexpr double kPollSeconds = 0.25;
  // Polls when kPollSeconds have passed since the last poll. Returns true if it polled; then
  // `errors` holds the messages of the programs that failed to rebuild (empty: all good).
  bool poll(gl::ProgramCache& programs, std::vector<std::string>& errors);

private:
  std::chrono::steady_clock::time_point m_last = std::chrono::steady_clock::now();
};

} // namespace rtlab
