#include "gl/debug.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <deque>
#include <map>
#include <mutex>
#include <tuple>

#include "util/log.h"

namespace rtlab {
namespace {

constexpr int kMaxRepeats = 3;        // times one message is logged before it is only counted
constexpr int kMaxErrorDrain = 1024;  // guards against a driver that never returns GL_NO_ERROR
constexpr size_t kKeptMessages = 64;  // error texts kept for glErrorMessagesSince

// Since the last drainGlErrors (the per-frame counter):
std::atomic<int> g_apiErrors{0};   // debug messages of type ERROR from GL_DEBUG_SOURCE_API
std::atomic<int> g_otherErrors{0}; // debug messages of type ERROR from any other source
// Since the process started, never reset (glErrorTotal).
std::atomic<std::int64_t> g_total{0};
bool g_debugOutput = false;        // the callback is installed on the current context
GLint g_maxLabelLength = 0;

std::mutex g_repeatMutex;
std::map<std::tuple<GLenum, GLenum, GLuint>, int> g_repeats;

// The last kKeptMessages errors: (the total once this error was counted, its text).
std::mutex g_messageMutex;
std::deque<std::pair<std::int64_t, std::string>> g_messages;

// Adds one error to the process total and keeps its text.
void countError(std::string text) {
  const std::int64_t n = g_total.fetch_add(1) + 1;
  std::lock_guard<std::mutex> lock(g_messageMutex);
  g_messages.emplace_back(n, std::move(text));
  if (g_messages.size() > kKeptMessages) g_messages.pop_front();
}

bool hasDebugApi() {
  return (GLAD_GL_VERSION_4_3 || GLAD_GL_KHR_debug) && glDebugMessageCallback && glObjectLabel;
}

const char* sourceName(GLenum source) {
  switch (source) {
  case GL_DEBUG_SOURCE_API: return "api";
  case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
  case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
  case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
  case GL_DEBUG_SOURCE_APPLICATION: return "application";
  default: return "other";
  }
}

const char* typeName(GLenum type) {
  switch (type) {
  case GL_DEBUG_TYPE_ERROR: return "error";
  case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
  case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behavior";
  case GL_DEBUG_TYPE_PORTABILITY: return "portability";
  case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
  case GL_DEBUG_TYPE_MARKER: return "marker";
  default: return "other";
  }
}

// Counts every ERROR; logs a message at most kMaxRepeats times (a per-frame error would otherwise
// flood the console).
void GLAD_API_PTR onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                                 GLsizei length, const GLchar* message, const void* /*user*/) {
  if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP) return;
  // A failed compile or link is not a GL error: the program's own log reports it (file:line), and
  // a failed hot reload must not count as an error of the frame.
  const bool isError = type == GL_DEBUG_TYPE_ERROR && source != GL_DEBUG_SOURCE_SHADER_COMPILER;
  const bool debugLog = logLevel() == LogLevel::Debug;
  if (!isError && !debugLog) return;
  std::string text = length >= 0 ? std::string(message, static_cast<size_t>(length)) : message;
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::string line = std::string("GL ") + sourceName(source) + " " + typeName(type) + ": " + text;
  if (isError) {
    (source == GL_DEBUG_SOURCE_API ? g_apiErrors : g_otherErrors).fetch_add(1);
    countError(line); // counted and kept even when the log below drops it
  }
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION && !debugLog) return;

  int seen = 0;
  {
    std::lock_guard<std::mutex> lock(g_repeatMutex);
    seen = ++g_repeats[{source, type, id}];
  }
  if (seen > kMaxRepeats) return;
  if (seen == kMaxRepeats) line += " (further repeats are counted, not logged)";
  if (isError)
    logWarn(line);
  else
    logDebug(line);
}

} // namespace

std::string glErrorName(GLenum error) {
  switch (error) {
  case GL_NO_ERROR: return "GL_NO_ERROR";
  case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
  case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
  case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
  case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
  case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
  case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
  case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
  case GL_CONTEXT_LOST: return "GL_CONTEXT_LOST";
  default: {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04X", error);
    return buf;
  }
  }
}

void installDebugOutput() {
  // Errors left on the previous context are in the total already; the frame counter starts afresh.
  g_debugOutput = false;
  g_maxLabelLength = 0;
  g_apiErrors = 0;
  g_otherErrors = 0;
  {
    std::lock_guard<std::mutex> lock(g_repeatMutex);
    g_repeats.clear();
  }
  if (!hasDebugApi()) {
    logDebug("GL debug output unavailable (no KHR_debug); errors are counted with glGetError only");
    drainGlErrors(); // the context's errors so far: in the total, not in the first frame
    return;
  }
  glGetIntegerv(GL_MAX_LABEL_LENGTH, &g_maxLabelLength);
  glEnable(GL_DEBUG_OUTPUT);
  // Synchronous: a message arrives inside the call that caused it, so it is counted in that frame.
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onDebugMessage, nullptr);
  const GLboolean notifications = logLevel() == LogLevel::Debug ? GL_TRUE : GL_FALSE;
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr,
                        notifications);
  glDebugMessageControl(GL_DONT_CARE, GL_DEBUG_TYPE_PUSH_GROUP, GL_DONT_CARE, 0, nullptr, GL_FALSE);
  glDebugMessageControl(GL_DONT_CARE, GL_DEBUG_TYPE_POP_GROUP, GL_DONT_CARE, 0, nullptr, GL_FALSE);
  g_debugOutput = true;
  // Errors made before the callback was installed (context creation, the calls above) are found by
  // glGetError: they count in the process total, not in the first frame.
  drainGlErrors();
}

int drainGlErrors() {
  std::vector<GLenum> codes;
  for (GLenum e = glGetError(); e != GL_NO_ERROR && int(codes.size()) < kMaxErrorDrain; e = glGetError()) {
    codes.push_back(e);
    // With debug output on, the callback has already logged the message with its text.
    if (g_debugOutput)
      logDebug("glGetError: " + glErrorName(e));
    else
      logWarn("GL error " + glErrorName(e));
    if (e == GL_CONTEXT_LOST) break;
  }
  const int api = g_apiErrors.exchange(0);
  const int other = g_otherErrors.exchange(0);
  // One API error is reported both by glGetError and by a debug message; glGetError keeps only the
  // first of several, the callback sees all of them (and has counted them in the total already).
  const int polled = int(codes.size());
  const int unreported = std::max(polled - api, 0);
  for (int i = polled - unreported; i < polled; ++i)
    countError("glGetError: " + glErrorName(codes[size_t(i)]) + " (no debug message)");
  return api + unreported + other;
}

std::int64_t glErrorTotal() { return g_total.load(); }

std::vector<std::string> glErrorMessagesSince(std::int64_t mark) {
  std::vector<std::string> texts;
  std::lock_guard<std::mutex> lock(g_messageMutex);
  for (const auto& [n, text] : g_messages)
    if (n > mark) texts.push_back(text);
  return texts;
}

bool appendGlErrorReport(const std::string& path, const std::string& who) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) return false;
  std::string report = "gl_errors: " + std::to_string(glErrorTotal()) + " " + who + "\n";
  for (const std::string& text : glErrorMessagesSince(0)) report += "  " + text + "\n";
  // One append of the whole report, so that reports of processes appending at once do not interleave.
  const bool written = write(fd, report.data(), report.size()) == static_cast<ssize_t>(report.size());
  return close(fd) == 0 && written;
}

void setObjectLabel(GLenum identifier, GLuint name, const std::string& label) {
  if (!hasDebugApi() || name == 0) return;
  if (g_maxLabelLength <= 0) glGetIntegerv(GL_MAX_LABEL_LENGTH, &g_maxLabelLength);
  const size_t maxChars = g_maxLabelLength > 1 ? static_cast<size_t>(g_maxLabelLength - 1) : 0;
  const size_t n = std::min(label.size(), maxChars);
  glObjectLabel(identifier, name, static_cast<GLsizei>(n), label.data());
}

} // namespace rtlab
