// Fuzz target: the command-line parser (app/args.h) with the frame options' table
// (app/frame_option_specs.h), and the GL-free value parsers `rtlab render` applies to what it
// returns: --size, --frames, --seed, -t (technique lists) and --set (KEY=VALUE on a scene's
// parameters). The input is the argument list, arguments separated by NUL bytes.
#include "app/args.h"
#include "app/frame_option_specs.h"
#include "frame/selection.h"

#include "fuzz_frame.h"
#include "fuzz_target.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rtlab;
  if (size > fuzz::kMaxInputBytes) return -1;
  // argv[0] is the command, as rtlab's commands see it (they parse from index 2 of the real argv).
  std::vector<std::string> words = {"rtlab", "render"};
  const std::string_view input = fuzz::text(data, size);
  for (std::size_t begin = 0; begin <= input.size();) {
    const std::size_t end = std::min(input.find('\0', begin), input.size());
    words.emplace_back(input.substr(begin, end - begin));
    begin = end + 1;
  }
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  fuzz::expectOnlyErrors([&] {
    const auto specs = frameOptionSpecs();
    const Args args("render", specs, int(words.size()), argv.data(), 2, /*maxPositionals=*/1);
    if (args.help() && formatHelp("rtlab render [options]", "Renders.", specs).empty()) std::abort();
    int width = 0, height = 0;
    if (args.has("--size")) parseSize(args.get("--size"), width, height);
    if (args.has("--frames")) parseIntOption("--frames", args.get("--frames"), 1, 100000);
    if (args.has("--seed")) parseIntOption("--seed", args.get("--seed"), 0, 4294967295LL);
    TechniqueSelection selection(fuzz::registry());
    ParamSet params = fuzz::params();
    for (const auto& [name, value] : args.ordered()) {
      if (name == "--technique") selection.activateList(value);
      if (name == "--set") params.setAssignment(value);
    }
  });
  return 0;
}

// Every option name and alias of the table, and the help options.
std::vector<std::string> rtlabFuzzDictionaryWords() {
  std::vector<std::string> words = {"--help", "-h"};
  for (const auto& spec : rtlab::frameOptionSpecs()) {
    words.push_back(spec.name);
    if (!spec.alias.empty()) words.push_back(spec.alias);
  }
  return words;
}
