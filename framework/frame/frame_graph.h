// The per-frame pass graph (docs/architecture.md "The frame graph"; Falcor's reflect() and Filament's addPass are
// the models). Every frame the renderer and the active techniques add passes; each pass declares
// the resources it reads and writes in `setup`, and does its GL work in `execute`. compile() keeps
// only the passes that feed a requested output, allocates their textures from the pool (reusing
// last frame's when the description matches, releasing the rest), and run() executes and times
// them. A technique that is off adds no pass and holds no pool memory.
#pragma once
#include "frame/frame_view.h"
#include "gl/objects.h"
#include "gl/texture.h"

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace rtlab {

class ParamSet;
class PassTimer;
class ResourcePool;
class SceneGpu;
struct GpuCommon;
struct Scene;
namespace gl { class ProgramCache; }

class PassBuilder {
public:
  void read(const std::string& resource) { m_reads.push_back(resource); }
  // Read when some pass produces it this frame; the execute function checks ctx.has().
  void readIfPresent(const std::string& resource) { m_optionalReads.push_back(resource); }
  void write(const std::string& resource, const gl::TextureDesc& desc) { m_writes.emplace_back(resource, desc); }

private:
  friend class FrameGraph;
  std::vector<std::string> m_reads, m_optionalReads;
  std::vector<std::pair<std::string, gl::TextureDesc>> m_writes;
};

// Everything a pass's execute function may use.
struct PassContext {
  const Scene& scene;
  const ParamSet& params;
  const FrameView& view;
  SceneGpu& sceneGpu;
  gl::ProgramCache& programs;
  ResourcePool& pool;
  const GpuCommon& common;
  bool has(const std::string& resource) const;
  gl::Texture& texture(const std::string& resource) const; // Error(Internal) if absent
  // Binds a framebuffer over `colors` for a full-screen pass: viewport = the first target's size,
  // depth test, blending and culling off. (FrameGraph::run restores the default state after every
  // pass, so a pass sets what it needs and leaks nothing.)
  void beginFullscreen(const std::string& label, const std::vector<std::string>& colors) const;
  // A framebuffer over frame resources (cached by the pool across frames).
  const gl::Framebuffer& framebuffer(const std::string& label, const std::vector<std::string>& colors,
                                     const std::string& depth = "", int layer = -1) const;
};

class FrameGraph {
public:
  FrameGraph(const Scene& scene, const ParamSet& params, const FrameView& view, SceneGpu& sceneGpu,
             gl::ProgramCache& programs, ResourcePool& pool, const GpuCommon& common);

  // Passes added after this are attributed to `technique` in stats ("" = the framework).
  void setTechnique(const std::string& technique) { m_technique = technique; }
  // Colour stages (docs/stages.md "Colour versions"): the colour resource the technique being set
  // up reads, and the one it must write (RGBA16F, frame-sized). The renderer sets both around each
  // colour-stage technique's setup; they are empty for the other stages.
  void setColorVersions(const std::string& input, const std::string& output) {
    m_colorInput = input;
    m_colorOutput = output;
  }
  const std::string& colorInput() const { return m_colorInput; }
  const std::string& colorOutput() const { return m_colorOutput; }
  void addPass(const std::string& name, const std::function<void(PassBuilder&)>& setup,
               std::function<void(PassContext&)> execute);

  const Scene& scene() const { return m_ctx.scene; }
  const ParamSet& params() const { return m_ctx.params; }
  const FrameView& view() const { return m_ctx.view; }
  int width() const { return m_ctx.view.width; }
  int height() const { return m_ctx.view.height; }
  // True if a pass added so far writes the resource.
  bool isProduced(const std::string& resource) const;

  // Culls to what `targets` need, then allocates. Error(Internal) if a target or a required read
  // has no producer.
  void compile(const std::vector<std::string>& targets);
  // Executes the kept passes in order, each bracketed by the timer.
  void run(PassTimer& timer);

  struct PassRecord {
    std::string name, technique;
    bool kept = false;
  };
  std::vector<PassRecord> passes() const;

private:
  struct Pass {
    std::string name, technique;
    PassBuilder decl;
    std::function<void(PassContext&)> execute;
    bool kept = false;
  };
  PassContext m_ctx;
  std::string m_technique;
  std::string m_colorInput, m_colorOutput;
  std::vector<Pass> m_passes;
};

} // namespace rtlab
