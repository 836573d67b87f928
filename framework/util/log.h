// Minimal leveled logging to stderr. Errors for the user go through Error, not through here.
#pragma once
#include <string>

namespace rtlab {

enum class LogLevel { Debug = 0, Info = 1, Warn = 2, Quiet = 3 };

void setLogLevel(LogLevel level);
LogLevel logLevel();
void logDebug(const std::string& msg);
void logInfo(const std::string& msg);
void logWarn(const std::string& msg);

} // namespace rtlab
