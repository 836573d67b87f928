// How `rtlab render` writes an AOV (docs/cli.md "PNG previews of data"): EXR/PFM hold the raw
// data; a PNG of a data or debug AOV is a preview, by docs/contract.md's encoding unless --range or
// --false-color say otherwise, or a debug view's values leave [0, 1] (then auto-ranged).
#pragma once
#include "app/args.h"
#include "image/image.h"
#include "image/preview.h"

#include <optional>
#include <string>

namespace rtlab {

class TechniqueRegistry;

struct AovPreviewRequest {
  bool range = false;                // --range given
  std::optional<PreviewRange> fixed; // --range LO:HI (nullopt with --range auto)
  bool falseColor = false;           // --false-color
};

// Validates --range/--false-color against the AOV and the output format before any GL work:
// Error(Usage) for bad --range text, for either flag with an EXR/PFM output or with `color`,
// and for --false-color with a three-channel AOV.
AovPreviewRequest parseAovPreview(const Args& args, const std::string& aov, ImageFormat format,
                                  const TechniqueRegistry& registry);

// Writes the AOV image to `out` (format by extension). For a PNG preview that is not the
// contract's encoding, prints one line to stderr naming the range used ("rtlab: note: ...").
void writeAovImage(const std::string& out, const Image& image, const std::string& aov,
                   const AovPreviewRequest& request);

} // namespace rtlab
