// What every fuzz target shares (docs/testing.md "Fuzzing"): the input cap, a private scratch
// directory for the loaders that read files, and the oracle. A parser may reject any input with
// rtlab::Error, whose message must be one line (docs/contract.md); anything else escaping it (a
// standard exception, a crash, a sanitizer report, a leak) is a finding: the exception reaches
// std::terminate, which aborts, which libFuzzer and the replay executables report as a crash.
#pragma once
#include "util/error.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

// The entry point libFuzzer calls (and tests/fuzz/replay_main.cpp, for the corpus replay).
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
// Words the target's dictionary (tests/fuzz/dict/<target>.dict) must hold, from the code's own
// tables; a target without such a table does not define it (the replay's --dict check).
__attribute__((weak)) std::vector<std::string> rtlabFuzzDictionaryWords();

namespace rtlab::fuzz {

// Inputs above this size are skipped at once (1 MiB: every seed is below 100 KiB, and a larger
// input only makes each run slower without reaching new code).
inline constexpr std::size_t kMaxInputBytes = std::size_t(1) << 20;

inline std::string_view text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A directory of this process's own under $TMPDIR (or /tmp), created on first use and removed at
// exit: the only place the targets write.
inline const std::filesystem::path& scratchDir() {
  static const std::filesystem::path dir = [] {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/rtlab-fuzz-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) {
      std::perror("rtlab fuzz: mkdtemp");
      std::abort();
    }
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratchDir(), ec);
    });
    return std::filesystem::path(pattern);
  }();
  return dir;
}

// Writes the input to scratchDir()/name (replacing the previous input) and returns the path.
inline std::string writeScratch(const std::string& name, std::string_view bytes) {
  const std::string path = (scratchDir() / name).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  out.close();
  if (!out) {
    std::fprintf(stderr, "rtlab fuzz: cannot write the input to '%s'\n", path.c_str());
    std::abort();
  }
  return path;
}

// Runs `parse`; an rtlab::Error is a documented rejection, provided its message is one line and
// its code is not Internal (exit 1 is a bug, never the answer to an input).
template <typename F>
void expectOnlyErrors(F&& parse) {
  try {
    parse();
  } catch (const rtlab::Error& e) {
    const std::string_view message = e.what();
    if (message.empty() || message.find('\n') != std::string_view::npos) {
      std::fprintf(stderr, "rtlab fuzz: the error message is not one line: '%s'\n", e.what());
      std::abort();
    }
    if (e.code() == rtlab::ExitCode::Internal) {
      std::fprintf(stderr, "rtlab fuzz: internal error: %s\n", e.what());
      std::abort();
    }
    // RTLAB_FUZZ_VERBOSE=1: say why each input was rejected (is a seed valid?).
    static const bool verbose = std::getenv("RTLAB_FUZZ_VERBOSE") != nullptr;
    if (verbose) std::fprintf(stderr, "rejected: %s\n", e.what());
  }
}

} // namespace rtlab::fuzz
