// The showcase's measured atlas (docs/cli.md "rtlab showcase"): for each stage that has a
// reference and techniques, a small sweep (`rtlab sweep`, the same machinery and report) of all
// its techniques on the stage's showcase scene, shown as each technique beside the reference
// with its error figures and heat map, and the stage's error-against-time chart.
#pragma once
#include <string>
#include <vector>

namespace rtlab {

struct AtlasOptions {
  std::string outDir;           // the showcase folder; sweeps go to outDir/sweeps/<stage>/
  int width = 640, height = 360;
  int frames = 5;
  int spp = 32;                 // reference samples per pixel
  std::vector<std::string> frameArgs; // --backend/--timing as given to the showcase
};

struct AtlasStage {
  std::string stage, title, anchor;
  std::string html; // the section, links relative to outDir
};

// Runs one sweep per stage (progress on stderr) and returns the sections, in stage order.
std::vector<AtlasStage> buildAtlas(const AtlasOptions& options);

// The axes of a stage's atlas sweep, as --vary arguments: each of the stage's log-scale integer
// keys that does not define the reference (shadow.resolution), else each technique's first
// log-scale integer key (its sample count), at a quarter of its default (within its range) and
// at its default, so that every technique's last point is its default frame.
std::vector<std::string> atlasVaries(const std::string& stage, const std::vector<std::string>& techniques);

} // namespace rtlab
