// One timing mechanism for every pass, headless or in the viewer (docs/architecture.md
// "Timing"): GL timer queries on a hardware GPU; on Mesa's software rasterizers, where timer
// queries do not measure the rasterization, each pass is bracketed by glFinish and timed on the
// CPU clock.
#pragma once
#include "gl/objects.h"

#include <chrono>
#include <cstdint>
#include <optional>
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
  explicit PassTimer(TimingMethod method) : m_method(method), m_countWork(s_countWorkDefault) {}
  TimingMethod method() const { return m_method; }

  // Work counting, the record that a pass did GL work (tests/render/test_extremes.cpp): each pass
  // is also bracketed by two pipeline-statistics queries (GL_ARB_pipeline_statistics_query, core
  // in 4.6), the vertices its draws submitted and the compute-shader invocations its dispatches
  // ran; Sample::work is their sum after endFrame(). Off by default (the queries wait for the GPU);
  // timers made after setCountWorkDefault(true) count. Without the extension nothing is counted.
  static void setCountWorkDefault(bool on) { s_countWorkDefault = on; }
  static bool workCountingSupported(); // the current context has GL_ARB_pipeline_statistics_query

  void beginFrame();
  void begin(const std::string& pass, const std::string& technique);
  void end();
  // Waits for the frame's results (glFinish / query results) and records the frame's wall time.
  void endFrame();

  struct Sample {
    std::string pass, technique;
    double ms = 0.0;
    std::optional<std::uint64_t> work; // set when work was counted (setCountWorkDefault)
  };
  const std::vector<Sample>& frameSamples() const { return m_samples; }
  double frameMs() const { return m_frameMs; }

private:
  using Clock = std::chrono::steady_clock;
  TimingMethod m_method;
  std::vector<Sample> m_samples;
  std::vector<gl::Query> m_queries; // grown on demand, reused across frames
  std::size_t m_used = 0;
  static inline bool s_countWorkDefault = false;
  bool m_countWork;
  bool m_counting = false;           // this frame counts (m_countWork and the extension)
  std::vector<gl::Query> m_workQueries; // two per pass: vertices submitted, compute invocations
  std::size_t m_workUsed = 0;
  Clock::time_point m_frameStart, m_passStart;
  double m_frameMs = 0.0;
};

} // namespace rtlab
