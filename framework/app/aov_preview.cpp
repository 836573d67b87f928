#include "app/aov_preview.h"

#include "frame/aovs.h"
#include "frame/registry.h"
#include "util/error.h"
#include "util/number_format.h"

#include <cstdio>

namespace rtlab {

AovPreviewRequest parseAovPreview(const Args& args, const std::string& aov, ImageFormat format,
                                  const TechniqueRegistry& registry) {
  AovPreviewRequest r;
  r.range = args.has("--range");
  r.falseColor = args.has("--false-color");
  if (r.range) r.fixed = parsePreviewRange("--range", args.get("--range"));
  if (!r.range && !r.falseColor) return r;
  const std::string flag = r.range ? "--range" : "--false-color";
  if (format != ImageFormat::Png)
    usageError(flag + " shapes a PNG preview; EXR and PFM outputs hold the raw data (write a .png, or drop " + flag + ")");
  if (aov == "color")
    usageError(flag + " applies to data and debug AOVs; 'color' is tone-mapped (see tonemap.exposure, or write it as .exr)");
  if (r.falseColor && aovChannels(aov, registry) != 1)
    usageError("--false-color needs a one-channel AOV; '" + aov + "' has " +
               std::to_string(aovChannels(aov, registry)) + " channels (use --range alone)");
  return r;
}

void writeAovImage(const std::string& out, const Image& image, const std::string& aov,
                   const AovPreviewRequest& request) {
  const PngEncoding encoding = pngEncodingForAov(aov);
  if (imageFormatFromPath(out) != ImageFormat::Png || aov == "color") {
    writeImage(out, image, encoding);
    return;
  }
  // A debug view has no contract encoding: auto-range it when its values leave [0, 1], where the
  // linear encoding would clip them.
  const ValueRange values = validRange(image);
  const bool outside = !values.empty() && (values.min < 0.0f || values.max > 1.0f);
  const bool autoDebug = !isBuiltinAov(aov) && outside;
  const bool depthLike = encoding == PngEncoding::NormalizeRange;
  if (!request.range && !request.falseColor && !autoDebug) {
    writeImage(out, image, encoding);
    return;
  }
  PreviewRange range;
  bool automatic = false;
  if (request.fixed) {
    range = *request.fixed;
  } else if (request.range || autoDebug || depthLike) {
    range = autoPreviewRange(image);
    automatic = true;
  } else if (encoding == PngEncoding::Normal) {
    range = {-1.0f, 1.0f}; // n*0.5+0.5, the contract's normal preview
  }
  writeImage(out, previewImage(image, range, request.falseColor), PngEncoding::Linear01);
  if (automatic || request.falseColor)
    std::fprintf(stderr, "rtlab: note: '%s' previews %s from %s (%s) to %s (%s)%s\n", out.c_str(), aov.c_str(),
                 formatNumber(range.lo).c_str(), request.falseColor ? "darkest" : "black",
                 formatNumber(range.hi).c_str(), request.falseColor ? "brightest, magma" : "white",
                 automatic ? "; the valid pixels' range (choose one with --range LO:HI)" : "");
}

} // namespace rtlab
