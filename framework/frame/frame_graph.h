// The per-frame pass graph (docs/frame-graph.md; Falcor's reflect() and Filament's addPass are the
// models). Every frame the renderer and the active techniques add passes; each pass declares in
// `setup` how it uses each resource (sampled, attachment at a level and layer, storage image,
// storage or atomic-counter buffer, indirect arguments, CPU read-back), and does its GL work in
// `execute`. compile() keeps only the passes that feed a requested output, refuses inconsistent
// declarations, plans the memory barriers the declarations imply, and allocates the resources from
// the pool (reusing last frame's when the description matches, releasing the rest). run() binds each
// pass's images and buffers, issues its barrier, executes and times it, and restores the known GL
// state (gl/state.h) after it. A technique that is off adds no pass and holds no pool memory.
#pragma once
#include "frame/frame_view.h"
#include "frame/pass_use.h"
#include "frame/resource_pool.h"
#include "gl/buffer.h"
#include "gl/objects.h"
#include "gl/texture.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <functional>
#include <map>
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
namespace gl { class Program; class ProgramCache; }

class PassBuilder {
public:
  // Sampled: the pass fetches the texture through a sampler (it binds the texture itself).
  void read(const std::string& resource);
  // Read when an earlier pass produces it this frame; the execute function checks ctx.has().
  void readIfPresent(const std::string& resource);
  // Attachment at level 0, all layers (PassContext::framebuffer attaches it so).
  void write(const std::string& resource, const gl::TextureDesc& desc);
  // Attachment at `level` and `layer` (-1 = all layers: layered rendering; else one array layer,
  // cube face or 3D slice).
  void writeAttachment(const std::string& resource, const gl::TextureDesc& desc, int level, int layer = -1);
  // Storage image at image `unit`, all layers of `level` (bound with glBindImageTexture before execute).
  void readImage(const std::string& resource, int unit, int level = 0);
  void writeImage(const std::string& resource, const gl::TextureDesc& desc, int unit, int level = 0);
  void readWriteImage(const std::string& resource, int unit, int level = 0);
  // Storage or atomic-counter buffer at binding `index` (bound with glBindBufferBase before execute).
  void readBuffer(const std::string& resource, BufferBinding binding, int index);
  void writeBuffer(const std::string& resource, const gl::BufferDesc& desc, BufferBinding binding, int index);
  void readWriteBuffer(const std::string& resource, BufferBinding binding, int index);
  // Indirect draw or dispatch arguments (bound to GL_DRAW_INDIRECT_BUFFER and GL_DISPATCH_INDIRECT_BUFFER).
  void readIndirect(const std::string& resource);
  // The pass reads the resource on the CPU (glGetTextureImage, glGetNamedBufferSubData).
  void readBack(const std::string& resource);

  const std::vector<PassUse>& uses() const { return m_uses; }

private:
  friend class FrameGraph;
  friend struct PassContext;
  void add(PassUse use);
  const PassUse* attachment(const std::string& resource) const;
  std::vector<PassUse> m_uses;
  std::set<std::string> m_absent; // optional reads that no earlier kept pass writes (set by compile)
};

// Where a compute pass's invocation grid comes from; the work-group count is the grid divided by
// the program's local size (layout(local_size_x ...)), rounded up.
struct ComputeGrid {
  enum class Source { Frame, Resource, Fixed, Indirect };
  Source source = Source::Frame;
  std::string resource;       // Resource, Indirect
  int level = 0;              // Resource: the texture level whose (width, height, layers) is the grid
  glm::ivec3 size{0};         // Fixed: the invocations
  std::size_t offset = 0;     // Indirect: byte offset of the three work-group counts

  static ComputeGrid frame();                                          // (frame width, height, 1)
  static ComputeGrid of(const std::string& resource, int level = 0);   // a texture the pass declares
  static ComputeGrid fixed(glm::ivec3 invocations);
  static ComputeGrid indirect(const std::string& buffer, std::size_t offset = 0); // glDispatchComputeIndirect
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
  // Set by FrameGraph::run for the pass being executed.
  const PassBuilder* pass = nullptr;
  glm::ivec3 grid{0}; // compute passes: the invocation grid (0 for indirect dispatch)

  // False for a resource no pass produces this frame, and for a readIfPresent resource no earlier
  // pass writes.
  bool has(const std::string& resource) const;
  gl::Texture& texture(const std::string& resource) const;      // Error(Internal) if absent
  gl::BufferObject& buffer(const std::string& resource) const;  // Error(Internal) if absent
  // Binds a framebuffer over `colors` for a full-screen pass, viewport = the first target's size at
  // its declared level. The pass starts from the known state (depth test, blending, culling off).
  void beginFullscreen(const std::string& label, const std::vector<std::string>& colors) const;
  // A framebuffer over frame resources (cached by the pool across frames). Each resource is attached
  // at the level and layer this pass declared for it (writeAttachment; level 0, all layers
  // otherwise); `layer` >= 0 overrides the depth attachment's layer (one cube face per draw).
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
  // A compute pass: `execute` sets up and returns its compute program; the graph then dispatches
  // ceil(grid / local size) work groups (or the indirect counts).
  using ComputeExecute = std::function<gl::Program&(PassContext&)>;
  void addComputePass(const std::string& name, const ComputeGrid& grid, const std::function<void(PassBuilder&)>& setup,
                      ComputeExecute execute);

  const Scene& scene() const { return m_ctx.scene; }
  const ParamSet& params() const { return m_ctx.params; }
  const FrameView& view() const { return m_ctx.view; }
  int width() const { return m_ctx.view.width; }
  int height() const { return m_ctx.view.height; }
  // Lends a technique-owned texture or buffer to this frame under `name` (docs/frame-graph.md
  // "Imported resources"): it counts as written before the first pass, passes declare their uses
  // of it as of any resource (a write's description must equal the object's), the graph binds it
  // and plans its barriers, but never allocates, reallocates or releases it. For data that outlives
  // frames: a volume baked once per scene change, a history buffer. The object must live until
  // run() returns. Error(Internal) for a name imported twice.
  void importTexture(const std::string& name, gl::Texture& texture);
  void importBuffer(const std::string& name, gl::BufferObject& buffer);
  bool isImported(const std::string& name) const { return m_imports.count(name) != 0; }

  // True if a pass added so far writes the resource (or it is imported).
  bool isProduced(const std::string& resource) const;

  // Culls to what `targets` need, checks the declarations, plans the barriers, then allocates.
  // Error(Internal), naming the pass and the resource, if a target has no producer, two passes
  // describe one resource differently, a kept pass reads a resource no earlier pass writes, or a
  // compute grid names a resource its pass does not declare.
  void compile(const std::vector<std::string>& targets);
  // Executes the kept passes in order, each bracketed by the timer.
  void run(PassTimer& timer);

  // After every pass (and before the first) compare the GL state with the known state and throw
  // Error(Internal) naming the first differing field. On by default in debug builds.
  void setStateCheck(bool on) { m_stateCheck = on; }
  static void setStateCheckDefault(bool on);

  struct PassRecord {
    std::string name, technique;
    bool kept = false;
    bool compute = false;
  };
  std::vector<PassRecord> passes() const;
  // The barriers compile() planned: glMemoryBarrier(bits) right before `pass` (kEndOfFrame: after
  // the last pass, for the outputs the caller reads back or samples).
  struct Barrier {
    std::string pass;
    GLbitfield bits = 0;
  };
  static constexpr const char* kEndOfFrame = "(end of frame)";
  const std::vector<Barrier>& barriers() const { return m_barriers; }
  // The bits issued right before `pass` (0 if none).
  GLbitfield barrierBefore(const std::string& pass) const;

private:
  struct Pass {
    std::string name, technique;
    PassBuilder decl;
    std::function<void(PassContext&)> execute;
    bool compute = false;
    ComputeGrid grid;
    ComputeExecute computeExecute;
    bool kept = false;
    GLbitfield barrier = 0;
  };
  void checkDescriptions() const;
  void checkReads();
  void planBarriers(const std::vector<std::string>& targets);
  void bindUses(const Pass& pass) const;
  void dispatch(Pass& pass);
  void checkState(const std::string& when) const;

  PassContext m_ctx;
  std::string m_technique;
  std::string m_colorInput, m_colorOutput;
  std::vector<Pass> m_passes;
  std::vector<Barrier> m_barriers;
  std::map<std::string, ResourcePool::Import> m_imports;
  GLbitfield m_endBarrier = 0;
  bool m_stateCheck;
};

} // namespace rtlab
