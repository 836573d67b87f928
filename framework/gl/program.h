// A linked GLSL program built from files under shaders/, with every active uniform's location
// looked up once at link time. Compile and link errors are Error(Shader) as "file:line: message".
#pragma once
#include "gl/objects.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace rtlab::gl {

struct ProgramDesc {
  std::vector<std::string> stages;   // files relative to shaders/; stage from the extension (.vert .frag .geom .comp)
  std::vector<std::string> defines;  // "NAME VALUE"
  std::string label;
  std::string key() const;
};

class Program {
public:
  Program() = default;
  explicit Program(const ProgramDesc& desc); // throws Error(Shader)

  GLuint id() const { return m_handle.id(); }
  void use() const { glUseProgram(m_handle.id()); }
  const ProgramDesc& desc() const { return m_desc; }

  // -1 when the uniform is not active (optimized out): setters then do nothing, as GL would.
  GLint location(const std::string& name) const;
  Program& set(const std::string& name, float v);
  Program& set(const std::string& name, int v);
  Program& set(const std::string& name, bool v) { return set(name, v ? 1 : 0); }
  Program& set(const std::string& name, const glm::vec2& v);
  Program& set(const std::string& name, const glm::vec3& v);
  Program& set(const std::string& name, const glm::vec4& v);
  Program& set(const std::string& name, const glm::ivec2& v);
  Program& set(const std::string& name, const glm::ivec3& v);
  Program& set(const std::string& name, const glm::ivec4& v);
  Program& set(const std::string& name, unsigned v);
  Program& set(const std::string& name, const glm::uvec2& v);
  Program& set(const std::string& name, const glm::uvec3& v);
  Program& set(const std::string& name, const glm::uvec4& v);
  Program& set(const std::string& name, const glm::mat3& v);
  Program& set(const std::string& name, const glm::mat4& v);
  // Uniform arrays ("name" or "name[0]"); at most the declared length is written by GL.
  Program& set(const std::string& name, const std::vector<float>& values);
  Program& set(const std::string& name, const std::vector<int>& values);
  Program& set(const std::string& name, const std::vector<glm::vec2>& values);
  Program& set(const std::string& name, const std::vector<glm::vec3>& values);
  Program& set(const std::string& name, const std::vector<glm::vec4>& values);
  Program& set(const std::string& name, const std::vector<glm::ivec3>& values);
  Program& set(const std::string& name, const std::vector<glm::mat4>& values);

  // A compute program's local size (layout(local_size_x ...)); Error(Internal) for other programs.
  glm::ivec3 workGroupSize() const;

  // Files this program was built from (includes too) with their modification times, for reload.
  bool sourcesChanged() const;
  // The files' modification times on disk now, in the order they were recorded.
  std::vector<std::filesystem::file_time_type> sourceTimesNow() const;

private:
  ProgramDesc m_desc;
  ProgramHandle m_handle;
  std::unordered_map<std::string, GLint> m_locations;
  std::vector<std::pair<std::string, std::filesystem::file_time_type>> m_sources;
};

} // namespace rtlab::gl
