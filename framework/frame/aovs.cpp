#include "frame/aovs.h"

#include "frame/registry.h"
#include "frame/stages.h"
#include "util/error.h"
#include "util/suggest.h"

#include <algorithm>

namespace rtlab {

bool isBuiltinAov(const std::string& aov) {
  const auto& list = builtinAovs();
  return std::any_of(list.begin(), list.end(), [&](const AovInfo& a) { return a.name == aov; });
}

std::vector<std::string> knownAovNames(const TechniqueRegistry& registry) {
  std::vector<std::string> names;
  for (const auto& a : builtinAovs()) names.push_back(a.name);
  for (const auto& entry : registry.entries())
    for (const auto& view : entry.info.debugViews) names.push_back(view.name);
  return names;
}

void checkAovName(const std::string& aov, const std::vector<std::string>& active, const TechniqueRegistry& registry) {
  if (isBuiltinAov(aov)) return;
  for (const auto& entry : registry.entries())
    for (const auto& view : entry.info.debugViews)
      if (view.name == aov) {
        if (std::find(active.begin(), active.end(), entry.info.id) == active.end())
          usageError("AOV '" + aov + "' is a debug view of technique '" + entry.info.id +
                     "', which is not active (add -t " + entry.info.id + ")");
        return;
      }
  std::string known;
  for (const auto& a : builtinAovs()) known += (known.empty() ? "" : ", ") + a.name;
  usageError("unknown AOV '" + aov + "'" + didYouMean(aov, knownAovNames(registry)) + " (built-in: " + known +
             "; debug views: see 'rtlab list')");
}

int aovChannels(const std::string& aov, const TechniqueRegistry& registry) {
  for (const auto& a : builtinAovs())
    if (a.name == aov) return a.channels;
  for (const auto& entry : registry.entries())
    for (const auto& v : entry.info.debugViews)
      if (v.name == aov) return v.channels;
  throw Error(ExitCode::Internal, "unknown AOV '" + aov + "'");
}

PngEncoding pngEncodingForAov(const std::string& aov) {
  if (aov == "color") return PngEncoding::Srgb;
  if (aov == "normal") return PngEncoding::Normal;
  if (aov == "depth") return PngEncoding::NormalizeRange;
  return PngEncoding::Linear01;
}

} // namespace rtlab
