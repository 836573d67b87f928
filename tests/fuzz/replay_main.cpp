// The corpus replay (docs/testing.md "Fuzzing"): a fuzz target compiled with the normal compiler
// and this main instead of libFuzzer's. It runs the target once on every file of the given
// directories (recursively, in name order; dot files skipped) and, with `--dict FILE`, first
// checks that the dictionary holds every word of the target's own tables. A crash, a sanitizer
// report or an abort from the target's oracle fails the test; so does a missing directory or
// finding no input at all.
#include "fuzz_target.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "replay: cannot read '%s'\n", path.c_str());
    std::exit(2);
  }
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Each word must appear in the dictionary as a quoted entry, bare ("--size") or as a JSON string
// ("\"action\"").
bool checkDictionary(const fs::path& dict) {
  if (!rtlabFuzzDictionaryWords) {
    std::fprintf(stderr, "replay: --dict given, but this target has no word table\n");
    return false;
  }
  const std::string text = readAll(dict);
  bool ok = true;
  for (const auto& word : rtlabFuzzDictionaryWords())
    if (text.find("\"" + word + "\"") == std::string::npos && text.find("\"\\\"" + word + "\\\"\"") == std::string::npos) {
      std::fprintf(stderr, "replay: dictionary '%s' lacks \"%s\" (add it)\n", dict.c_str(), word.c_str());
      ok = false;
    }
  return ok;
}

} // namespace

int main(int argc, char** argv) {
  std::vector<fs::path> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--dict" && i + 1 < argc) {
      if (!checkDictionary(argv[++i])) return 1;
      continue;
    }
    std::error_code ec;
    if (!fs::is_directory(arg, ec)) {
      std::fprintf(stderr, "replay: '%s' is not a directory\nUsage: %s [--dict FILE] DIR...\n", arg.c_str(), argv[0]);
      return 2;
    }
    for (const auto& entry : fs::recursive_directory_iterator(arg))
      if (entry.is_regular_file() && entry.path().filename().string()[0] != '.') inputs.push_back(entry.path());
  }
  if (inputs.empty()) {
    std::fprintf(stderr, "replay: no inputs\n");
    return 2;
  }
  std::sort(inputs.begin(), inputs.end());
  for (const auto& path : inputs) {
    const std::string bytes = readAll(path);
    // The path first, so that the log of a crash names the input.
    std::fprintf(stderr, "replay: %s\n", path.c_str());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("replay: %zu inputs, no failure\n", inputs.size());
  return 0;
}
