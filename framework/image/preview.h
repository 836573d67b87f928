// Previews of data for 8-bit PNG (`rtlab render --range/--false-color`, docs/cli.md "PNG previews
// of data"): values mapped linearly from [lo, hi] to [0, 1], optionally through the magma colour
// map of heatmap.cpp. EXR and PFM outputs always hold the raw data; previews are PNG only.
#pragma once
#include "image/image.h"

#include <optional>
#include <string>

namespace rtlab {

struct PreviewRange {
  float lo = 0.0f;
  float hi = 1.0f;
};

// Parses `--range` text: "LO:HI" (decimal numbers, LO < HI, both finite) or "auto" (nullopt:
// the valid pixels' own range). Error(Usage) naming `option` and the text otherwise.
std::optional<PreviewRange> parsePreviewRange(const std::string& option, const std::string& text);

// The valid pixels' range (validRange) as a preview range; [0, 1] when there is no valid value,
// and a range of width 1 around a flat image's value, so it stays visible.
PreviewRange autoPreviewRange(const Image& data);

// (v - lo) / (hi - lo) per channel; background pixels (mask 0) are 0. With falseColor (one
// channel only, else Error(Internal)) the mapped value goes through the magma map instead, with
// background pixels mid gray, as errorHeatmap draws them. Write the result with
// PngEncoding::Linear01.
Image previewImage(const Image& data, PreviewRange range, bool falseColor);

} // namespace rtlab
