// GL debug output (KHR_debug / core 4.3), the per-frame GL error counter and object labels.
// Every function needs a current context with the glad entry points loaded (Context::loadGl).
#pragma once
#include <string>

#include <glad/gl.h>

namespace rtlab {

// Enables debug output when the context has it (core 4.3 or GL_KHR_debug), synchronously, with a
// callback that logs errors as warnings and everything else (shader compiler output included) as
// debug messages. Notifications are dropped unless RTLAB_LOG=debug. Repeats of one message are
// logged a few times, then only counted.
// Called by Context::loadGl; calling it again (new context) is harmless.
void installDebugOutput();

// GL errors since the last call: drains glGetError (until GL_NO_ERROR) and adds the debug messages
// of type ERROR received since the last call. API errors are reported both ways, so they are
// counted once (the larger of the two counts); errors from other sources are added. Shader
// compiler messages are not counted (the program's own log reports a failed compile or link).
// Meant to be called once per frame: one counter per frame.
int drainGlErrors();

// glObjectLabel when available (names the object in debuggers and in debug messages); a label
// longer than GL_MAX_LABEL_LENGTH is truncated. Does nothing without KHR_debug.
void setObjectLabel(GLenum identifier, GLuint name, const std::string& label);

// "GL_INVALID_ENUM", ... or the number in hex for an unknown code.
std::string glErrorName(GLenum error);

} // namespace rtlab
