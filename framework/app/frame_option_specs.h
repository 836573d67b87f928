// The scene and frame options shared by render, reference, sweep and view (docs/contract.md), as
// a table, and the parsers of their values that need no scene or GL: GL-free, so that rtlab_core
// (and the command-line fuzz target, tests/fuzz/cli.cpp) has them. frame_options.h resolves them.
#pragma once
#include "app/args.h"

#include <string>
#include <vector>

namespace rtlab {

std::vector<OptionSpec> frameOptionSpecs();

// "640x360" -> width, height in 1..8192; Error(Usage) otherwise.
void parseSize(const std::string& text, int& width, int& height);

} // namespace rtlab
