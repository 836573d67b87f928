// GLFW window context (the `view` command): OpenGL 4.5 core, forward compatible, vsync on.
#pragma once
#include <memory>
#include <string>

#include "platform/context.h"

namespace rtlab {

// Opens a window of the given size, makes its context current and loads GL. Throws
// Error(NoContext) when there is no usable display or the window system gives no GL 4.5 core.
std::unique_ptr<Context> createGlfwContext(int width, int height, const std::string& title);

} // namespace rtlab
