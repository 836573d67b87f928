// GL debug output (KHR_debug / core 4.3), the per-frame GL error counter, the process-wide GL
// error total and object labels (docs/architecture.md "GL errors", docs/testing.md "GL errors").
// installDebugOutput, drainGlErrors and setObjectLabel need a current context with the glad entry
// points loaded (Context::loadGl); glErrorTotal, glErrorMessagesSince and appendGlErrorReport do not.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glad/gl.h>

namespace rtlab {

// Enables debug output when the context has it (core 4.3 or GL_KHR_debug), synchronously, with a
// callback that logs errors as warnings and everything else (shader compiler output included) as
// debug messages. Notifications are dropped unless RTLAB_LOG=debug. Repeats of one message are
// logged a few times, then only counted.
// Called by Context::loadGl; calling it again (new context) is harmless. Errors the new context
// already has are added to the process total (glErrorTotal), not to the next frame's count.
void installDebugOutput();

// GL errors since the last call: drains glGetError (until GL_NO_ERROR) and adds the debug messages
// of type ERROR received since the last call. API errors are reported both ways, so they are
// counted once (the larger of the two counts); errors from other sources are added. Shader
// compiler messages are not counted (the program's own log reports a failed compile or link).
// Meant to be called once per frame: one counter per frame. What it returns is already in the
// process total (draining never drops an error from glErrorTotal).
int drainGlErrors();

// Every GL error this process has counted, on every context it made, inside frames or not (set-up,
// upload, read-back, teardown): each debug message of type ERROR as it arrives (synchronous
// output: inside the call that caused it), plus each glGetError result no debug message reported
// (found by drainGlErrors), so an API error reported both ways is counted once. Never reset.
std::int64_t glErrorTotal();

// The texts of the errors counted after the total was `mark` (at most the last 64 kept), oldest
// first: "GL api error: <driver's message>" or "glGetError: GL_INVALID_ENUM (no debug message)".
std::vector<std::string> glErrorMessagesSince(std::int64_t mark);

// Appends this process's report to `path`: a line "gl_errors: N <who>" (N = glErrorTotal()), then
// the kept messages, each on a line starting with two spaces. Returns false when the file cannot
// be written. The format is docs/contract.md "GL error report".
bool appendGlErrorReport(const std::string& path, const std::string& who);

// glObjectLabel when available (names the object in debuggers and in debug messages); a label
// longer than GL_MAX_LABEL_LENGTH is truncated. Does nothing without KHR_debug.
void setObjectLabel(GLenum identifier, GLuint name, const std::string& label);

// "GL_INVALID_ENUM", ... or the number in hex for an unknown code.
std::string glErrorName(GLenum error);

} // namespace rtlab
