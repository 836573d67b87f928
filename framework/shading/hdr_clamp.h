// Counters of the HDR clamp (docs/stages.md "The HDR clamp"): passes that write HDR colour in a
// 16-bit float format clamp it to 65504 (shaders/common/hdr.glsl) and count the clamped pixels,
// one uint counter per pass in a small storage buffer the renderer owns. Zeroed at the start of
// every frame (no wait); read back only when stats are requested (read() waits for the GPU).
#pragma once
#include "frame/stats.h"
#include "gl/gl.h"
#include "gl/objects.h"
#include "gl/program.h"

#include <string>
#include <vector>

namespace rtlab {

class HdrClampCounters {
public:
  static constexpr int kMaxPasses = 16;
  static constexpr GLuint kBinding = 7; // shaders/common/hdr.glsl has the same binding

  // Zeroes every counter and forgets which passes ran (creates the buffer on first use).
  void beginFrame();
  // Binds the counter buffer and sets `uniform` on the (used) program to the counter of `pass`,
  // which from now on is reported for this frame. Counters are assigned to pass names on first use.
  void bind(gl::Program& program, const std::string& pass, const char* uniform = "uHdrClampSlot") const;

  using Count = HdrClampCount;
  // The counts of the last frame, for the passes that bound their counter, in first-bind order.
  // Waits for the GPU to finish the frame.
  std::vector<Count> read() const;

private:
  int slot(const std::string& pass) const;
  gl::Buffer m_buffer;
  // Mutable: passes see the renderer's GpuCommon as const, and binding a counter is their only write.
  mutable std::vector<std::string> m_passes; // counter index -> pass name
  mutable std::vector<bool> m_used;          // bound this frame
};

} // namespace rtlab
