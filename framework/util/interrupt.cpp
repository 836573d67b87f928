#include "util/interrupt.h"

#include "util/atomic_file.h"
#include "util/error.h"

#include <unistd.h>

#include <csignal>

namespace rtlab {
namespace {

void onInterrupt(int) {
  removeTemporaries();
  static const char kMsg[] = "rtlab: error: interrupted\n";
  [[maybe_unused]] auto n = ::write(2, kMsg, sizeof(kMsg) - 1);
  ::_exit(int(ExitCode::Interrupted));
}

} // namespace

void installInterruptHandler() {
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
}

} // namespace rtlab
