// Scenes of known transparent layers for the transparency tests: camera-facing quads of black base
// colour and known emission, lit by a light of intensity 0 with no ambient, so that each layer's
// radiance C is its emission exactly and the opaque colour behind them is the backdrop's emission.
// The exact Over (docs/contract.md "Transparency") at any pixel is then a CPU computation.
#pragma once
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace rtlab {

struct KnownLayer {
  float depth = 1.0f;          // view depth of the quad (the camera looks along -z from the origin)
  glm::vec2 ndcMin{-1}, ndcMax{1}; // the screen rectangle it covers, in normalised device coordinates
  glm::vec3 emission{0};       // its radiance C
  float alpha = 0.5f;          // its coverage
  bool opaque = false;         // an opaque quad instead (alpha ignored)
};

// Layers in front of an opaque backdrop at depth 50 emitting `backdrop`, for frames of aspect
// `aspect` (width / height); the camera's fov is 60 degrees. The instances are added in the order
// given; SceneGpu still draws transparent instances back to front, so the order given is the draw
// order only among layers whose bounds sort equal (test_depth_peeling.cpp gives them equal bounds).
Scene makeKnownLayersScene(const std::string& name, const std::vector<KnownLayer>& layers, const glm::vec3& backdrop,
                           float aspect);

// Exact Over, in double precision, of the transparent layers covering NDC point `ndc`, onto the
// nearest opaque quad covering it (or the backdrop).
glm::dvec3 exactOver(const std::vector<KnownLayer>& layers, const glm::vec3& backdrop, const glm::vec2& ndc);

// The top-to-bottom pixel whose centre is nearest to NDC point `ndc` in a width x height frame.
glm::ivec2 pixelAt(const glm::vec2& ndc, int width, int height);

} // namespace rtlab
