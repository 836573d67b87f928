// Numbers in user-facing text (error messages, `rtlab list`, help): the shortest decimal that
// reads back as the value (std::to_chars), so 0.1 prints "0.1", not "0.100000001" or "1e-01".
// A value that is exactly a float (a float widened to double, as parameter defaults and scene
// values are) prints as that float's shortest form: 0.1f prints "0.1", not "0.10000000149011612".
// Integral values print as integers ("100000", not "1e+05"). Locale-independent.
#pragma once
#include <string>

namespace rtlab {

std::string formatNumber(double value);
std::string formatNumber(float value);

// For text that is read back as data (sweep values, canonical parameter text): integral values as
// integers, every other value as the shortest text that reads back as exactly this double.
std::string formatNumberExact(double value);

} // namespace rtlab
