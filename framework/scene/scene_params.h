// The scene's own parameters (docs/contract.md "Keys and values"): scene.ambient, light<N>.* for each
// light, only the keys that apply to its type, and camera.position/target/fov. Defaults come from
// the scene.
#pragma once
#include "params/param_spec.h"
#include "scene/scene.h"

#include <vector>

namespace rtlab {

class ParamSet;

// Upper bound of scene.ambient and of a glTF scene's extras.ambient (radiance, per channel); a
// lit white surface of the built-in scenes has a radiance of about 0.8.
constexpr double kMaxAmbient = 100.0;

std::vector<ParamSpec> sceneParamSpecs(const Scene& scene);
// Writes the parameter values into the scene's ambient, lights and camera (directions normalized).
// Throws Error(Usage) for a zero direction or a camera whose target equals its position.
void applySceneParams(const ParamSet& params, Scene& scene);

} // namespace rtlab
