// rtlab render: one frame (or --frames N measured frames) headless, one AOV to an image, stats.
#include "app/aov_preview.h"
#include "app/commands.h"
#include "app/exercise_option.h"
#include "app/frame_options.h"
#include "app/measure.h"
#include "app/run_info.h"
#include "frame/aovs.h"
#include "frame/registry.h"
#include "image/image.h"
#include "render/renderer.h"
#include "util/atomic_file.h"
#include "util/error.h"

#include <cstdio>
#include <iostream>

namespace rtlab {
namespace {

std::vector<OptionSpec> renderOptions() {
  auto specs = frameOptionSpecs();
  specs.push_back({"--aov", "", true, "NAME", "output: color (default), visibility, ao, indirect, depth, normal, albedo, or a debug view"});
  specs.push_back({"--out", "", true, "FILE", "output image .png/.exr/.pfm (default <scene>_<aov>.png)"});
  specs.push_back({"--stats", "", true, "FILE.json", "write timings, resources and resolved parameters"});
  specs.push_back({"--range", "", true, "LO:HI", "PNG preview of a data/debug AOV: map LO..HI to black..white ('auto': the data's range)"});
  specs.push_back(exerciseOptionSpec());
  specs.push_back({"--false-color", "", false, "", "PNG preview of a one-channel AOV through the magma colour map"});
  return specs;
}

} // namespace

int runRender(int argc, char** argv) {
  const auto specs = renderOptions();
  Args args("render", specs, argc, argv, 2);
  if (args.help()) {
    std::cout << formatHelp("rtlab render [scene and frame options] [--aov NAME] [--out FILE] [--stats FILE.json]\n"
                            "                    [--range LO:HI|auto] [--false-color]",
                            "Renders the scene headless with the active techniques and writes one AOV. EXR and PFM\n"
                            "hold the raw data; a PNG of a data or debug AOV is a preview (docs/cli.md).", specs);
    return 0;
  }
  ResolvedFrame frame = resolveFrame(args);
  applyExerciseOption(args, frame);
  const std::string aov = args.get("--aov", "color");
  const TechniqueRegistry& registry = TechniqueRegistry::instance();
  checkAovName(aov, frame.techniques, registry);
  const std::string out = args.get("--out", frame.scene.name + "_" + aov + ".png");
  const ImageFormat format = checkImageOutputPath(out);
  const AovPreviewRequest preview = parseAovPreview(args, aov, format, registry);
  const std::string statsPath = args.get("--stats");
  if (args.has("--stats") && statsPath.empty()) usageError("--stats needs a file name");
  if (!statsPath.empty()) checkOutputPath(statsPath);
  if (!frame.options.savePreset.empty()) checkOutputPath(frame.options.savePreset);

  auto context = createHeadlessContext(frame.options.backend);
  const TimingMethod timing = resolveTiming(frame.options.timing, context->info().software);
  Renderer renderer(registry);
  renderer.setScene(frame.scene);
  const bool display = aov == "color" && format == ImageFormat::Png;
  FrameOutputs outputs;
  if (!display) outputs.aovs = {aov};
  outputs.displayColor = display;
  const FrameStats stats = renderMeasured(renderer, frame, outputs, timing, !statsPath.empty(), !statsPath.empty());

  Image image = display ? renderer.readDisplayColor() : renderer.readAov(aov);
  writeAovImage(out, image, aov, preview);
  if (!statsPath.empty()) writeTextAtomically(statsPath, statsJson(frame, *context, timing, stats).dump(2) + "\n");
  saveRequestedPreset(frame);
  return 0;
}

} // namespace rtlab
