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
    auto times = program->sourceTimesNow();
    if (auto failed = m_failed.find(key); failed != m_failed.end() && failed->second.times == times) {
      errors.push_back(failed->second.message); // unchanged since it failed: not compiled again
      continue;
    }
    try {
      *program = Program(program->desc());
      m_failed.erase(key);
    } catch (const Error& e) {
      errors.push_back(e.what());
      m_failed[key] = Failure{std::move(times), e.what()};
    }
  }
  return errors;
}

} // namespace rtlab::gl
