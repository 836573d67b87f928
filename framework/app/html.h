// Small helpers for the self-contained HTML pages rtlab writes (the showcase, sweep reports).
#pragma once
#include <string>
#include <vector>

namespace rtlab::html {

std::string escape(const std::string& text);
// A table with a header row; cells are escaped.
std::string table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
// A table whose cells are HTML already (the caller escapes their text): for cells holding images.
std::string tableHtml(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
// The page skeleton with rtlab's inline stylesheet.
std::string page(const std::string& title, const std::string& body);
// The same, with `extraCss` appended to the stylesheet.
std::string page(const std::string& title, const std::string& body, const std::string& extraCss);
std::string formatMs(double ms);
std::string formatBytes(std::size_t bytes);

} // namespace rtlab::html
