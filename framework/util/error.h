// Errors that reach the user: one line, one exit code (docs/contract.md "Exit codes").
#pragma once
#include <stdexcept>
#include <string>

namespace rtlab {

enum class ExitCode : int {
  Ok = 0,
  Internal = 1,
  Usage = 2,        // unknown command/option/technique/key/scene/AOV, bad syntax, out of range
  Input = 3,        // input file missing, unreadable or invalid; compare size mismatch
  NoContext = 4,    // no GL context; view without display
  Shader = 5,       // shader compile or link failure
  Output = 6,       // output file could not be written
  Interrupted = 130 // SIGINT
};

// A message is one line even where it quotes the user's text: a newline or another control
// character in a key, an id or a file name (fuzzing found a script action named "\nbookmark",
// docs/testing.md "Fuzzing") is written as an escape: \n, \r, \t, \x1b.
inline std::string oneLineMessage(const std::string& text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u != 0x7f) out += c;
    else if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else (out += "\\x") += {kHex[u >> 4], kHex[u & 15]};
  }
  return out;
}

// Thrown for every user-facing failure. what() is the message without the "rtlab: error: " prefix,
// on one line (oneLineMessage).
class Error : public std::runtime_error {
public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(oneLineMessage(message)), m_code(code) {}
  ExitCode code() const { return m_code; }

private:
  ExitCode m_code;
};

[[noreturn]] inline void usageError(const std::string& msg) { throw Error(ExitCode::Usage, msg); }
[[noreturn]] inline void inputError(const std::string& msg) { throw Error(ExitCode::Input, msg); }
[[noreturn]] inline void outputError(const std::string& msg) { throw Error(ExitCode::Output, msg); }

} // namespace rtlab
