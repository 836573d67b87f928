// Programs are expensive to build (0.1-0.4 s of JIT each on llvmpipe), so one cache per context
// keeps them for the context's lifetime, keyed by files + defines.
#pragma once
#include "gl/program.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rtlab::gl {

class ProgramCache {
public:
  // Builds on first use; throws Error(Shader) when the program does not compile or link.
  Program& get(const ProgramDesc& desc);
  // Rebuilds programs whose files changed on disk. A failed rebuild keeps the last good program;
  // the error messages are returned (one per failed program). A program whose rebuild failed is
  // not compiled again until its files change again; its message is returned meanwhile.
  std::vector<std::string> reloadChanged();
  std::size_t size() const { return m_programs.size(); }
  void clear() {
    m_programs.clear();
    m_failed.clear();
  }

private:
  std::map<std::string, std::unique_ptr<Program>> m_programs;
  struct Failure {
    std::vector<std::filesystem::file_time_type> times; // of the files that failed
    std::string message;
  };
  std::map<std::string, Failure> m_failed; // by program key
};

} // namespace rtlab::gl
