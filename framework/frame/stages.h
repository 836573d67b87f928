// The frame's fixed recipe of stages (docs/architecture.md "Stages and slots") and the parameters the frame itself
// owns: stage parameters (shadow.*, ao.radius) and tone mapping (tonemap.*).
#pragma once
#include "params/param_spec.h"

#include <string>
#include <vector>

namespace rtlab {

struct StageInfo {
  std::string id;      // "shadow"
  bool exclusive = true;
  std::string output;  // AOV the stage produces: "visibility", "ao", "indirect", "color"
  std::vector<ParamSpec> params;
};

const std::vector<StageInfo>& stages();
const StageInfo* findStage(const std::string& id);
std::vector<ParamSpec> tonemapParams();

// AOVs every frame can output (docs/contract.md): color, visibility, ao, indirect, depth, normal, albedo.
struct AovInfo {
  std::string name;
  int channels;
  std::string help;
};
const std::vector<AovInfo>& builtinAovs();

} // namespace rtlab
