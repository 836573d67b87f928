#include "app/html.h"

#include <cstdio>

namespace rtlab::html {

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\'': out += "&#39;"; break;
    default: out += c;
    }
  }
  return out;
}

std::string table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::string s = "<table><thead><tr>";
  for (const auto& h : header) s += "<th>" + escape(h) + "</th>";
  s += "</tr></thead><tbody>";
  for (const auto& row : rows) {
    s += "<tr>";
    for (const auto& cell : row) s += "<td>" + escape(cell) + "</td>";
    s += "</tr>";
  }
  return s + "</tbody></table>";
}

std::string tableHtml(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::string s = "<table><thead><tr>";
  for (const auto& h : header) s += "<th>" + escape(h) + "</th>";
  s += "</tr></thead><tbody>";
  for (const auto& row : rows) {
    s += "<tr>";
    for (const auto& cell : row) s += "<td>" + cell + "</td>";
    s += "</tr>";
  }
  return s + "</tbody></table>";
}

std::string page(const std::string& title, const std::string& body) { return page(title, body, ""); }

std::string page(const std::string& title, const std::string& body, const std::string& extraCss) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + escape(title) +
         "</title>\n<style>\n"
         "body{font-family:system-ui,sans-serif;margin:2em;max-width:1200px;color:#222}\n"
         "h1{font-size:1.6em}h2{margin-top:2em;border-bottom:1px solid #ccc}\n"
         "table{border-collapse:collapse;margin:.5em 0;font-size:.9em}\n"
         "td,th{border:1px solid #ddd;padding:.2em .6em;text-align:left}th{background:#f3f3f3}\n"
         "figure{display:inline-block;margin:.5em}figcaption{font-size:.85em;color:#555}\n"
         "img{max-width:100%;image-rendering:auto;border:1px solid #ccc}\n"
         ".meta{color:#666;font-size:.9em}\n" +
         extraCss + "</style></head><body>\n" +
         body + "\n</body></html>\n";
}

std::string formatMs(double ms) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", ms);
  return buf;
}

std::string formatBytes(std::size_t bytes) {
  char buf[32];
  if (bytes >= (std::size_t(1) << 20)) std::snprintf(buf, sizeof buf, "%.1f MiB", double(bytes) / double(1 << 20));
  else if (bytes >= 1024) std::snprintf(buf, sizeof buf, "%.1f KiB", double(bytes) / 1024.0);
  else std::snprintf(buf, sizeof buf, "%zu B", bytes);
  return buf;
}

} // namespace rtlab::html
