// A small command-line parser: each command declares its options; anything else is a usage error
// (exit 2) naming the option and the command.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace rtlab {

struct OptionSpec {
  std::string name;       // "--scene"
  std::string alias;      // "-t" or ""
  bool takesValue = true;
  std::string valueName;  // "S", for help
  std::string help;
};

class Args {
public:
  // Parses argv[first..]; `--help`/`-h` sets help(). Error(Usage) for unknown options, a missing
  // value, or positionals beyond maxPositionals.
  // Messages name the invocation "<program> <command>" ("rtlab render"; a tool of its own passes
  // its program name and an empty command).
  Args(const std::string& command, const std::vector<OptionSpec>& specs, int argc, char** argv, int first,
       int maxPositionals = 0, const std::string& program = "rtlab");

  bool help() const { return m_help; }
  bool has(const std::string& name) const { return m_values.count(name) != 0; }
  // Last value given (options given twice: the last wins), or `fallback`.
  std::string get(const std::string& name, const std::string& fallback = "") const;
  const std::vector<std::string>& all(const std::string& name) const;
  const std::vector<std::string>& positionals() const { return m_positionals; }
  // Options in command-line order: (name, value).
  const std::vector<std::pair<std::string, std::string>>& ordered() const { return m_ordered; }

private:
  bool m_help = false;
  std::map<std::string, std::vector<std::string>> m_values;
  std::vector<std::pair<std::string, std::string>> m_ordered;
  std::vector<std::string> m_positionals;
};

// "Usage: ..." block with one line per option.
std::string formatHelp(const std::string& usage, const std::string& description, const std::vector<OptionSpec>& specs);

// Integer parsing for option values; Error(Usage) naming the option and the allowed range.
long long parseIntOption(const std::string& option, const std::string& text, long long min, long long max);
// A finite decimal number > 0; Error(Usage) naming the option otherwise.
double parsePositiveNumber(const std::string& option, const std::string& text);

} // namespace rtlab
