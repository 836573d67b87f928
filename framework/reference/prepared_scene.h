// A scene made ready for the CPU reference: a private copy of the Scene and the Embree BVH over
// its opaque triangles (embree_scene.h), which points into that copy's materials and textures.
// Immutable once built, so many jobs may trace it at once and share it through a shared_ptr:
// ProgressiveReference reuses one across restarts so that a camera move (or a light edit) does
// not rebuild the BVH. It must be rebuilt when meshes, instances, transforms or materials change.
#pragma once
#include "reference/embree_scene.h"
#include "scene/scene.h"

#include <cstddef>
#include <utility>

namespace rtlab {

class PreparedReferenceScene {
public:
  // Copies `scene` and builds the BVH (Error(Internal) if Embree fails): the slow step of a job on a
  // large scene, done once here instead of on every restart.
  explicit PreparedReferenceScene(Scene scene) : m_scene(std::move(scene)), m_tracer(m_scene) {}
  PreparedReferenceScene(const PreparedReferenceScene&) = delete;
  PreparedReferenceScene& operator=(const PreparedReferenceScene&) = delete;

  const Scene& scene() const { return m_scene; }
  const reference::EmbreeScene& tracer() const { return m_tracer; }
  std::size_t triangleCount() const { return m_tracer.triangleCount(); }

private:
  Scene m_scene; // declared first: the tracer points into it
  reference::EmbreeScene m_tracer;
};

} // namespace rtlab
