#include "frame/stats.h"

#include <algorithm>

namespace rtlab {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void FrameStats::addFrame(const PassTimer& timer, int glErrors) {
  for (const auto& s : timer.frameSamples()) {
    auto it = std::find_if(m_series.begin(), m_series.end(), [&](const Series& x) { return x.name == s.pass; });
    if (it == m_series.end()) {
      m_series.push_back(Series{s.pass, s.technique, {}, {}});
      it = m_series.end() - 1;
    }
    it->ms.push_back(s.ms);
    it->work.push_back(s.work);
  }
  m_frameMs.push_back(timer.frameMs());
  m_glErrors += glErrors;
}

std::vector<FrameStats::PassSummary> FrameStats::passes() const {
  std::vector<PassSummary> out;
  for (const auto& s : m_series) {
    PassSummary p{s.name, s.technique, median(s.ms), 0, 0, std::nullopt};
    p.msMin = *std::min_element(s.ms.begin(), s.ms.end());
    p.msMax = *std::max_element(s.ms.begin(), s.ms.end());
    if (std::all_of(s.work.begin(), s.work.end(), [](const auto& w) { return w.has_value(); }))
      for (const auto& w : s.work) p.workMin = p.workMin ? std::min(*p.workMin, *w) : *w;
    out.push_back(p);
  }
  return out;
}

double FrameStats::frameMs() const { return median(m_frameMs); }

std::size_t FrameStats::resourceBytes() const {
  std::size_t total = 0;
  for (const auto& r : m_resources) total += r.bytes;
  return total;
}

double FrameStats::techniqueMs(const std::string& technique) const {
  double total = 0;
  for (const auto& p : passes())
    if (p.technique == technique) total += p.ms;
  return total;
}

nlohmann::ordered_json FrameStats::toJson() const {
  nlohmann::ordered_json j;
  j["frames"] = frames();
  j["frame_ms"] = frameMs();
  auto passArray = nlohmann::ordered_json::array();
  for (const auto& p : passes())
    passArray.push_back({{"name", p.name}, {"technique", p.technique}, {"ms", p.ms}, {"ms_min", p.msMin}, {"ms_max", p.msMax}});
  j["passes"] = passArray;
  auto resArray = nlohmann::ordered_json::array();
  for (const auto& r : m_resources) resArray.push_back({{"name", r.name}, {"bytes", r.bytes}});
  j["resources"] = resArray;
  j["resource_bytes"] = resourceBytes();
  j["gl_errors"] = m_glErrors;
  auto clampArray = nlohmann::ordered_json::array();
  for (const auto& c : m_hdrClamped) clampArray.push_back({{"pass", c.pass}, {"pixels", c.pixels}});
  j["hdr_clamped"] = clampArray;
  auto counterArray = nlohmann::ordered_json::array();
  for (const auto& c : m_counters)
    counterArray.push_back({{"technique", c.technique}, {"name", c.name}, {"value", c.value}});
  j["counters"] = counterArray;
  if (m_exposure)
    j["exposure"] = {{"log_average_luminance", m_exposure->logAverageLuminance},
                     {"max_luminance", m_exposure->maxLuminance},
                     {"key_exposure", m_exposure->keyExposure},
                     {"pixels", m_exposure->pixels},
                     {"non_finite_pixels", m_exposure->nonFinite}};
  return j;
}

} // namespace rtlab
