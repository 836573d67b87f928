// "Did you mean" hints for names the user mistyped: keys, techniques, scenes, AOVs.
#pragma once
#include <string>
#include <vector>

namespace rtlab {

// The known name closest to `typed`: one equal ignoring case first ("PCSS" -> "pcss"), else the
// one with the smallest case-insensitive edit distance, if that distance is at most 3 and at most
// half of typed's length ("shadowmap" -> "shadow_map"). Empty when nothing is that close.
std::string closestName(const std::string& typed, const std::vector<std::string>& known);

// " (did you mean 'x'?)" for closestName's answer, or `otherwise` when there is none.
std::string didYouMean(const std::string& typed, const std::vector<std::string>& known,
                       const std::string& otherwise = "");

} // namespace rtlab
