// The known pipeline state every frame-graph pass starts from and is returned to after it
// (docs/frame-graph.md "The known state"), a snapshot of the tracked state read back with glGet*, and
// a comparison that names the first differing field.
#pragma once
#include "gl/gl.h"

#include <string>
#include <utility>
#include <vector>

namespace rtlab::gl {

// Units and binding indices tracked per kind (image units, storage and atomic-counter buffer
// indices, sampler units), limited by what the context offers.
constexpr int kTrackedBindings = 8;
constexpr int kTrackedSamplerUnits = 16;

// The tracked state as named values, in a fixed order ("blend.src_rgb", "image_unit[2].texture", ...).
struct StateSnapshot {
  std::vector<std::pair<std::string, double>> fields;
  const double* find(const std::string& name) const;
};

// Reads the tracked state from the current context.
StateSnapshot captureState();
// The values restoreKnownState() sets, without touching GL (same fields and order as captureState()).
StateSnapshot knownState();
// Sets the known state: no culling (back faces, CCW front), no blending (ONE, ZERO, ADD), depth test
// off with LESS and writes on, all color writes on, no polygon offset (0, 0), no scissor, stencil or
// rasterizer discard, no image units, storage, atomic-counter, indirect or sampler bindings, texture
// unit 0 active, program 0, vertex array 0, framebuffer 0.
void restoreKnownState();
// "" when equal, else "<field> is <value>, expected <value>" for the first field that differs.
std::string firstDifference(const StateSnapshot& actual, const StateSnapshot& expected);

} // namespace rtlab::gl
