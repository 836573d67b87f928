// Every parameter a frame knows, in one ParamSet: tone mapping, stage parameters, every
// registered technique's parameters (active or not: --set stores values for inactive ones), and
// the scene's light<N>.* and camera.* keys.
#pragma once
#include "params/param_set.h"

namespace rtlab {

struct Scene;
class TechniqueRegistry;

ParamSet makeParamSet(const Scene& scene, const TechniqueRegistry& registry);

} // namespace rtlab
