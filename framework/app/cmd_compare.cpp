// rtlab compare A B [--json]: error metrics of B against A over their valid pixels (CONTRACT.md
// "compare --json", docs/metrics.md). Exits 0 whatever the difference; 3 when an input is missing,
// unreadable, invalid or of another size than the other; 2 for usage errors.
#include "app/args.h"
#include "app/commands.h"
#include "image/image.h"
#include "image/metrics.h"
#include "util/error.h"

#include <cmath>
#include <cstdio>
#include <iostream>
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

} // namespace

int runCompare(int argc, char** argv) {
  const std::vector<OptionSpec> specs = {
      {"--json", "", false, "", "machine-readable output (CONTRACT.md schema)"},
  };
  Args args("compare", specs, argc, argv, 2, 2);
  if (args.help()) {
    std::cout << formatHelp(
        "rtlab compare A B [--json]",
        "Compares image B with image A (.png, .exr or .pfm) over their valid pixels: finite in both, and\n"
        "A = 1 where a file has an alpha channel. Prints RMSE, PSNR (peak 1; none when identical), SSIM,\n"
        "FLIP (LDR, 67 pixels per degree), the largest absolute difference, the count of NaN/Inf pixels\n"
        "and the count of valid pixels. Exits 0 whatever the difference, 3 when an image is missing,\n"
        "invalid or of another size. See docs/metrics.md.",
        specs);
    return 0;
  }
  if (args.positionals().size() != 2)
    usageError("compare needs two images, A and B (got " + std::to_string(args.positionals().size()) +
               "; see 'rtlab compare --help')");
  const std::string& pathA = args.positionals()[0];
  const std::string& pathB = args.positionals()[1];
  const Image a = readInput(pathA);
  const Image b = readInput(pathB);
  if (a.width != b.width || a.height != b.height)
    inputError("images differ in size: '" + pathA + "' is " + std::to_string(a.width) + "x" +
               std::to_string(a.height) + ", '" + pathB + "' is " + std::to_string(b.width) + "x" +
               std::to_string(b.height));

  MetricsOptions options;
  // PNG files hold display values (sRGB-encoded colour, data previews as shown).
  options.displayEncoded = isPng(pathA) && isPng(pathB);
  const Metrics m = computeMetrics(a, b, options);

  if (args.has("--json")) {
    std::cout << metricsToJson(m).dump(2) << "\n";
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
  return 0;
}

} // namespace rtlab
