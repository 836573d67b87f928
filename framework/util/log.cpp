#include "util/log.h"

#include <cstdio>
#include <cstdlib>

namespace rtlab {
namespace {
LogLevel initialLevel() {
  const char* env = std::getenv("RTLAB_LOG");
  if (!env) return LogLevel::Warn;
  std::string v(env);
  if (v == "debug") return LogLevel::Debug;
  if (v == "info") return LogLevel::Info;
  if (v == "quiet") return LogLevel::Quiet;
  return LogLevel::Warn;
}
LogLevel g_level = initialLevel();

void emit(LogLevel level, const char* tag, const std::string& msg) {
  if (level < g_level) return;
  std::fprintf(stderr, "rtlab: %s: %s\n", tag, msg.c_str());
}
} // namespace

void setLogLevel(LogLevel level) { g_level = level; }
LogLevel logLevel() { return g_level; }
void logDebug(const std::string& msg) { emit(LogLevel::Debug, "debug", msg); }
void logInfo(const std::string& msg) { emit(LogLevel::Info, "info", msg); }
void logWarn(const std::string& msg) { emit(LogLevel::Warn, "warning", msg); }

} // namespace rtlab
