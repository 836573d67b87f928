// The axes and the grid of a parameter sweep (`rtlab sweep --vary KEY=SPEC`, docs/sweeps.md).
// GL-free and independent of the technique registry, so the rules are unit-tested on plain data.
//
// SPEC is a list of values, `V1,V2,...` (vec3 and color: `x,y,z;x,y,z;...`), or, for float and
// int keys, `LO:HI:N`: N >= 2 values from LO to HI, spaced linearly or logarithmically by the
// key's declared scale (log needs LO, HI > 0). Every value is checked against the key's range
// (never clamped). Generated floats are rounded to 6 significant digits (the ends stay exact),
// ints to the nearest integer; duplicates are removed, keeping the first.
#pragma once
#include "params/param_spec.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace rtlab {

struct SweepAxis {
  std::string key;
  std::string spec;                // as given
  std::vector<std::string> values; // canonical texts: parseParamValue() reads each back exactly
};

// "KEY=SPEC" -> {KEY, SPEC}. Error(Usage) when '=' is missing or either side is empty.
std::pair<std::string, std::string> splitVaryArgument(const std::string& text);

// The values of one axis, as canonical texts. Error(Usage) naming the key, and its range for a
// value outside it.
std::vector<std::string> expandSweepValues(const ParamSpec& spec, const std::string& text);

// The text that reads back as exactly `value`: floats in the shortest exact decimal form, ints
// as integers, bools true|false, enums by name, vec3/color as x,y,z.
std::string canonicalParamText(const ParamSpec& spec, const ParamValue& value);

struct SweepTechnique {
  std::string id, stage;
};

// Whether varying `key` can change a frame with this technique: keys of its stage, its own
// "<id>." keys, and the frame-wide prefixes tonemap., light<N>. and camera.
bool sweepKeyApplies(const std::string& key, const SweepTechnique& technique);

// "light<N>." with N decimal digits.
bool isLightKey(const std::string& key);

struct SweepGridPoint {
  std::string technique;
  std::vector<std::pair<std::string, std::string>> values; // (key, text) of the axes that apply, in axis order
};

// For each technique in order, the cross product of the axes that apply to it (first axis
// outermost). Error(Usage) when an axis applies to none of the techniques, a key is given twice,
// or the grid has more than maxPoints points.
std::vector<SweepGridPoint> buildSweepGrid(const std::vector<SweepTechnique>& techniques,
                                           const std::vector<SweepAxis>& axes, std::size_t maxPoints = 100000);

} // namespace rtlab
