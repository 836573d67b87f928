#include "frame/param_catalog.h"

#include "frame/registry.h"
#include "frame/stages.h"
#include "scene/scene_params.h"

namespace rtlab {

ParamSet makeParamSet(const Scene& scene, const TechniqueRegistry& registry) {
  ParamSet set;
  set.declare(tonemapParams());
  for (const auto& stage : stages()) set.declare(stage.params);
  for (const auto& entry : registry.entries()) set.declare(entry.info.params);
  set.declare(sceneParamSpecs(scene));
  return set;
}

} // namespace rtlab
