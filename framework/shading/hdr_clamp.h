// Counters of the HDR clamp (docs/stages.md "The HDR clamp"): passes that write HDR colour in a
// 16-bit float format clamp it to 65504 (shaders/common/hdr.glsl) and count the clamped pixels,
// one uint counter per pass in a small storage buffer the renderer owns and imports into a counting
// frame's graph (docs/frame-graph.md "Imported resources"), so the passes declare it and the graph
// binds it and plans its barriers. Counting is on only for frames that ask for it
// (FrameOutputs::countHdrClamped: the shaders then get HDR_CLAMP_COUNT and atomics, which slow
// llvmpipe down); such a frame zeroes the counters first (no wait), and read() (which waits for
// the GPU) returns the last counted frame's counts.
#pragma once
#include "frame/stats.h"
#include "gl/gl.h"
#include "gl/buffer.h"
#include "gl/program.h"

#include <string>
#include <vector>

namespace rtlab {

class FrameGraph;
class PassBuilder;

class HdrClampCounters {
public:
  static constexpr int kMaxPasses = 16;
  static constexpr int kBinding = 7; // shaders/common/hdr.glsl has the same binding
  static constexpr const char* kResource = "hdr_clamp.counters";

  // Starts a frame. With `count`: zeroes every counter and forgets which passes ran (creates the
  // buffer on first use); without, the last counted frame's counts stay.
  void beginFrame(bool count);
  // The counter buffer (valid while counting), for FrameGraph::importBuffer under kResource.
  gl::BufferObject& buffer() { return m_buffer; }
  // Whether this frame counts: a pass then adds the define "HDR_CLAMP_COUNT" to its program.
  bool counting() const { return m_counting; }
  // When counting: sets `uniform` on the program to the counter of `pass`, which is then reported
  // for this frame (counters are assigned to pass names on first use). The pass declares the buffer
  // (declareUse) and the graph binds it. Otherwise does nothing.
  void bind(gl::Program& program, const std::string& pass, const char* uniform = "uHdrClampSlot") const;
  // In a pass's setup: declares the counters read-write at kBinding when the frame counts (the
  // renderer imported them).
  static void declareUse(const FrameGraph& frame, PassBuilder& b);

  using Count = HdrClampCount;
  // The counts of the last counted frame, for the passes that bound their counter, in first-bind
  // order. Waits for the GPU to finish that frame.
  std::vector<Count> read() const;

private:
  int slot(const std::string& pass) const;
  gl::BufferObject m_buffer;
  bool m_counting = false;
  // Mutable: passes see the renderer's GpuCommon as const, and binding a counter is their only write.
  mutable std::vector<std::string> m_passes; // counter index -> pass name
  mutable std::vector<bool> m_used;          // bound this frame
};

} // namespace rtlab
