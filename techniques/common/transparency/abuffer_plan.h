// The A-buffer's memory plan (techniques/abuffer/README.md "Memory"): how many nodes the pool
// holds, and in which screen rectangles a frame is built and resolved so that each rectangle's
// fragments fit the pool. Pure arithmetic, no GL: the passes (abuffer_passes.h) follow it.
#pragma once
#include <cstdint>
#include <vector>

namespace rtlab::abuffer {

constexpr std::uint64_t kNodeBytes = 16;           // shaders/abuffer/node.glsl: a uvec4
constexpr std::uint64_t kInitialNodesPerPixel = 4; // the pool's first size, before any frame was counted
constexpr std::uint64_t kEndOfList = 0xffffffffu;  // node.glsl kEndOfList: indices stay below it

// A rectangle of pixels in GL window coordinates (y up), the scissor of one build and resolve.
struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
  std::uint64_t pixels() const { return std::uint64_t(width) * std::uint64_t(height); }
  bool operator==(const Rect&) const = default;
};

// The most nodes one pool may hold: the budget and the GL limit on a storage block
// (GL_MAX_SHADER_STORAGE_BLOCK_SIZE), in nodes, and below the end-of-list marker; at least 1.
std::uint64_t maxNodes(std::uint64_t budgetBytes, std::uint64_t glBlockLimitBytes);

// The number of horizontal bands for a frame expected to need `expectedNodes`: enough that each
// holds about 1/1.1 of the largest pool (bands are equal in height, fragments are not spread
// evenly), between 1 and `height`.
int bandCount(std::uint64_t expectedNodes, std::uint64_t maxNodes, int height);

// `count` horizontal bands of equal height (the first ones one row taller when the height does
// not divide), covering the width x height frame from the bottom row up.
std::vector<Rect> bands(int width, int height, int count);

// The capacity to allocate when `needed` nodes must fit: 25% more (so that a slowly growing scene
// does not reallocate every frame), at most maxNodes.
std::uint64_t grownCapacity(std::uint64_t needed, std::uint64_t maxNodes);

// The parts of a rectangle whose build needed `count` > maxNodes nodes: split along its longer
// side into ceil(1.25 count / maxNodes) strips (at most one pixel wide), in order (bottom to top,
// or left to right). A single pixel is not split (its fragments beyond the pool are dropped).
std::vector<Rect> split(const Rect& rect, std::uint64_t count, std::uint64_t maxNodes);

} // namespace rtlab::abuffer
