// Fuzz target: viewer scripts (viewer/script.h): parsed, then checked against a frame as
// `rtlab view --script` does before the window opens.
//
// validateScript reads the files "load_preset" names and checks that output paths are writable
// (it writes nothing). It runs only on scripts whose "file" and "dir" fields are relative paths
// without "..": a fuzzed absolute path could name a FIFO or a device (/dev/stdin) and block.
#include "viewer/script.h"

#include "fuzz_frame.h"
#include "fuzz_target.h"

namespace {

bool namesOnlyLocalFiles(const std::vector<rtlab::ScriptAction>& script) {
  for (const auto& action : script)
    for (const char* field : {"file", "dir"}) {
      const auto it = action.args.find(field);
      if (it == action.args.end()) continue;
      if (!it->is_string()) return false;
      const std::string path = it->get<std::string>();
      if (path.empty() || path[0] == '/' || path.find("..") != std::string::npos) return false;
    }
  return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rtlab;
  if (size > fuzz::kMaxInputBytes) return -1;
  fuzz::expectOnlyErrors([&] {
    const auto script = parseScript(std::string(fuzz::text(data, size)), "demo.json");
    validateScriptBookmarks(script, 2);
    if (namesOnlyLocalFiles(script)) validateScript(script, fuzz::params(), fuzz::registry());
  });
  return 0;
}

std::vector<std::string> rtlabFuzzDictionaryWords() {
  std::vector<std::string> words = {"action"};
  for (const auto& name : rtlab::scriptActionNames()) words.push_back(name);
  return words;
}
