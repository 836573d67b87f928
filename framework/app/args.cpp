#include "app/args.h"

#include "util/error.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

namespace rtlab {

Args::Args(const std::string& command, const std::vector<OptionSpec>& specs, int argc, char** argv, int first,
           int maxPositionals, const std::string& program) {
  const std::string invocation = command.empty() ? program : program + " " + command;
  for (int i = first; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      m_help = true;
      continue;
    }
    if (arg.size() > 1 && arg[0] == '-' && !(arg.size() > 1 && (std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.'))) {
      std::string value;
      bool inlineValue = false;
      if (arg.rfind("--", 0) == 0) {
        auto eq = arg.find('=');
        if (eq != std::string::npos) {
          value = arg.substr(eq + 1);
          arg = arg.substr(0, eq);
          inlineValue = true;
        }
      }
      const OptionSpec* spec = nullptr;
      for (const auto& s : specs)
        if (s.name == arg || (!s.alias.empty() && s.alias == arg)) spec = &s;
      if (!spec) usageError("unknown option '" + arg + "' for '" + invocation + "' (see '" + invocation + " --help')");
      if (spec->takesValue && !inlineValue) {
        if (i + 1 >= argc) usageError("option '" + arg + "' needs a value (" + spec->valueName + ")");
        value = argv[++i];
      } else if (!spec->takesValue && inlineValue) {
        usageError("option '" + arg + "' takes no value");
      }
      m_values[spec->name].push_back(value);
      m_ordered.emplace_back(spec->name, value);
      continue;
    }
    if (int(m_positionals.size()) >= maxPositionals)
      usageError("unexpected argument '" + arg + "' for '" + invocation + "' (see '" + invocation + " --help')");
    m_positionals.push_back(arg);
  }
}

std::string Args::get(const std::string& name, const std::string& fallback) const {
  auto it = m_values.find(name);
  return it == m_values.end() || it->second.empty() ? fallback : it->second.back();
}

const std::vector<std::string>& Args::all(const std::string& name) const {
  static const std::vector<std::string> kEmpty;
  auto it = m_values.find(name);
  return it == m_values.end() ? kEmpty : it->second;
}

std::string formatHelp(const std::string& usage, const std::string& description, const std::vector<OptionSpec>& specs) {
  std::ostringstream os;
  os << "Usage: " << usage << "\n\n" << description << "\n\nOptions:\n";
  for (const auto& s : specs) {
    std::string left = "  " + (s.alias.empty() ? "" : s.alias + ", ") + s.name + (s.takesValue ? " " + s.valueName : "");
    if (left.size() < 30) left.resize(30, ' ');
    else left += "  ";
    os << left << s.help << "\n";
  }
  os << "  -h, --help                  this help\n";
  return os.str();
}

long long parseIntOption(const std::string& option, const std::string& text, long long min, long long max) {
  long long v = 0;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || v < min || v > max)
    usageError("invalid value '" + text + "' for " + option + ": expected an integer in [" + std::to_string(min) + ", " +
               std::to_string(max) + "]");
  return v;
}

double parsePositiveNumber(const std::string& option, const std::string& text) {
  double v = 0.0;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v) || !(v > 0.0))
    usageError("invalid value '" + text + "' for " + option + ": expected a number > 0");
  return v;
}

} // namespace rtlab
