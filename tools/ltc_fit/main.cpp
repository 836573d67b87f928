// rtlab_ltc_fit: fits the LTC tables of the frame's GGX lobe (assets/ltc/README.md) and writes them
// with LtcTable::save. Every failure is one line "rtlab: error: ..." on stderr and the exit code of
// docs/contract.md (2 usage, 6 output, 1 internal).
#include "error_map.h"
#include "ltc_fit.h"

#include "app/args.h"
#include "image/image.h"
#include "reference/progress.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/interrupt.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <thread>

namespace {

// Pixels per table cell in the error map (64 x 64 cells: 512 x 512).
constexpr int kErrorMapScale = 8;

const std::vector<rtlab::OptionSpec> kOptions = {
    {"--size", "", true, "N", "table size N x N, 2..1024 (default 64)"},
    {"--samples", "", true, "S", "per-cell samples of each MIS strategy, 16..1048576 (default 1024)"},
    {"--seed", "", true, "N", "seed of every sample set, 0..2^63-1 (default 1)"},
    {"--threads", "", true, "T", "worker threads, 1..256 (default: the CPU count); the table does not depend on it"},
    {"--out", "", true, "FILE", "the table to write (default ggx.json)"},
    {"--error-map", "", true, "FILE", "also write the fit error's heat map (PNG; assets/ltc/README.md)"},
    {"--error-max", "", true, "E", "the error at the top of the heat map's scale, > 0 (default 0.5)"},
    {"--table", "", true, "FILE", "read this table instead of fitting one (with --error-map only)"},
    {"--quiet", "-q", false, "", "no progress bar"},
};

int run(int argc, char** argv) {
  using namespace rtlab;
  const Args args("", kOptions, argc, argv, 1, 0, "rtlab_ltc_fit");
  if (args.help()) {
    std::fputs(formatHelp("rtlab_ltc_fit [options]",
                          "Fits the linearly transformed cosines of the frame's GGX specular lobe (D V cos, height-correlated\n"
                          "Smith, no Fresnel) and writes the LTC table (assets/ltc/README.md).",
                          kOptions)
                   .c_str(),
               stdout);
    return 0;
  }
  const std::string errorMap = args.get("--error-map");
  const float errorMax = float(parsePositiveNumber("--error-max", args.get("--error-max", "0.5")));
  if (args.has("--error-map")) {
    requirePngPath(errorMap, "--error-map");
    checkOutputPath(errorMap);
  }
  if (args.has("--table")) {
    for (const char* option : {"--size", "--samples", "--seed", "--threads", "--out"})
      if (args.has(option)) usageError(std::string(option) + " cannot be combined with --table (which reads a fitted table)");
    if (!args.has("--error-map")) usageError("--table needs --error-map (there is nothing else to do with a fitted table)");
    const LtcTable table = LtcTable::load(args.get("--table"));
    writeImage(errorMap, ltcfit::ltcErrorMap(table, errorMax, kErrorMapScale));
    return 0;
  }
  ltcfit::FitOptions options;
  options.size = int(parseIntOption("--size", args.get("--size", "64"), 2, 1024));
  options.samples = int(parseIntOption("--samples", args.get("--samples", "1024"), 16, 1 << 20));
  options.seed = std::uint64_t(parseIntOption("--seed", args.get("--seed", "1"), 0, 0x7fffffffffffffffll));
  const unsigned cpus = std::max(1u, std::thread::hardware_concurrency());
  options.threads = int(parseIntOption("--threads", args.get("--threads", std::to_string(cpus)), 1, 256));
  const std::string out = args.get("--out", "ggx.json");
  checkOutputPath(out);

  const auto start = std::chrono::steady_clock::now();
  LtcTable table;
  {
    reference::ProgressBar bar("ltc fit", std::uint64_t(options.size) * std::uint64_t(options.size),
                               !args.has("--quiet") && ::isatty(2));
    table = ltcfit::fitTable(options, [&](int cells) { bar.advance(std::uint64_t(cells)); });
  }
  table.fitSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  table.save(out);
  if (args.has("--error-map")) writeImage(errorMap, ltcfit::ltcErrorMap(table, errorMax, kErrorMapScale));
  std::fprintf(stderr, "ltc fit: %dx%d, %d samples, seed %llu, %d threads: %.1f s -> %s\n", options.size, options.size,
               options.samples, (unsigned long long)options.seed, options.threads, table.fitSeconds, out.c_str());
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  rtlab::installInterruptHandler();
  try {
    return run(argc, argv);
  } catch (const rtlab::Error& e) {
    std::fprintf(stderr, "rtlab: error: %s\n", e.what());
    return int(e.code());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rtlab: error: internal: %s\n", e.what());
    return int(rtlab::ExitCode::Internal);
  }
}
