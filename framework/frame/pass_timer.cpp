#include "frame/pass_timer.h"

#include "util/error.h"

namespace rtlab {

TimingChoice parseTimingChoice(const std::string& text) {
  if (text == "auto") return TimingChoice::Auto;
  if (text == "gpu-query") return TimingChoice::GpuQuery;
  if (text == "cpu-finish") return TimingChoice::CpuFinish;
  usageError("unknown timing method '" + text + "' (choices: auto, gpu-query, cpu-finish)");
}

TimingMethod resolveTiming(TimingChoice choice, bool softwareRasterizer) {
  switch (choice) {
  case TimingChoice::GpuQuery: return TimingMethod::GpuQuery;
  case TimingChoice::CpuFinish: return TimingMethod::CpuFinish;
  case TimingChoice::Auto: break;
  }
  return softwareRasterizer ? TimingMethod::CpuFinish : TimingMethod::GpuQuery;
}

const char* timingName(TimingMethod method) {
  return method == TimingMethod::GpuQuery ? "gpu-query" : "cpu-finish";
}

void PassTimer::beginFrame() {
  m_samples.clear();
  m_used = 0;
  glFinish(); // the frame's wall time starts with an idle GPU
  m_frameStart = Clock::now();
}

void PassTimer::begin(const std::string& pass, const std::string& technique) {
  m_samples.push_back(Sample{pass, technique, 0.0});
  if (m_method == TimingMethod::CpuFinish) {
    glFinish();
    m_passStart = Clock::now();
  } else {
    if (m_used == m_queries.size()) m_queries.emplace_back(GL_TIME_ELAPSED, "pass-timer");
    glBeginQuery(GL_TIME_ELAPSED, m_queries[m_used].id());
  }
}

void PassTimer::end() {
  if (m_method == TimingMethod::CpuFinish) {
    glFinish();
    m_samples.back().ms = std::chrono::duration<double, std::milli>(Clock::now() - m_passStart).count();
  } else {
    glEndQuery(GL_TIME_ELAPSED);
    ++m_used;
  }
}

void PassTimer::endFrame() {
  glFinish();
  m_frameMs = std::chrono::duration<double, std::milli>(Clock::now() - m_frameStart).count();
  if (m_method == TimingMethod::GpuQuery) {
    for (std::size_t i = 0; i < m_used && i < m_samples.size(); ++i) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(m_queries[i].id(), GL_QUERY_RESULT, &ns);
      m_samples[i].ms = double(ns) * 1e-6;
    }
  }
}

} // namespace rtlab
