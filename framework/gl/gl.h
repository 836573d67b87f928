// The one include for GL: glad's generated 4.5 core loader (generated at build time, cmake/glad.cmake).
#pragma once
#include <glad/gl.h>
