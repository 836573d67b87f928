#include "frame/scene_notifier.h"

#include <algorithm>

namespace rtlab {

void SceneNotifier::sceneSet() {
  for (auto& [id, change] : m_pending) change = SceneChange::everything();
  // The first frame of a new scene is already a change of everything: no light comparison.
  m_haveLastLights = false;
}

void SceneNotifier::setActive(const std::vector<std::string>& ids) {
  std::erase_if(m_pending, [&](const auto& entry) { return std::find(ids.begin(), ids.end(), entry.first) == ids.end(); });
  for (const auto& id : ids) m_pending.try_emplace(id, SceneChange::everything());
}

void SceneNotifier::deliver(const std::vector<Light>& lights, const std::vector<std::string>& order,
                            const std::map<std::string, std::unique_ptr<Technique>>& techniques) {
  // Copied only when they changed: an unchanged frame allocates nothing.
  if (!m_haveLastLights || !sameLights(lights, m_lastLights)) {
    if (m_haveLastLights)
      for (auto& [id, change] : m_pending) change.lights = true;
    m_lastLights = lights;
    m_haveLastLights = true;
  }
  for (const auto& id : order) {
    auto pending = m_pending.find(id);
    auto technique = techniques.find(id);
    if (pending == m_pending.end() || !pending->second.any() || technique == techniques.end()) continue;
    const SceneChange change = pending->second;
    pending->second = SceneChange{};
    technique->second->sceneChanged(change);
  }
}

} // namespace rtlab
