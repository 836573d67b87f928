// A progress bar on stderr for long reference renders:
//   "\rreference visibility [#####     ] 45% 1.2 s left"
// Thread-safe: workers report finished work; whichever gets the lock redraws, at most every
// 100 ms. The caller decides whether to show it (rtlab reference: only when stderr is a terminal).
#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace rtlab::reference {

class ProgressBar {
public:
  ProgressBar(std::string label, std::uint64_t total, bool enabled);
  ~ProgressBar(); // finishes the line if it was drawn
  void advance(std::uint64_t amount);
  void finish();

  // The line without the leading '\r' (for tests).
  static std::string format(const std::string& label, double fraction, double secondsLeft, bool knowEta);

private:
  using Clock = std::chrono::steady_clock;
  std::string m_label;
  std::uint64_t m_total;
  bool m_enabled;
  std::atomic<std::uint64_t> m_done{0};
  std::mutex m_drawMutex;
  Clock::time_point m_start, m_lastDraw;
  bool m_drawn = false, m_finished = false;
  std::uint64_t m_drawnDone = 0;
  void draw(std::uint64_t done);
};

} // namespace rtlab::reference
