// Per-pass timings over the measured frames and the resources of the last frame, written as the
// --stats JSON of docs/contract.md.
#pragma once
#include "frame/pass_timer.h"
#include "image/exposure.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rtlab {

struct ResourceUse {
  std::string name;
  std::size_t bytes = 0;
};

// Pixels a pass clamped to 65504 in the last frame (docs/stages.md "The HDR clamp").
struct HdrClampCount {
  std::string pass;
  std::uint64_t pixels = 0;
};

// A technique's count about the last measured frame (Technique::counters()).
struct CounterValue {
  std::string technique, name;
  double value = 0;
};

class FrameStats {
public:
  // Adds one measured frame.
  void addFrame(const PassTimer& timer, int glErrors);
  void setResources(std::vector<ResourceUse> resources) { m_resources = std::move(resources); }
  // The HDR clamp counts of the last measured frame (Renderer::readHdrClamped).
  void setHdrClamped(std::vector<HdrClampCount> counts) { m_hdrClamped = std::move(counts); }
  const std::vector<HdrClampCount>& hdrClamped() const { return m_hdrClamped; }
  void setCounters(std::vector<CounterValue> counters) { m_counters = std::move(counters); }
  const std::vector<CounterValue>& counters() const { return m_counters; }
  // The exposure readout of the last measured frame's `color` (image/exposure.h); written as
  // "exposure" only when set.
  void setExposure(const ExposureReadout& exposure) { m_exposure = exposure; }
  const std::optional<ExposureReadout>& exposure() const { return m_exposure; }

  struct PassSummary {
    std::string name, technique;
    double ms = 0, msMin = 0, msMax = 0; // median, min, max over frames
    // The least GL work of the pass over the frames (PassTimer::Sample::work), when every frame
    // counted it; not written to the JSON.
    std::optional<std::uint64_t> workMin;
  };
  std::vector<PassSummary> passes() const;
  double frameMs() const; // median
  int frames() const { return int(m_frameMs.size()); }
  int glErrors() const { return m_glErrors; }
  const std::vector<ResourceUse>& resources() const { return m_resources; }
  std::size_t resourceBytes() const;
  // Sum of the median ms of the passes attributed to `technique`.
  double techniqueMs(const std::string& technique) const;

  // Fields that depend only on what was measured: frames, frame_ms, passes, resources,
  // resource_bytes, gl_errors, hdr_clamped, counters, exposure (when set). The caller adds the run's description (schema, version, ...).
  nlohmann::ordered_json toJson() const;

private:
  struct Series {
    std::string name, technique;
    std::vector<double> ms;
    std::vector<std::optional<std::uint64_t>> work;
  };
  std::vector<Series> m_series;
  std::vector<double> m_frameMs;
  std::vector<ResourceUse> m_resources;
  std::vector<HdrClampCount> m_hdrClamped;
  std::vector<CounterValue> m_counters;
  std::optional<ExposureReadout> m_exposure;
  int m_glErrors = 0;
};

double median(std::vector<double> values);

} // namespace rtlab
