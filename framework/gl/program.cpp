#include "gl/program.h"

#include "gl/shader_source.h"
#include "util/error.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <sstream>

namespace rtlab::gl {
namespace {

GLenum stageFromPath(const std::string& path) {
  auto ends = [&](const char* ext) {
    const std::string e(ext);
    return path.size() >= e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0;
  };
  if (ends(".vert")) return GL_VERTEX_SHADER;
  if (ends(".frag")) return GL_FRAGMENT_SHADER;
  if (ends(".geom")) return GL_GEOMETRY_SHADER;
  if (ends(".comp")) return GL_COMPUTE_SHADER;
  throw Error(ExitCode::Shader, "cannot tell the shader stage of '" + path + "' (use .vert .frag .geom .comp)");
}

std::string firstLine(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.find("error") != std::string::npos) return line;
  in.clear();
  in.str(text);
  std::getline(in, line);
  return line;
}

} // namespace

std::string ProgramDesc::key() const {
  std::string k;
  for (const auto& s : stages) k += s + "|";
  k += "#";
  for (const auto& d : defines) k += d + ";";
  return k;
}

Program::Program(const ProgramDesc& desc) : m_desc(desc), m_handle(desc.label.empty() ? desc.key() : desc.label) {
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint s : shaders) glDeleteShader(s);
  };
  std::vector<std::string> allFiles;
  for (const auto& path : desc.stages) {
    ShaderSource src;
    GLuint shader = 0;
    try {
      src = loadShaderSource(path, desc.defines);
      shader = glCreateShader(stageFromPath(path));
    } catch (...) {
      cleanup();
      throw;
    }
    shaders.push_back(shader);
    const char* text = src.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      GLint len = 0;
      glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
      std::string log(std::size_t(std::max(len, 1)), '\0');
      glGetShaderInfoLog(shader, len, nullptr, log.data());
      cleanup();
      const std::string mapped = mapInfoLog(log.c_str(), src.files);
      throw Error(ExitCode::Shader, "shader compile failed: " + firstLine(mapped));
    }
    glAttachShader(m_handle.id(), shader);
    for (const auto& f : src.files) allFiles.push_back(f);
  }
  glLinkProgram(m_handle.id());
  cleanup();
  GLint ok = GL_FALSE;
  glGetProgramiv(m_handle.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(m_handle.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(std::size_t(std::max(len, 1)), '\0');
    glGetProgramInfoLog(m_handle.id(), len, nullptr, log.data());
    std::string files;
    for (const auto& s : desc.stages) files += (files.empty() ? "" : " + ") + s;
    throw Error(ExitCode::Shader, "shader link failed (" + files + "): " + firstLine(log.c_str()));
  }
  GLint count = 0, maxLen = 0;
  glGetProgramiv(m_handle.id(), GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(m_handle.id(), GL_ACTIVE_UNIFORM_MAX_LENGTH, &maxLen);
  std::string name(std::size_t(std::max(maxLen, 1)), '\0');
  for (GLint i = 0; i < count; ++i) {
    GLsizei len = 0;
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(m_handle.id(), GLuint(i), maxLen, &len, &size, &type, name.data());
    std::string n(name.data(), std::size_t(len));
    GLint loc = glGetUniformLocation(m_handle.id(), n.c_str());
    if (loc < 0) continue; // block members
    m_locations[n] = loc;
    if (n.size() > 3 && n.compare(n.size() - 3, 3, "[0]") == 0) m_locations[n.substr(0, n.size() - 3)] = loc;
  }
  for (const auto& f : allFiles) {
    std::error_code ec;
    m_sources.emplace_back(f, std::filesystem::last_write_time(f, ec));
  }
}

GLint Program::location(const std::string& name) const {
  auto it = m_locations.find(name);
  return it == m_locations.end() ? -1 : it->second;
}

Program& Program::set(const std::string& n, float v) { glProgramUniform1f(id(), location(n), v); return *this; }
Program& Program::set(const std::string& n, int v) { glProgramUniform1i(id(), location(n), v); return *this; }
Program& Program::set(const std::string& n, const glm::vec2& v) { glProgramUniform2fv(id(), location(n), 1, glm::value_ptr(v)); return *this; }
Program& Program::set(const std::string& n, const glm::vec3& v) { glProgramUniform3fv(id(), location(n), 1, glm::value_ptr(v)); return *this; }
Program& Program::set(const std::string& n, const glm::vec4& v) { glProgramUniform4fv(id(), location(n), 1, glm::value_ptr(v)); return *this; }
Program& Program::set(const std::string& n, const glm::ivec2& v) { glProgramUniform2iv(id(), location(n), 1, glm::value_ptr(v)); return *this; }
Program& Program::set(const std::string& n, const glm::ivec3& v) { glProgramUniform3iv(id(), location(n), 1, glm::value_ptr(v)); return *this; }
Program& Program::set(const std::string& n, const glm::ivec4& v) { glProgramUniform4iv(id(), location(n), 1, glm::value_ptr(v)); return *this; }
Program& Program::set(const std::string& n, unsigned v) { glProgramUniform1ui(id(), location(n), v); return *this; }
Program& Program::set(const std::string& n, const glm::uvec2& v) { glProgramUniform2uiv(id(), location(n), 1, glm::value_ptr(v)); return *this; }
Program& Program::set(const std::string& n, const glm::uvec3& v) { glProgramUniform3uiv(id(), location(n), 1, glm::value_ptr(v)); return *this; }
Program& Program::set(const std::string& n, const glm::uvec4& v) { glProgramUniform4uiv(id(), location(n), 1, glm::value_ptr(v)); return *this; }
Program& Program::set(const std::string& n, const glm::mat3& v) { glProgramUniformMatrix3fv(id(), location(n), 1, GL_FALSE, glm::value_ptr(v)); return *this; }
Program& Program::set(const std::string& n, const glm::mat4& v) { glProgramUniformMatrix4fv(id(), location(n), 1, GL_FALSE, glm::value_ptr(v)); return *this; }

Program& Program::set(const std::string& n, const std::vector<float>& v) {
  if (!v.empty()) glProgramUniform1fv(id(), location(n), GLsizei(v.size()), v.data());
  return *this;
}

Program& Program::set(const std::string& n, const std::vector<int>& v) {
  if (!v.empty()) glProgramUniform1iv(id(), location(n), GLsizei(v.size()), v.data());
  return *this;
}

Program& Program::set(const std::string& n, const std::vector<glm::vec2>& v) {
  if (!v.empty()) glProgramUniform2fv(id(), location(n), GLsizei(v.size()), glm::value_ptr(v.front()));
  return *this;
}

Program& Program::set(const std::string& n, const std::vector<glm::vec3>& v) {
  if (!v.empty()) glProgramUniform3fv(id(), location(n), GLsizei(v.size()), glm::value_ptr(v.front()));
  return *this;
}

Program& Program::set(const std::string& n, const std::vector<glm::vec4>& v) {
  if (!v.empty()) glProgramUniform4fv(id(), location(n), GLsizei(v.size()), glm::value_ptr(v.front()));
  return *this;
}

Program& Program::set(const std::string& n, const std::vector<glm::ivec3>& v) {
  if (!v.empty()) glProgramUniform3iv(id(), location(n), GLsizei(v.size()), glm::value_ptr(v.front()));
  return *this;
}

Program& Program::set(const std::string& n, const std::vector<glm::mat4>& v) {
  if (!v.empty()) glProgramUniformMatrix4fv(id(), location(n), GLsizei(v.size()), GL_FALSE, glm::value_ptr(v.front()));
  return *this;
}

glm::ivec3 Program::workGroupSize() const {
  const bool compute = std::any_of(m_desc.stages.begin(), m_desc.stages.end(), [](const std::string& s) {
    return s.size() > 5 && s.compare(s.size() - 5, 5, ".comp") == 0;
  });
  if (!compute) throw Error(ExitCode::Internal, "program '" + m_desc.key() + "' is not a compute program");
  GLint size[3] = {1, 1, 1};
  glGetProgramiv(id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
  return glm::ivec3(size[0], size[1], size[2]);
}

std::vector<std::filesystem::file_time_type> Program::sourceTimesNow() const {
  std::vector<std::filesystem::file_time_type> times;
  for (const auto& [path, time] : m_sources) {
    std::error_code ec;
    times.push_back(std::filesystem::last_write_time(path, ec));
  }
  return times;
}

bool Program::sourcesChanged() const {
  for (const auto& [path, time] : m_sources) {
    std::error_code ec;
    if (std::filesystem::last_write_time(path, ec) != time) return true;
  }
  return false;
}

} // namespace rtlab::gl
