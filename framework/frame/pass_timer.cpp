#include "frame/pass_timer.h"

#include "util/error.h"

#include <cstring>

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

namespace {
// GL_ARB_pipeline_statistics_query's targets (the loader is generated for 4.5 core without it).
constexpr GLenum kVerticesSubmitted = 0x82EE;          // GL_VERTICES_SUBMITTED_ARB
constexpr GLenum kComputeShaderInvocations = 0x82F5;   // GL_COMPUTE_SHADER_INVOCATIONS_ARB
constexpr GLenum kWorkTargets[2] = {kVerticesSubmitted, kComputeShaderInvocations};
} // namespace

bool PassTimer::workCountingSupported() {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
    if (name && std::strcmp(name, "GL_ARB_pipeline_statistics_query") == 0) return true;
  }
  return false;
}

void PassTimer::beginFrame() {
  m_samples.clear();
  m_used = 0;
  m_workUsed = 0;
  // The extension list is read once per process, not per frame (one process has one GL platform).
  static const bool supported = workCountingSupported();
  m_counting = m_countWork && supported;
  glFinish(); // the frame's wall time starts with an idle GPU
  m_frameStart = Clock::now();
}

void PassTimer::begin(const std::string& pass, const std::string& technique) {
  m_samples.push_back(Sample{pass, technique, 0.0, std::nullopt});
  if (m_counting) {
    for (GLenum target : kWorkTargets) {
      if (m_workUsed == m_workQueries.size()) m_workQueries.emplace_back(target, "pass-work");
      glBeginQuery(target, m_workQueries[m_workUsed++].id());
    }
  }
  if (m_method == TimingMethod::CpuFinish) {
    glFinish();
    m_passStart = Clock::now();
  } else {
    if (m_used == m_queries.size()) m_queries.emplace_back(GL_TIME_ELAPSED, "pass-timer");
    glBeginQuery(GL_TIME_ELAPSED, m_queries[m_used].id());
  }
}

void PassTimer::end() {
  if (m_counting)
    for (GLenum target : kWorkTargets) glEndQuery(target);
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
  if (m_counting) {
    for (std::size_t i = 0; i < m_samples.size() && 2 * i + 1 < m_workUsed; ++i) {
      GLuint64 vertices = 0, invocations = 0;
      glGetQueryObjectui64v(m_workQueries[2 * i].id(), GL_QUERY_RESULT, &vertices);
      glGetQueryObjectui64v(m_workQueries[2 * i + 1].id(), GL_QUERY_RESULT, &invocations);
      m_samples[i].work = vertices + invocations;
    }
  }
}

} // namespace rtlab
