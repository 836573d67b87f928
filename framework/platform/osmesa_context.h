// OSMesa headless context (Mesa's off-screen gallium driver, llvmpipe): OpenGL 4.5 core, current
// with a small owned RGBA buffer; rtlab renders into its own framebuffer objects.
#pragma once
#include <memory>

#include "platform/context.h"

namespace rtlab {

// Creates the context, makes it current and loads GL. Throws Error(NoContext) with a short reason
// (one clause, no backend name) on failure.
std::unique_ptr<Context> createOsMesaContext();

} // namespace rtlab
