#include "gl/shader_source.h"

#include "gl/shader_overlay.h"
#include "util/error.h"
#include "util/paths.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace rtlab::gl {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void shaderError(const std::string& msg) { throw Error(ExitCode::Shader, msg); }

// A shader file: its path relative to shaders/ when it is one of rtlab's (empty for a file given by
// an absolute path outside), and where its text comes from (the shaders/ tree or the overlay).
struct Located {
  std::string logical;
  std::string physical;               // read from here, named in errors, watched for reload
  const ShaderReplacement* replacement = nullptr;
};

Located locateLogical(const std::string& logical) {
  const auto& overlay = shaderOverlay();
  if (auto it = overlay.find(logical); it != overlay.end()) return {logical, it->second.path, &it->second};
  return {logical, fs::path(shaderPath(logical)).lexically_normal().string(), nullptr};
}

bool existsLogical(const std::string& logical) {
  return shaderOverlay().count(logical) != 0 || fs::exists(shaderPath(logical));
}

// `name` as written in #include (or the root path), resolved relative to the including file and
// then to shaders/.
Located resolvePath(const std::string& name, const Located* includer) {
  if (fs::path(name).is_absolute()) return {"", name, nullptr};
  if (includer && !includer->logical.empty()) {
    const std::string local = (fs::path(includer->logical).parent_path() / name).lexically_normal().generic_string();
    if (existsLogical(local)) return locateLogical(local);
  } else if (includer) {
    fs::path local = fs::path(includer->physical).parent_path() / name;
    if (fs::exists(local)) return {"", local.lexically_normal().string(), nullptr};
  }
  return locateLogical(fs::path(name).lexically_normal().generic_string());
}

bool readText(const Located& file, std::string& text) {
  if (file.replacement && file.replacement->inMemory) {
    text = file.replacement->text;
    return true;
  }
  std::ifstream in(file.physical, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  text = ss.str();
  return true;
}

struct Preprocessor {
  std::vector<std::string> files;
  std::vector<std::string> stack;
  std::ostringstream out;

  int fileIndex(const std::string& path) {
    for (std::size_t i = 0; i < files.size(); ++i)
      if (files[i] == path) return int(i);
    files.push_back(path);
    return int(files.size()) - 1;
  }

  void include(const Located& file, const std::string& fromFile, int fromLine, bool isRoot,
               const std::vector<std::string>& defines) {
    const std::string& path = file.physical;
    for (const auto& s : stack)
      if (s == path) shaderError(fromFile + ":" + std::to_string(fromLine) + ": #include cycle through '" + path + "'");
    std::string text;
    if (!readText(file, text)) {
      if (isRoot) shaderError("cannot read shader '" + path + "'");
      shaderError(fromFile + ":" + std::to_string(fromLine) + ": cannot open included file '" + path + "'");
    }
    std::istringstream in(text);
    stack.push_back(path);
    const int index = fileIndex(path);
    static const std::regex includeRe(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    std::string line;
    int lineNo = 0;
    bool sawVersion = !isRoot;
    if (!isRoot) out << "#line 1 " << index << "\n";
    while (std::getline(in, line)) {
      ++lineNo;
      std::smatch m;
      if (isRoot && !sawVersion) {
        if (line.rfind("#version", 0) != 0) shaderError(path + ":" + std::to_string(lineNo) + ": the first line must be #version");
        out << line << "\n";
        for (const auto& d : defines) out << "#define " << d << "\n";
        out << "#line " << lineNo + 1 << " " << index << "\n";
        sawVersion = true;
      } else if (std::regex_match(line, m, includeRe)) {
        const Located target = resolvePath(m[1].str(), &file);
        // A replacement (a student's file) reads only rtlab's shaders: nothing else on the
        // machine may end up in a compile error's message (docs/exercises.md "Safety").
        if (file.replacement && (target.logical.empty() || target.logical.rfind("..", 0) == 0))
          shaderError(path + ":" + std::to_string(lineNo) + ": an exercise file may include only files under shaders/ (not '" +
                      m[1].str() + "')");
        include(target, path, lineNo, false, defines);
        out << "#line " << lineNo + 1 << " " << index << "\n";
      } else {
        out << line << "\n";
      }
    }
    if (isRoot && !sawVersion) shaderError(path + ":1: empty shader, expected #version");
    stack.pop_back();
  }
};

} // namespace

ShaderSource loadShaderSource(const std::string& path, const std::vector<std::string>& defines) {
  Preprocessor pp;
  pp.include(resolvePath(path, nullptr), "", 0, true, defines);
  return ShaderSource{pp.out.str(), pp.files};
}

std::string mapInfoLog(const std::string& log, const std::vector<std::string>& files) {
  static const std::regex mesaRe(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
  static const std::regex nvRe(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
  std::istringstream in(log);
  std::ostringstream out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::smatch m;
    if (std::regex_match(line, m, mesaRe) || std::regex_match(line, m, nvRe)) {
      const std::size_t file = std::stoul(m[1].str());
      const std::string name = file < files.size() ? files[file] : "<source " + m[1].str() + ">";
      out << name << ":" << m[2].str() << ": " << m[3].str() << "\n";
    } else {
      out << line << "\n";
    }
  }
  return out.str();
}

} // namespace rtlab::gl
