#include "util/suggest.h"

#include <algorithm>
#include <cctype>

namespace rtlab {
namespace {

char lower(char c) { return char(std::tolower(static_cast<unsigned char>(c))); }

// Levenshtein distance, ignoring case.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

} // namespace

std::string closestName(const std::string& typed, const std::vector<std::string>& known) {
  std::string best;
  std::size_t bestDist = std::min<std::size_t>(3, typed.size() / 2) + 1;
  for (const auto& name : known) {
    const std::size_t d = editDistance(typed, name);
    if (d == 0) return name; // equal ignoring case
    if (d < bestDist) {
      bestDist = d;
      best = name;
    }
  }
  return best;
}

std::string didYouMean(const std::string& typed, const std::vector<std::string>& known, const std::string& otherwise) {
  const std::string best = closestName(typed, known);
  return best.empty() ? otherwise : " (did you mean '" + best + "'?)";
}

} // namespace rtlab
