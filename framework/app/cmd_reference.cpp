// rtlab reference: the ground truth of one data AOV (visibility, ao, indirect) for a frame,
// computed on the CPU with Embree from the frame's own G-buffer (docs/measuring.md).
#include "app/commands.h"
#include "app/frame_options.h"
#include "app/reference_run.h"
#include "frame/aovs.h"
#include "frame/registry.h"
#include "image/image.h"
#include "reference/reference.h"
#include "render/renderer.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/log.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace rtlab {
namespace {

std::vector<OptionSpec> referenceOptions() {
  auto specs = frameOptionSpecs();
  specs.push_back({"--aov", "", true, "NAME", "required: visibility (light 0), ao or indirect"});
  specs.push_back({"--spp", "", true, "N", "samples per pixel, 1..65536 (default 64)"});
  specs.push_back({"--out", "", true, "FILE", "output image .exr/.pfm/.png (default <scene>_<aov>_ref.exr)"});
  return specs;
}

} // namespace

int runReference(int argc, char** argv) {
  const auto specs = referenceOptions();
  Args args("reference", specs, argc, argv, 2);
  if (args.help()) {
    std::cout << formatHelp("rtlab reference [scene and frame options] --aov visibility|ao|indirect [--spp N] [--out FILE]",
                            "Computes the ground truth of a data AOV on the CPU (Embree ray casting) from the frame's "
                            "own surface points. --frames is accepted and ignored.",
                            specs);
    return 0;
  }
  if (!args.has("--aov")) usageError("reference needs --aov visibility|ao|indirect");
  const std::string aov = args.get("--aov");
  if (!isReferenceAov(aov)) usageError("unknown reference AOV '" + aov + "' (choices: visibility, ao, indirect)");
  const int spp = args.has("--spp") ? int(parseIntOption("--spp", args.get("--spp"), kReferenceMinSpp, kReferenceMaxSpp)) : 64;
  ResolvedFrame frame = resolveFrame(args);
  const std::string out = args.get("--out", frame.scene.name + "_" + aov + "_ref.exr");
  checkImageOutputPath(out); // before any work: a directory (6), an unknown extension (2)
  if (!frame.options.savePreset.empty()) checkOutputPath(frame.options.savePreset);

  auto context = createHeadlessContext(frame.options.backend);
  Renderer renderer(TechniqueRegistry::instance());
  renderer.setScene(frame.scene);
  ReferenceStats stats;
  const Image image = renderReferenceFrame(renderer, frame, aov, spp, ::isatty(STDERR_FILENO) == 1, stats);
  char line[160];
  std::snprintf(line, sizeof(line), "reference %s: %dx%d, %d spp, %.3g M rays in %.2f s (%.3g M rays/s)", aov.c_str(),
                image.width, image.height, spp, double(stats.rays) * 1e-6, stats.seconds,
                stats.seconds > 0.0 ? double(stats.rays) * 1e-6 / stats.seconds : 0.0);
  logInfo(line);
  writeImage(out, image, pngEncodingForAov(aov));
  saveRequestedPreset(frame);
  return 0;
}

} // namespace rtlab
