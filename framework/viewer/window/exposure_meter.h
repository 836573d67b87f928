// The viewer's exposure readout (docs/viewer.md "Exposure readout"): a compute reduction of the
// frame's linear colour into one partial sum per 16x16 tile (shaders/viewer/exposure.comp), read
// back a frame later through a fence so the viewer never waits for the GPU, and finished on the CPU
// (image/exposure.h). The viewer starts one at most every kInterval.
#pragma once
#include "gl/buffer.h"
#include "gl/program_cache.h"
#include "gl/texture.h"
#include "image/exposure.h"

#include <chrono>
#include <optional>

namespace rtlab {

class ExposureMeter {
public:
  static constexpr std::chrono::milliseconds kInterval{250};

  explicit ExposureMeter(gl::ProgramCache& programs) : m_programs(programs) {}
  ~ExposureMeter();
  ExposureMeter(const ExposureMeter&) = delete;
  ExposureMeter& operator=(const ExposureMeter&) = delete;

  // Whether a measurement should start now: none is in flight and kInterval has passed since the
  // last start.
  bool due(std::chrono::steady_clock::time_point now) const;
  // Dispatches the reduction over `color` (linear RGB, its whole level 0) and fences it.
  void start(const gl::Texture& color, std::chrono::steady_clock::time_point now);
  // The readout of the measurement in flight once the GPU has finished it (it is then no longer in
  // flight); nullopt while it runs or when none was started. `wait`: block until it has finished.
  std::optional<ExposureReadout> poll(bool wait = false);

private:
  void releaseFence();

  gl::ProgramCache& m_programs;
  gl::BufferObject m_tiles;
  GLsync m_fence = nullptr;
  std::size_t m_tileCount = 0;
  std::chrono::steady_clock::time_point m_lastStart{};
  bool m_started = false;
};

} // namespace rtlab
