#include "app/run_info.h"

#include "platform/context.h"
#include "util/version.h"

namespace rtlab {

nlohmann::ordered_json statsJson(const ResolvedFrame& frame, const Context& context, TimingMethod timing,
                                 const FrameStats& stats) {
  nlohmann::ordered_json j;
  j["schema"] = 1;
  j["version"] = versionString();
  j["commit"] = gitCommit();
  j["renderer"] = context.info().renderer;
  j["backend"] = context.backendName();
  j["size"] = {frame.options.width, frame.options.height};
  j["timing"] = timingName(timing);
  j["seed"] = frame.options.seed;
  j["scene"] = frame.options.sceneSpec;
  const nlohmann::ordered_json measured = stats.toJson();
  for (const auto& [key, value] : measured.items()) j[key] = value;
  j["techniques"] = frame.techniques;
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (const auto& spec : frame.params.specs()) params[spec.key] = paramValueToJson(spec, frame.params.value(spec.key));
  j["params"] = params;
  return j;
}

} // namespace rtlab
