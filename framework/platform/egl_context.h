// EGL headless context: the surfaceless platform (Mesa) or the device platform (one EGLDevice, for
// headless GPU nodes), OpenGL 4.5 core, current without a surface. rtlab renders into its own FBOs.
#pragma once
#include <memory>

#include "platform/context.h"

namespace rtlab {

enum class EglPlatform { Surfaceless, Device };

// Creates the context, makes it current and loads GL. Device tries every enumerated device and
// keeps the first that works. Throws Error(NoContext) with a short reason (one clause, no backend
// name) when the platform gives no OpenGL 4.5 core context.
std::unique_ptr<Context> createEglContext(EglPlatform platform);

} // namespace rtlab
