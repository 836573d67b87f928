#include "reference/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rtlab::reference {
namespace {

constexpr int kBarWidth = 30;
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);

void writeStderr(const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(2, p, left);
    if (n <= 0) return;
    p += n;
    left -= std::size_t(n);
  }
}

} // namespace

ProgressBar::ProgressBar(std::string label, std::uint64_t total, bool enabled)
    : m_label(std::move(label)), m_total(std::max<std::uint64_t>(total, 1)), m_enabled(enabled),
      m_start(Clock::now()), m_lastDraw(m_start) {}

ProgressBar::~ProgressBar() {
  try {
    finish();
  } catch (...) {
  }
}

std::string ProgressBar::format(const std::string& label, double fraction, double secondsLeft, bool knowEta) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  const int filled = int(std::floor(fraction * kBarWidth));
  std::string line = label + " [" + std::string(std::size_t(filled), '#') +
                     std::string(std::size_t(kBarWidth - filled), ' ') + "] ";
  char tail[64];
  const int percent = int(std::floor(fraction * 100.0));
  if (knowEta) std::snprintf(tail, sizeof(tail), "%3d%% %.1f s left", percent, std::max(0.0, secondsLeft));
  else std::snprintf(tail, sizeof(tail), "%3d%%", percent);
  return line + tail;
}

void ProgressBar::advance(std::uint64_t amount) {
  const std::uint64_t done = m_done.fetch_add(amount) + amount;
  if (!m_enabled) return;
  std::unique_lock lock(m_drawMutex, std::try_to_lock);
  if (!lock.owns_lock() || m_finished) return;
  const auto now = Clock::now();
  if (now - m_lastDraw < kRedrawInterval && done < m_total) return;
  m_lastDraw = now;
  draw(done);
}

void ProgressBar::draw(std::uint64_t done) {
  const double fraction = double(std::min(done, m_total)) / double(m_total);
  const double elapsed = std::chrono::duration<double>(Clock::now() - m_start).count();
  const bool knowEta = fraction > 0.0 && elapsed > 0.2;
  const double left = knowEta ? elapsed * (1.0 - fraction) / fraction : 0.0;
  // Pad with spaces so a shorter line fully covers the previous one.
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&.
  std::string line = "\r";
  line += format(m_label, fraction, left, knowEta);
  line += "   ";
  writeStderr(line);
  m_drawn = true;
  m_drawnDone = done;
}

void ProgressBar::finish() {
  if (!m_enabled) return;
  std::lock_guard lock(m_drawMutex);
  if (m_finished) return;
  m_finished = true;
  if (!m_drawn) return;
  if (m_drawnDone != m_done.load()) draw(m_done.load());
  writeStderr("\n");
}

} // namespace rtlab::reference
