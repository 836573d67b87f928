#include "exercise/regions.h"

#include "util/error.h"

#include <regex>
#include <sstream>

namespace rtlab {

const char* const kStubNotice =
    "// Stub: a neutral value so that the program compiles and runs. Replace it with your code.";

namespace {

enum class LineKind { Code, Begin, Task, Stub, End };

struct Line {
  LineKind kind = LineKind::Code;
  std::string text;   // the whole line
  std::string indent; // leading white space
  std::string arg;    // region name (Begin) or task text (Task)
};

Line classify(const std::string& text, const std::string& file, int lineNo) {
  static const std::regex beginRe(R"(^(\s*)// exercise\(([a-z0-9_]+(?:-[a-z0-9_]+)*)\): begin\s*$)");
  static const std::regex taskRe(R"(^(\s*)// task:(?: (.*))?$)");
  static const std::regex stubRe(R"(^(\s*)// exercise: stub\s*$)");
  static const std::regex endRe(R"(^(\s*)// exercise: end\s*$)");
  Line line;
  line.text = text;
  std::smatch m;
  if (std::regex_match(text, m, beginRe)) {
    line = {LineKind::Begin, text, m[1].str(), m[2].str()};
  } else if (std::regex_match(text, m, taskRe)) {
    line = {LineKind::Task, text, m[1].str(), m[2].str()};
  } else if (std::regex_match(text, m, stubRe)) {
    line = {LineKind::Stub, text, m[1].str(), ""};
  } else if (std::regex_match(text, m, endRe)) {
    line = {LineKind::End, text, m[1].str(), ""};
  } else if (text.find("exercise(") != std::string::npos || text.find("// exercise:") != std::string::npos) {
    inputError(file + ":" + std::to_string(lineNo) + ": malformed exercise marker '" + text +
               "' (expected '// exercise(NAME): begin', '// exercise: stub' or '// exercise: end')");
  }
  return line;
}

// "<indent>// code" -> "<indent>code"; "<indent>//" -> "". Anything else is not a stub line.
bool uncomment(const std::string& text, std::string& code) {
  static const std::regex stubLineRe(R"(^(\s*)//(?: (.*))?$)");
  std::smatch m;
  if (!std::regex_match(text, m, stubLineRe)) return false;
  code = m[2].matched ? m[1].str() + m[2].str() : "";
  return true;
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

// Walks a file's lines through the region grammar, calling back per region; returns the regions.
struct Walk {
  std::vector<ExerciseRegion> regions;
  std::vector<Line> lines;
};

Walk walk(const std::string& text, const std::string& file, bool student) {
  Walk w;
  const auto raw = splitLines(text);
  enum class State { Outside, Task, Solution, Stub } state = State::Outside;
  ExerciseRegion current;
  auto where = [&](int lineNo) { return file + ":" + std::to_string(lineNo) + ": "; };
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const int lineNo = int(i) + 1;
    Line line = classify(raw[i], file, lineNo);
    switch (line.kind) {
    case LineKind::Begin:
      if (state != State::Outside)
        inputError(where(lineNo) + "exercise region '" + line.arg + "' begins inside region '" + current.name +
                   "' (line " + std::to_string(current.beginLine) + "); regions do not nest");
      current = ExerciseRegion{};
      current.name = line.arg;
      current.beginLine = lineNo;
      state = State::Task;
      break;
    case LineKind::Task:
      if (state != State::Task)
        inputError(where(lineNo) + "a '// task:' line belongs right after '// exercise(NAME): begin'");
      current.task.push_back(line.arg);
      break;
    case LineKind::Stub:
      if (state == State::Outside) inputError(where(lineNo) + "'// exercise: stub' outside a region");
      if (state == State::Task) {
        if (current.task.empty()) inputError(where(current.beginLine) + "region '" + current.name + "' has no '// task:' line");
        inputError(where(lineNo) + "region '" + current.name + "' has no solution lines before its stub");
      }
      if (state == State::Stub) inputError(where(lineNo) + "region '" + current.name + "' has two '// exercise: stub' lines");
      state = State::Stub;
      break;
    case LineKind::End:
      if (state == State::Outside) inputError(where(lineNo) + "'// exercise: end' without a region");
      if (state == State::Task && current.task.empty())
        inputError(where(current.beginLine) + "region '" + current.name + "' has no '// task:' line");
      if (state != State::Stub && !student)
        inputError(where(lineNo) + "region '" + current.name + "' ends without '// exercise: stub' (every region needs a stub)");
      current.endLine = lineNo;
      w.regions.push_back(std::move(current));
      current = ExerciseRegion{};
      state = State::Outside;
      break;
    case LineKind::Code:
      if (state == State::Task) {
        if (current.task.empty()) inputError(where(current.beginLine) + "region '" + current.name + "' has no '// task:' line");
        state = State::Solution;
      }
      if (state == State::Solution) {
        current.solution.push_back(line.text);
      } else if (state == State::Stub) {
        std::string code;
        if (!uncomment(line.text, code))
          inputError(where(lineNo) + "stub line of region '" + current.name + "' must be a comment ('// code')");
        current.stub.push_back(code);
      }
      break;
    }
    w.lines.push_back(std::move(line));
  }
  if (state != State::Outside)
    inputError(where(current.beginLine) + "exercise region '" + current.name + "' has no '// exercise: end'");
  return w;
}

} // namespace

std::vector<ExerciseRegion> parseExerciseRegions(const std::string& text, const std::string& file, bool student) {
  return walk(text, file, student).regions;
}

std::string studentCopy(const std::string& text, const std::string& file, const std::set<std::string>& chosen) {
  const Walk w = walk(text, file, false);
  std::ostringstream out;
  std::size_t next = 0; // index of the next region in w.regions
  for (std::size_t i = 0; i < w.lines.size(); ++i) {
    const int lineNo = int(i) + 1;
    if (next >= w.regions.size() || lineNo < w.regions[next].beginLine) {
      out << w.lines[i].text << "\n";
      continue;
    }
    const ExerciseRegion& region = w.regions[next];
    if (chosen.count(region.name)) {
      const std::string& indent = w.lines[i].indent;
      out << w.lines[i].text << "\n";
      for (std::size_t t = 0; t < region.task.size(); ++t) out << w.lines[i + 1 + t].text << "\n";
      out << indent << kStubNotice << "\n";
      for (const auto& code : region.stub) out << code << "\n";
      out << w.lines[std::size_t(region.endLine) - 1].text << "\n";
    } else {
      for (const auto& line : region.solution) out << line << "\n";
    }
    i = std::size_t(region.endLine) - 1;
    ++next;
  }
  return out.str();
}

} // namespace rtlab
