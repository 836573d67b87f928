// The one include for GL: glad's generated 4.5 core loader (built at configure time).
#pragma once
#include <glad/gl.h>
