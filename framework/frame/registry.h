// The technique registry. Every folder techniques/<id>/ defines registerTechnique_<id>(), and a
// CMake-generated file calls them all (cmake/techniques.cmake), so registration survives static
// linking and adding a technique touches no other file.
#pragma once
#include "frame/technique.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rtlab {

struct TechniqueEntry {
  TechniqueInfo info;
  std::function<std::unique_ptr<Technique>()> create;
};

class TechniqueRegistry {
public:
  // Throws Error(Internal) for a duplicate id, an unknown stage, or a parameter key that does
  // not start with "<id>.".
  void add(TechniqueEntry entry);
  const std::vector<TechniqueEntry>& entries() const { return m_entries; }
  const TechniqueEntry* find(const std::string& id) const;
  // Throws Error(Usage) "unknown technique 'x'" listing the known ids.
  const TechniqueEntry& get(const std::string& id) const;

  static const TechniqueRegistry& instance(); // all registered techniques

private:
  std::vector<TechniqueEntry> m_entries;
};

// Defined in the generated technique_registry.cpp.
void registerAllTechniques(TechniqueRegistry& registry);

// Convenience for technique files: registers T (default-constructible, with a static info()).
template <typename T>
void registerTechniqueType(TechniqueRegistry& registry) {
  registry.add(TechniqueEntry{T::staticInfo(), [] { return std::make_unique<T>(); }});
}

} // namespace rtlab
