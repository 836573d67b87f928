// rtlab reference: the ground truth of one stage for a frame, by the stage's registered reference
// (reference/reference_registry.h; docs/measuring.md "References per stage").
#include "app/commands.h"
#include "app/frame_options.h"
#include "app/reference_run.h"
#include "frame/aovs.h"
#include "frame/registry.h"
#include "image/image.h"
#include "reference/reference_registry.h"
#include "render/renderer.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/log.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace rtlab {
namespace {

// "visibility (light 0's visibility from each surface point), ao (...), ..." from the registry.
std::string aovHelp(const ReferenceRegistry& references) {
  std::string s;
  for (const auto& e : references.entries()) s += (s.empty() ? "" : "; ") + e.aov + ": " + e.help;
  return s;
}

// The sample range of the references that sample (all of them share it today).
std::string sppHelp(const ReferenceRegistry& references) {
  std::string s;
  for (const auto& e : references.entries()) {
    if (!e.samples()) continue;
    const std::string range = std::to_string(e.minSpp) + ".." + std::to_string(e.maxSpp) + " (default " +
                              std::to_string(e.defaultSpp) + ")";
    if (s.find(range) == std::string::npos) s += (s.empty() ? "" : "; ") + range;
  }
  return "samples per pixel, " + s;
}

std::vector<OptionSpec> referenceOptions(const ReferenceRegistry& references) {
  auto specs = frameOptionSpecs();
  specs.push_back({"--aov", "", true, "NAME", "required: " + aovHelp(references)});
  specs.push_back({"--spp", "", true, "N", sppHelp(references)});
  specs.push_back({"--out", "", true, "FILE", "output image .exr/.pfm/.png (default <scene>_<aov>_ref.exr)"});
  return specs;
}

} // namespace

int runReference(int argc, char** argv) {
  const ReferenceRegistry& references = ReferenceRegistry::instance();
  const auto specs = referenceOptions(references);
  Args args("reference", specs, argc, argv, 2);
  const std::string choices = references.choices("|");
  if (args.help()) {
    std::cout << formatHelp("rtlab reference [scene and frame options] --aov " + choices + " [--spp N] [--out FILE]",
                            "Computes the ground truth of a stage on the CPU from what the frame reads back "
                            "(docs/measuring.md \"References per stage\"). --frames is accepted and ignored.",
                            specs);
    return 0;
  }
  if (!args.has("--aov")) usageError("reference needs --aov " + choices);
  const std::string aov = args.get("--aov");
  const ReferenceEntry& reference = references.get(aov); // exit 2 naming the choices
  const int spp = args.has("--spp") ? int(parseIntOption("--spp", args.get("--spp"), reference.minSpp, reference.maxSpp))
                                    : reference.defaultSpp;
  ResolvedFrame frame = resolveFrame(args);
  const std::string out = args.get("--out", frame.scene.name + "_" + aov + "_ref.exr");
  checkImageOutputPath(out); // before any work: a directory (6), an unknown extension (2)
  if (!frame.options.savePreset.empty()) checkOutputPath(frame.options.savePreset);

  auto context = createHeadlessContext(frame.options.backend);
  Renderer renderer(TechniqueRegistry::instance());
  renderer.setScene(frame.scene);
  ReferenceStats stats;
  const Image image = renderReferenceFrame(renderer, frame, reference, spp, ::isatty(STDERR_FILENO) == 1, stats);
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
