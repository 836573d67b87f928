// rtlab compare A B [--json]: error metrics of B against A over their valid pixels (docs/contract.md
// "compare --json", docs/metrics.md). Exits 0 whatever the difference; 3 when an input is missing,
// unreadable, invalid or of another size than the other; 2 for usage errors.
#include "app/args.h"
#include "app/commands.h"
#include "image/image.h"
#include "image/metrics.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/log.h"
#include "util/number_format.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

namespace rtlab {
namespace {

Image readInput(const std::string& path) {
  try {
    imageFormatFromPath(path);
  } catch (const Error&) {
    inputError("cannot read image '" + path + "': unsupported format (use .png, .exr or .pfm)");
  }
  return readImage(path);
}

bool isPng(const std::string& path) { return imageFormatFromPath(path) == ImageFormat::Png; }

std::string number(double v) {
  if (!std::isfinite(v)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Inputs of different kinds still compare (exit 0), but the figures mean little: say so.
void warnOnUnlikeInputs(const std::string& pathA, const Image& a, const std::string& pathB, const Image& b) {
  if (isPng(pathA) != isPng(pathB)) {
    const std::string& png = isPng(pathA) ? pathA : pathB;
    const std::string& data = isPng(pathA) ? pathB : pathA;
    logWarn("'" + png + "' is an 8-bit display image (tone-mapped, sRGB-encoded colour or a data preview) and '" +
            data + "' holds linear float data: the metrics compare unlike values (compare two EXR/PFM files)");
  }
  if (a.channels != b.channels)
    logWarn("'" + pathA + "' has " + std::to_string(a.channels) + (a.channels == 1 ? " channel" : " channels") +
            " and '" + pathB + "' has " + std::to_string(b.channels) +
            (b.channels == 1 ? " channel" : " channels") + ": the three-channel one is compared by its luminance");
}

// --heatmap: |B - A| per pixel (mean over channels, absoluteErrorImage) on the magma map from 0
// to `scale`; invalid pixels gray. Returns the scale used.
double writeHeatmap(const std::string& path, const Image& a, const Image& b, const Metrics& m,
                    const std::optional<double>& fixedScale) {
  const double scale = fixedScale ? *fixedScale : m.maxAbs;
  writeImage(path, errorHeatmap(absoluteErrorImage(a, b), float(scale)));
  return scale;
}

// --over: the valid pixels whose |B - A| (mean over channels, as the heat map) exceeds `threshold`.
std::size_t countOver(const Image& a, const Image& b, double threshold) {
  const Image error = absoluteErrorImage(a, b);
  std::size_t over = 0;
  for (std::size_t i = 0; i < error.pixels.size(); ++i) over += error.mask[i] > 0.0f && double(error.pixels[i]) > threshold;
  return over;
}

} // namespace

int runCompare(int argc, char** argv) {
  const std::vector<OptionSpec> specs = {
      {"--json", "", false, "", "machine-readable output (docs/contract.md schema)"},
      {"--heatmap", "", true, "OUT.png", "write |B - A| per pixel as a heat map (magma, 0 .. --heatmap-max)"},
      {"--heatmap-max", "", true, "E", "the heat map's top: error E and above is brightest (default: max_abs)"},
      {"--over", "", true, "E", "also count the valid pixels whose |B - A| (mean over channels) exceeds E"},
  };
  Args args("compare", specs, argc, argv, 2, 2);
  if (args.help()) {
    std::cout << formatHelp(
        "rtlab compare A B [--json] [--heatmap OUT.png [--heatmap-max E]] [--over E]",
        "Compares image B with image A (.png, .exr or .pfm) over their valid pixels: finite in both, and\n"
        "A = 1 where a file has an alpha channel. Prints RMSE, PSNR (peak 1; none when identical), SSIM,\n"
        "FLIP (LDR, 67 pixels per degree), the largest absolute difference, the count of NaN/Inf pixels\n"
        "and the count of valid pixels. Exits 0 whatever the difference, 3 when an image is missing,\n"
        "invalid or of another size. Warns (exit still 0) when a PNG is compared with an EXR/PFM or\n"
        "the channel counts differ. --heatmap writes the per-pixel absolute error, mean over the\n"
        "channels, from 0 (black) to --heatmap-max (brightest; default the largest error) on the\n"
        "magma colour map, invalid pixels gray. --over E adds the count and the fraction of the valid\n"
        "pixels whose error (the heat map's) exceeds E. See docs/metrics.md and docs/cli.md.",
        specs);
    return 0;
  }
  if (args.positionals().size() != 2)
    usageError("compare needs two images, A and B (got " + std::to_string(args.positionals().size()) +
               "; see 'rtlab compare --help')");
  const std::string& pathA = args.positionals()[0];
  const std::string& pathB = args.positionals()[1];
  const std::string heatmapPath = args.get("--heatmap");
  if (args.has("--heatmap")) {
    if (heatmapPath.empty()) usageError("--heatmap needs a file name");
    requirePngPath(heatmapPath, "--heatmap"); // a directory: exit 6 naming it
    checkOutputPath(heatmapPath);
  }
  std::optional<double> heatmapMax;
  if (args.has("--heatmap-max")) {
    if (!args.has("--heatmap")) usageError("--heatmap-max needs --heatmap OUT.png");
    heatmapMax = parsePositiveNumber("--heatmap-max", args.get("--heatmap-max"));
  }
  std::optional<double> over;
  if (args.has("--over")) over = parsePositiveNumber("--over", args.get("--over"));
  const Image a = readInput(pathA);
  const Image b = readInput(pathB);
  if (a.width != b.width || a.height != b.height)
    inputError("images differ in size: '" + pathA + "' is " + std::to_string(a.width) + "x" +
               std::to_string(a.height) + ", '" + pathB + "' is " + std::to_string(b.width) + "x" +
               std::to_string(b.height));
  warnOnUnlikeInputs(pathA, a, pathB, b);

  MetricsOptions options;
  // PNG files hold display values (sRGB-encoded colour, data previews as shown).
  options.displayEncoded = isPng(pathA) && isPng(pathB);
  const Metrics m = computeMetrics(a, b, options);
  const double heatmapScale = heatmapPath.empty() ? 0.0 : writeHeatmap(heatmapPath, a, b, m, heatmapMax);
  const std::size_t overCount = over ? countOver(a, b, *over) : 0;
  const double overFraction = m.validPixels ? double(overCount) / double(m.validPixels) : 0.0;

  if (args.has("--json")) {
    nlohmann::ordered_json j = metricsToJson(m);
    if (!heatmapPath.empty()) j["heatmap"] = {{"file", heatmapPath}, {"max", heatmapScale}};
    if (over) j["over"] = {{"threshold", *over}, {"pixels", overCount}, {"fraction", overFraction}};
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  const std::string psnr =
      m.psnr ? number(*m.psnr) + " dB" : (m.validPixels ? std::string("none (identical)") : std::string("n/a"));
  std::cout << "rmse          " << number(m.rmse) << "\n"
            << "psnr          " << psnr << "\n"
            << "ssim          " << number(m.ssim) << "\n"
            << "flip          " << number(m.flip) << "\n"
            << "max_abs       " << number(m.maxAbs) << "\n"
            << "nan_count     " << m.nanCount << "\n"
            << "valid_pixels  " << m.validPixels << "\n";
  if (over)
    std::cout << "over          " << overCount << " (" << number(overFraction) << " of the valid pixels above " << number(*over)
              << ")\n";
  if (!heatmapPath.empty())
    std::cout << "heatmap       " << heatmapPath << " (|B - A|, mean over channels: 0 black .. " << formatNumber(heatmapScale)
              << " brightest, magma; invalid pixels gray)\n";
  return 0;
}

} // namespace rtlab
