// Every transparent fragment of a frame, read back to the CPU: the input of the transparency
// reference (docs/measuring.md "References per stage", docs/contract.md "Transparency"). A pass
// draws the transparent instances with the layer shading every transparency technique uses
// (shaders/shading/layer.glsl), depth-tested against the opaque depth before the shader runs, and
// appends each fragment to a storage buffer. So that nothing is dropped, it first counts the
// fragments of each row, then captures the frame in bands of rows whose fragments fit the buffer
// (at most kMaxCaptureBytes, and the context's largest storage block), reading each band back.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

class FrameGraph;

// One fragment as shaders/shading/capture.frag writes it (std430, 28 bytes).
struct CapturedFragment {
  std::uint32_t x = 0, y = 0; // pixel; y counts rows from the top (Image's order)
  float depth = 0.0f;         // window depth gl_FragCoord.z: the order along the pixel's ray
  float r = 0.0f, g = 0.0f, b = 0.0f; // radiance C = lit + E (not premultiplied)
  float alpha = 0.0f;                 // coverage
};

struct CapturedFragments {
  int width = 0, height = 0;
  std::vector<CapturedFragment> fragments; // in no particular order
  int bands = 0;                           // how many bands the capture took
};

// The capture buffer's size limit per band (the context's GL_MAX_SHADER_STORAGE_BLOCK_SIZE too).
inline constexpr std::size_t kMaxCaptureBytes = std::size_t(64) << 20;

// Adds the pass "transparency.capture" reading the opaque depth; it fills `out` when it runs.
// Returns the resource to request as a target so that the pass is kept. `maxBytes` (tests) lowers
// the band size limit. Error(Internal) if one row alone holds more fragments than a band can.
std::string addFragmentCapturePass(FrameGraph& frame, CapturedFragments& out, std::size_t maxBytes = kMaxCaptureBytes);

} // namespace rtlab
