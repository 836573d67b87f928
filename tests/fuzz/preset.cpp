// Fuzz target: preset files (params/preset.h) loaded from the scratch directory, their techniques
// activated and their parameters applied to a scene's parameter set, as `--preset` does.
#include "frame/selection.h"
#include "params/preset.h"

#include "fuzz_frame.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rtlab;
  if (size > fuzz::kMaxInputBytes) return -1;
  const std::string path = fuzz::writeScratch("preset.json", fuzz::text(data, size));
  fuzz::expectOnlyErrors([&] {
    const Preset preset = loadPreset(path);
    TechniqueSelection selection(fuzz::registry());
    if (preset.techniques)
      for (const auto& id : *preset.techniques) selection.activate(id);
    ParamSet params = fuzz::params();
    applyPreset(preset, params, path);
  });
  return 0;
}
