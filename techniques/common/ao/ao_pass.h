// Shared machinery of the ao stage (used by ssao and hbao): the view-space surface buffer the
// estimators read ("ao.view", at full or half resolution), the technique's estimator pass
// ("ao.raw"), a depth- and normal-aware separable bilateral blur, the depth-aware upsampling
// and resolve into the stage output "ao", and the debug views <id>.raw, <id>.blurred and
// <id>.pattern. Every resource here is produced only while an ao technique is active (only its
// setup adds these passes) and only when something reads it. Shaders: shaders/ao/.
#pragma once
#include "frame/technique.h"
#include "gl/objects.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "params/param_spec.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace rtlab {

class FrameGraph;
struct PassContext;
class ParamSet;

namespace aores {
inline const std::string kView = "ao.view";       // xyz view-space shading normal, w linear depth (0 = sky)
inline const std::string kRaw = "ao.raw";         // the estimator's AO before the blur, AO resolution
inline const std::string kBlurX = "ao.blur_x";    // after the horizontal blur
inline const std::string kBlurred = "ao.blurred"; // after both blur directions
} // namespace aores

// Texture units the framework binds for the estimator (shaders/ao/common/ao_common.glsl):
// 0 ao.view, 1 blue noise. A technique's own textures start at kAoFirstFreeUnit.
constexpr int kAoFirstFreeUnit = 2;

// The estimator pass of one ao technique.
struct AoEstimatorPass {
  std::string technique; // "ssao" (AoTechnique fills it in from its info's id)
  std::string fragment;  // "ssao/ssao.frag": includes ../ao/common/ao_common.glsl,
                         // defines aoEvaluate(), then includes ../ao/common/ao_main.glsl
  std::vector<std::string> defines;
  // Sets the technique's own uniforms (and textures from kAoFirstFreeUnit).
  std::function<void(PassContext&, gl::Program&)> bind;
};

// The filtering knobs both ao techniques share, declared once here with the technique's prefix:
// "<id>.blur" (bool), "<id>.blur_radius" (px), "<id>.half_resolution" (bool).
std::vector<ParamSpec> aoFilterParams(const std::string& technique);
// "<id>.raw", "<id>.blurred", "<id>.pattern".
std::vector<DebugView> aoDebugViews(const std::string& technique);

// Owns the blue-noise rotation texture the estimators share (created on first use).
class AoKit {
public:
  static constexpr int kNoiseSize = 64;
  void bindNoise(gl::Program& program);
  std::size_t ownedBytes() const { return m_noise ? m_noise.desc().bytes() : 0; }

private:
  gl::Texture m_noise;
};

// Adds the whole ao chain for the technique: prepare, estimator, blur (when "<id>.blur"), the
// depth-aware upsampling into "ao" at half resolution (at full resolution the last of estimator
// and blur writes "ao" itself), and the three debug views (culled unless requested).
void addAoPasses(FrameGraph& frame, const AoEstimatorPass& pass, AoKit& kit);

// Base of the ao techniques: owns the AoKit and adds the whole chain (addAoPasses) around the
// estimator that the derived class describes. A derived class declares its own parameters in
// staticInfo() and returns withAoChain(info), which appends the shared filter parameters and
// debug views, so that the registry and the instance see the same declarations.
class AoTechnique : public Technique {
public:
  const TechniqueInfo& info() const override { return m_info; }
  void setup(FrameGraph& frame) override;
  std::size_t ownedBytes() const override { return m_kit.ownedBytes(); }

protected:
  explicit AoTechnique(TechniqueInfo info) : m_info(std::move(info)) {}
  // The estimator pass for this frame's parameters (`technique` need not be set).
  virtual AoEstimatorPass estimator(const ParamSet& params) const = 0;
  // `info` with aoFilterParams(info.id) appended to its parameters and aoDebugViews(info.id) as
  // its debug views.
  static TechniqueInfo withAoChain(TechniqueInfo info);

private:
  TechniqueInfo m_info;
  AoKit m_kit;
};

} // namespace rtlab
