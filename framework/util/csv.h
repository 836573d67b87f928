// CSV output (RFC 4180): fields with a comma, quote, CR or LF are quoted, quotes doubled; lines
// end in "\n".
#pragma once
#include <string>
#include <vector>

namespace rtlab {

std::string csvField(const std::string& text);
std::string csvLine(const std::vector<std::string>& fields); // with the trailing "\n"

} // namespace rtlab
