// Renders frames of one scene with the active techniques: builds the frame graph in the fixed
// stage order, culls it to the requested outputs, runs and times it, and reads AOVs back.
// One Renderer per GL context; it owns the program cache, the resource pool and the scene's GPU
// data, and the instances of the active techniques (a technique turned off is destroyed, and its
// pool textures are released at the next frame).
#pragma once
#include "frame/pass_timer.h"
#include "frame/resource_pool.h"
#include "frame/scene_notifier.h"
#include "frame/stats.h"
#include "frame/technique.h"
#include "gl/program_cache.h"
#include "image/image.h"
#include "reference/surfaces.h"
#include "scene/scene.h"
#include "shading/fragment_capture.h"
#include "shading/gpu_common.h"
#include "shading/scene_gpu.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rtlab {

class FrameGraph;
class ParamSet;
class TechniqueRegistry;
struct AovSource;
struct StageInfo;

// What one frame must produce.
struct FrameOutputs {
  std::vector<std::string> aovs; // built-in AOV names or active techniques' debug views
  bool displayColor = false;     // also produce tone-mapped color (color.ldr) for PNG or a window
  bool surfaces = false;         // keep the G-buffer's surface points for readSurfaces()
  std::vector<std::string> colors{}; // colour versions to keep for readColor(): "lighting", "lit", "pre_post", "hdr"
  bool countHdrClamped = false;      // count the HDR clamp's pixels (readHdrClamped); slower shaders, for stats only
  bool transparentFragments = false; // capture every transparent fragment (readTransparentFragments)
  std::size_t captureBandBytes = kMaxCaptureBytes; // the capture's buffer limit per band (tests lower it)
};

class Renderer {
public:
  explicit Renderer(const TechniqueRegistry& registry);
  ~Renderer();

  // Copies the scene and uploads it. Every active technique hears of it (Technique::sceneChanged)
  // before its setup() on the next frame.
  void setScene(const Scene& scene);
  const Scene& scene() const { return m_scene; }
  // Instantiates newly active techniques and destroys the ones no longer active.
  void setTechniques(const std::vector<std::string>& orderedIds);
  const std::vector<std::string>& techniques() const { return m_order; }

  // Error(Usage) if an AOV is unknown, belongs to an inactive technique, or is a stage AOV that only
  // a technique computes (arealight) on a scene its stage applies to with no such technique active.
  void checkAov(const std::string& aov) const;
  // Renders one frame at width x height; the scene's lights and camera take their values from
  // `params` first, then techniques hear of scene changes (docs/scene-data.md). Timings go to `timer`.
  void render(const ParamSet& params, int width, int height, const FrameOutputs& outputs, PassTimer& timer);

  // Reads an AOV of the last frame: channels 1 or 3, rows top to bottom, mask from coverage.
  Image readAov(const std::string& aov) const;
  // The tone-mapped color of the last frame (linear, 3 channels; sRGB is applied on output).
  Image readDisplayColor() const;
  // A colour version of the last frame (docs/stages.md "Colour versions"; it must be in
  // FrameOutputs::colors): linear, 3 channels, rows top to bottom, mask from coverage.
  Image readColor(const std::string& version) const;
  // The resource that held a colour version in the last frame (an alias of an earlier version's
  // resource when no pass changed the colour in between). Error(Internal) before a frame.
  const std::string& colorVersionResource(const std::string& version) const;
  // HDR clamp counts of the last frame rendered with FrameOutputs::countHdrClamped, per pass that
  // ran (docs/stages.md "The HDR clamp"). Waits for the GPU: for stats only.
  std::vector<HdrClampCount> readHdrClamped() const;
  // The surface points of the last frame (needs FrameOutputs::surfaces).
  SurfaceData readSurfaces() const;
  // Every transparent fragment of the last frame (needs FrameOutputs::transparentFragments;
  // shading/fragment_capture.h).
  const CapturedFragments& readTransparentFragments() const { return m_fragments; }
  // Texture of a resource of the last frame (the viewer draws it), or nullptr.
  const gl::Texture* resource(const std::string& name);

  std::vector<ResourceUse> resources() const;
  // Every active technique's counters about the last frame, in stage order (Technique::counters();
  // may wait for the GPU: for stats only).
  std::vector<CounterValue> counters() const;
  // Passes of the last frame (kept or culled).
  struct PassInfo {
    std::string name, technique;
    bool kept;
    bool compute = false;
    GLbitfield barrier = 0; // the glMemoryBarrier bits the graph issued right before it
  };
  const std::vector<PassInfo>& lastPasses() const { return m_lastPasses; }
  gl::ProgramCache& programs() { return m_programs; }

private:
  // Adds the G-buffer, the stages in table order with the lighting pass before the first colour
  // stage, and records the colour versions; returns the final colour's resource.
  std::string addStagePasses(FrameGraph& graph);
  bool stageHasTechnique(const StageInfo& stage) const;
  // Where built-in AOV `aov` comes from in this frame (the stage table's AOV rules).
  AovSource aovSource(const std::string& aov, const std::string& finalColor) const;

  const TechniqueRegistry& m_registry;
  Scene m_scene;
  std::unique_ptr<SceneGpu> m_sceneGpu;
  gl::ProgramCache m_programs;
  ResourcePool m_pool;
  GpuCommon m_common;
  std::map<std::string, std::unique_ptr<Technique>> m_techniques;
  std::vector<std::string> m_order;
  SceneNotifier m_notifier;
  std::vector<PassInfo> m_lastPasses;
  std::map<std::string, std::string> m_colorResources; // colour version -> resource, last frame
  CapturedFragments m_fragments;
};

} // namespace rtlab
