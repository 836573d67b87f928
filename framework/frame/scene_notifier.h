// Tells the active techniques what changed in the scene (Technique::sceneChanged; the categories
// and their timing are in docs/scene-data.md "Scene changes"). The renderer reports scene sets
// and technique activations as they happen; deliver() runs once per frame, after the frame's
// parameters were applied to the scene and before any technique's setup(), and finds light
// changes by comparing the scene's lights with the previous frame's.
#pragma once
#include "frame/technique.h"
#include "scene/scene.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rtlab {

class SceneNotifier {
public:
  // A scene was set: every active technique hears everything on the next frame.
  void sceneSet();
  // The active techniques, as Renderer::setTechniques keeps their instances: one newly active
  // hears everything on its first frame; one no longer active is forgotten.
  void setActive(const std::vector<std::string>& ids);
  // Adds this frame's light change, then calls sceneChanged on each technique in `order` that has
  // something pending (once each), and clears what it delivered.
  void deliver(const std::vector<Light>& lights, const std::vector<std::string>& order,
               const std::map<std::string, std::unique_ptr<Technique>>& techniques);

private:
  std::map<std::string, SceneChange> m_pending; // one entry per active technique
  std::vector<Light> m_lastLights;              // as the previous frame applied them
  bool m_haveLastLights = false;                // false until a frame after the last scene set
};

} // namespace rtlab
