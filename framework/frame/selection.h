// Which techniques are active: at most one per exclusive stage, any number in a stack stage.
// `-t A,B` activates in order; a later technique in the same exclusive stage replaces the earlier;
// `none` deactivates everything (docs/contract.md).
#pragma once
#include <string>
#include <vector>

namespace rtlab {

class TechniqueRegistry;

class TechniqueSelection {
public:
  explicit TechniqueSelection(const TechniqueRegistry& registry) : m_registry(&registry) {}
  // Error(Usage) for an unknown id.
  void activate(const std::string& id);
  // Comma-separated list, as given to -t.
  void activateList(const std::string& list);
  void deactivate(const std::string& id);
  void clear() { m_active.clear(); }
  bool isActive(const std::string& id) const;
  // Active ids in stage order (the frame's order), then activation order within a stack stage.
  std::vector<std::string> ordered() const;
  // The active technique of a stage, or "" if none (first one for stack stages).
  std::string activeIn(const std::string& stage) const;

private:
  const TechniqueRegistry* m_registry;
  std::vector<std::string> m_active;
};

} // namespace rtlab
