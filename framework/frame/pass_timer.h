// One timing mechanism for every pass, headless or in the viewer (docs/architecture.md
// "Timing"): GL timer queries on a hardware GPU; on Mesa's software rasterizers, where timer
// queries do not measure the rasterization, each pass is bracketed by glFinish and timed on the
// CPU clock.
#pragma once
#include "gl/objects.h"

#include <chrono>
#include <string>
#include <vector>

namespace rtlab {

enum class TimingMethod { GpuQuery, CpuFinish };
enum class TimingChoice { Auto, GpuQuery, CpuFinish };

TimingChoice parseTimingChoice(const std::string& text); // auto|gpu-query|cpu-finish, else Error(Usage)
TimingMethod resolveTiming(TimingChoice choice, bool softwareRasterizer);
const char* timingName(TimingMethod method); // "gpu-query" | "cpu-finish"

class PassTimer {
public:
  explicit PassTimer(TimingMethod method) : m_method(method) {}
  TimingMethod method() const { return m_method; }

  void beginFrame();
  void begin(const std::string& pass, const std::string& technique);
  void end();
  // Waits for the frame's results (glFinish / query results) and records the frame's wall time.
  void endFrame();

  struct Sample {
    std::string pass, technique;
    double ms = 0.0;
  };
  const std::vector<Sample>& frameSamples() const { return m_samples; }
  double frameMs() const { return m_frameMs; }

private:
  using Clock = std::chrono::steady_clock;
  TimingMethod m_method;
  std::vector<Sample> m_samples;
  std::vector<gl::Query> m_queries; // grown on demand, reused across frames
  std::size_t m_used = 0;
  Clock::time_point m_frameStart, m_passStart;
  double m_frameMs = 0.0;
};

} // namespace rtlab
