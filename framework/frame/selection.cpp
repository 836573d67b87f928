#include "frame/selection.h"

#include "frame/registry.h"
#include "frame/stages.h"
#include "util/error.h"

#include <algorithm>
#include <sstream>

namespace rtlab {

void TechniqueSelection::activate(const std::string& id) {
  if (id == "none") {
    m_active.clear();
    return;
  }
  const TechniqueEntry& entry = m_registry->get(id);
  const StageInfo* stage = findStage(entry.info.stage);
  if (stage->exclusive) {
    m_active.erase(std::remove_if(m_active.begin(), m_active.end(),
                                  [&](const std::string& other) { return m_registry->get(other).info.stage == stage->id; }),
                   m_active.end());
  } else {
    m_active.erase(std::remove(m_active.begin(), m_active.end(), id), m_active.end());
  }
  m_active.push_back(id);
}

void TechniqueSelection::activateList(const std::string& list) {
  if (list.empty()) usageError("empty technique list after -t");
  // getline yields no token after a trailing comma, so "a,b," would pass silently without this.
  if (list.back() == ',') usageError("empty technique name in '" + list + "'");
  std::stringstream ss(list);
  std::string id;
  while (std::getline(ss, id, ',')) {
    if (id.empty()) usageError("empty technique name in '" + list + "'");
    activate(id);
  }
}

void TechniqueSelection::deactivate(const std::string& id) {
  m_active.erase(std::remove(m_active.begin(), m_active.end(), id), m_active.end());
}

bool TechniqueSelection::isActive(const std::string& id) const {
  return std::find(m_active.begin(), m_active.end(), id) != m_active.end();
}

std::vector<std::string> TechniqueSelection::ordered() const {
  std::vector<std::string> out;
  for (const auto& stage : stages())
    for (const auto& id : m_active)
      if (m_registry->get(id).info.stage == stage.id) out.push_back(id);
  return out;
}

std::string TechniqueSelection::activeIn(const std::string& stage) const {
  for (const auto& id : ordered())
    if (m_registry->get(id).info.stage == stage) return id;
  return "";
}

} // namespace rtlab
