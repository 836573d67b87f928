// References per stage (docs/measuring.md "References per stage"): each stage that can be measured
// registers one reference, the way techniques register (frame/registry.h). A reference declares
// what it reads back from the frame (its inputs), which parameter keys define it (the sweep's
// reference hash covers exactly those, plus the scene, size, spp and seed), its sample range, and
// the function that computes it. `rtlab reference --aov X` and `rtlab sweep` dispatch through here.
#pragma once
#include "image/image.h"
#include "params/param_set.h"
#include "reference/reference.h"
#include "reference/surfaces.h"
#include "scene/scene.h"
#include "shading/fragment_capture.h"

#include <atomic>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace rtlab {

class Fnv1a64;
class TechniqueRegistry;

// What a reference reads back from the frame.
enum class FrameInput : unsigned {
  SurfacePoints = 1u << 0, // the G-buffer's surface points (SurfaceData), read back after a G-buffer-only frame
  Materials = 1u << 1,     // the scene's materials and textures; without it every material is Material{}
  PrePostColor = 1u << 2,  // the linear colour before the post stage (frame resource "color.pre_post")
  // Every transparent fragment of the frame (shading/fragment_capture.h) and the opaque colour under
  // them (colour version "lit"), from a frame without the transparency stage's techniques.
  TransparentFragments = 1u << 3,
};

class FrameInputs {
public:
  FrameInputs() = default;
  FrameInputs(std::initializer_list<FrameInput> inputs) {
    for (FrameInput i : inputs) m_bits |= unsigned(i);
  }
  bool has(FrameInput input) const { return (m_bits & unsigned(input)) != 0; }

private:
  unsigned m_bits = 0;
};

// The colour versions the PrePostColor and TransparentFragments inputs read (docs/stages.md "Colour versions").
inline constexpr const char* kPrePostColorVersion = "pre_post";
inline constexpr const char* kOpaqueColorVersion = "lit";

struct ReferenceEntry;

// What a reference's compute function receives: the inputs it declared, nothing else.
class ReferenceFrame {
public:
  ReferenceFrame(const ReferenceEntry& entry, const Scene& scene, const ParamSet& params, int spp, unsigned seed,
                 bool progress);

  // The scene with the lights and camera as the frame's parameters set them (materials only with
  // FrameInput::Materials).
  const Scene& scene() const { return m_scene; }
  // Error(Internal) unless the reference declared the input and the runner provided it.
  const SurfaceData& surfaces() const;
  const Image& prePostColor() const;
  // TransparentFragments: the captured fragments and the opaque colour ("lit") they cover.
  const CapturedFragments& transparentFragments() const;
  const Image& opaqueColor() const;
  // The value of a parameter; Error(Internal) for a key the reference does not declare, so a
  // reference cannot depend on a key the sweep's hash leaves out.
  float getFloat(const std::string& key) const;
  int spp() const { return m_spp; }
  unsigned seed() const { return m_seed; }
  bool progress() const { return m_progress; }
  // Cooperative cancellation (the viewer's compare mode restarts or closes while a reference
  // computes): a compute function that runs longer than a moment checks cancelled() regularly and
  // then throws Error(Interrupted); its result would be dropped anyway. threads(): how many threads
  // it may use (0: the hardware's), so a window sharing the machine keeps a core.
  bool cancelled() const { return m_cancel && m_cancel->load(std::memory_order_relaxed); }
  const std::atomic<bool>* cancelFlag() const { return m_cancel; }
  unsigned threads() const { return m_threads; }
  void setCancel(const std::atomic<bool>* flag) { m_cancel = flag; }
  void setThreads(unsigned threads) { m_threads = threads; }

  // Set by the runner (app/reference_run.h) after reading the inputs back.
  void setSurfaces(const SurfaceData* surfaces) { m_surfaces = surfaces; }
  void setPrePostColor(const Image* color) { m_prePostColor = color; }
  void setTransparentFragments(const CapturedFragments* fragments, const Image* opaque) {
    m_fragments = fragments;
    m_opaqueColor = opaque;
  }

private:
  const ReferenceEntry& m_entry;
  const Scene& m_scene;
  const ParamSet& m_params;
  int m_spp;
  unsigned m_seed;
  bool m_progress;
  const SurfaceData* m_surfaces = nullptr;
  const Image* m_prePostColor = nullptr;
  const CapturedFragments* m_fragments = nullptr;
  const Image* m_opaqueColor = nullptr;
  const std::atomic<bool>* m_cancel = nullptr;
  unsigned m_threads = 0;
};

using ReferenceCompute = std::function<Image(const ReferenceFrame&, ReferenceStats&)>;

struct ReferenceEntry {
  std::string aov;    // `rtlab reference --aov <aov>`: the stage's output AOV for the three built-ins
  std::string stage;  // the stage it measures (frame/stages.h): sweeps of that stage compare against it
  std::string help;   // one line for --help
  int channels = 1;   // 1 or 3
  FrameInputs inputs;
  // The keys that define it: "camera." (a prefix: ends with '.'), "light<N>." (every light<digits>.
  // key), or an exact key ("ao.radius"). The scene itself always defines it.
  std::vector<std::string> keys;
  int minSpp = 1, maxSpp = 1, defaultSpp = 1; // 1, 1, 1: it does not sample
  ReferenceCompute compute;

  bool definesKey(const std::string& key) const;
  bool samples() const { return maxSpp > 1; }
};

class ReferenceRegistry {
public:
  // Error(Internal) for a duplicate AOV or stage, an unknown stage, a malformed key pattern, an
  // empty compute function or an inconsistent spp range.
  void add(ReferenceEntry entry);
  const std::vector<ReferenceEntry>& entries() const { return m_entries; }
  const ReferenceEntry* findAov(const std::string& aov) const;
  const ReferenceEntry* findStage(const std::string& stage) const;
  // Error(Usage) "unknown reference AOV 'x' (choices: visibility, ao, indirect)".
  const ReferenceEntry& get(const std::string& aov) const;
  std::string choices(const std::string& separator = ", ") const; // the AOVs, in registration order

  static const ReferenceRegistry& instance(); // all registered references (frame/reference_registry_instance.cpp)

private:
  std::vector<ReferenceEntry> m_entries;
};

// The three references of the Embree ray caster (reference/reference.h): visibility (shadow
// stage), ao, indirect.
void registerBuiltinReferences(ReferenceRegistry& registry);

// Defined in the generated technique_registry.cpp (cmake/techniques.cmake): the built-in
// references, then every techniques/<id>/<id>_reference.cpp's registerReference_<id>().
void registerAllReferences(ReferenceRegistry& registry);

// The scene as the reference may see it: the lights and camera as `params` set them, and its
// materials and textures only when the entry declares FrameInput::Materials (every material is
// Material{} otherwise). What `rtlab reference` and the viewer's compare mode give a reference.
Scene sceneForReference(const Scene& scene, const ParamSet& params, const ReferenceEntry& entry);

// Whether the value of `key` is part of the reference's identity: one of its declared keys; for a
// reference that reads a colour of the frame (PrePostColor, TransparentFragments), also every key
// that can change that colour (all but the keys of the measured stage and its techniques, of the
// post stage's techniques, and tonemap.*).
bool referenceDependsOnKey(const ReferenceEntry& entry, const std::string& key, const TechniqueRegistry& techniques);
// Feeds the key and value of every key the reference depends on, in `params`' declaration order,
// to `h`: the part of the sweep's reference hash that parameters contribute (app/sweep_plan.h
// referenceHash).
void hashReferenceKeys(const ReferenceEntry& entry, const ParamSet& params, const TechniqueRegistry& techniques,
                       Fnv1a64& h);

} // namespace rtlab
