#include "gl/program_cache.h"

#include "util/error.h"

namespace rtlab::gl {

Program& ProgramCache::get(const ProgramDesc& desc) {
  const std::string key = desc.key();
  auto it = m_programs.find(key);
  if (it != m_programs.end()) return *it->second;
  auto program = std::make_unique<Program>(desc);
  Program& ref = *program;
  m_programs.emplace(key, std::move(program));
  return ref;
}

std::vector<std::string> ProgramCache::reloadChanged() {
  std::vector<std::string> errors;
  for (auto& [key, program] : m_programs) {
    if (!program->sourcesChanged()) continue;
    try {
      *program = Program(program->desc());
    } catch (const Error& e) {
      errors.push_back(e.what());
    }
  }
  return errors;
}

} // namespace rtlab::gl
