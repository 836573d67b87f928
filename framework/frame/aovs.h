// AOV names a frame can output: the built-in ones and the active techniques' debug views.
#pragma once
#include "image/image.h"

#include <string>
#include <vector>

namespace rtlab {

class TechniqueRegistry;

// Error(Usage) if the AOV is unknown, or is a debug view of a technique that is not active.
void checkAovName(const std::string& aov, const std::vector<std::string>& activeTechniques,
                  const TechniqueRegistry& registry);
bool isBuiltinAov(const std::string& aov);
// Every AOV name: the built-in ones, then each registered technique's debug views.
std::vector<std::string> knownAovNames(const TechniqueRegistry& registry);
// Channels of a known AOV (1 or 3); Error(Internal) if unknown.
int aovChannels(const std::string& aov, const TechniqueRegistry& registry);

// How an AOV is written to PNG (docs/contract.md): color sRGB, normal n*0.5+0.5, depth normalized
// to the visible range, everything else linear in [0,1].
PngEncoding pngEncodingForAov(const std::string& aov);

} // namespace rtlab
