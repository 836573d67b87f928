// The frame's recipe of stages as data (docs/stages.md): each stage's position, slot, the scene
// predicate that decides whether it runs at all, its output and the output's neutral value, and
// what the lighting pass does with the output. The renderer loops over this table; nothing else
// names a stage. Also the parameters the frame itself owns: stage parameters (shadow.*, ao.radius)
// and tone mapping (tonemap.*).
#pragma once
#include "params/param_spec.h"

#include <string>
#include <vector>

namespace rtlab {

struct Scene;

// Whether a stage runs for a scene at all (docs/stages.md "The stage table").
enum class StagePredicate {
  Always,
  RectLight,           // the scene has a rectangular light
  TransparentMaterial, // the scene has an instance with a transparent (BLEND) material
};

// What the lighting pass does with a stage's output.
enum class LightingEffect {
  MultiplyLight0Direct,    // visibility: scales light 0's direct term
  MultiplyAmbientIndirect, // ao: scales the ambient term and the indirect term
  AddIndirect,             // indirect: irradiance added, times diffuse albedo / pi
  ReplaceRectLights,       // arealight: the lighting pass no longer adds rectangular lights as points;
                           // the stage adds their contribution to the colour
  TransformColor,          // transparency, post: read the current colour version, write the next
};

// Where a stage AOV's value comes from (docs/stages.md "Stage AOVs").
enum class AovRule {
  // The stage's output resource (`StageInfo::output`); the stage's neutral value on every surface
  // pixel where no technique wrote it. A = surface mask. (visibility, ao, indirect)
  OutputOrNeutral,
  // The frame resource named like the AOV, which the stage's active technique writes. Where the
  // stage does not apply to the scene: the AOV's neutral value on every surface pixel. Where it
  // applies but no technique of the stage is active, the frame holds no such value: a usage error.
  // A = surface mask. (arealight)
  TechniqueResource,
  // The stage's colour version (`StageInfo::colorVersion`), whoever produced it (a technique, the
  // fallback, or an alias when the stage does not run). A = 1 where the colour's alpha (coverage:
  // 1 on opaque surfaces, premultiplied-over accumulated by the layers) is above 0. (transparency)
  ColorVersionCoverage,
};

// The AOV a stage defines (docs/contract.md "Images and AOVs"); `name` empty: none.
struct StageAov {
  std::string name;
  int channels = 3;
  std::string help;
  AovRule rule = AovRule::OutputOrNeutral;
  float neutral = 0.0f; // TechniqueResource: the value where the stage does not apply (OutputOrNeutral
                        // uses StageInfo::neutral, which the lighting pass assumes too)
};

struct StageInfo {
  std::string id;        // "shadow"
  int order = 0;         // position in the frame, 0-based (= index in stages())
  bool exclusive = true; // one technique at most ("exclusive") or several in -t order ("stack")
  StagePredicate predicate = StagePredicate::Always;
  std::string output;    // AOV the stage produces: "visibility", "ao", "indirect", "color"
  // Value of the output where no technique of the stage is active (what the lighting pass and the
  // AOV pass assume); colour stages are the identity instead (their version aliases the input).
  float neutral = 0.0f;
  LightingEffect lighting = LightingEffect::TransformColor;
  // Colour stages: the colour version the stage's result is (docs/stages.md "Colour versions"):
  // "lit", "pre_post", "hdr". Empty for the stages that feed the lighting pass.
  std::string colorVersion;
  // Framework pass that does the stage's work when the predicate holds and no technique of the
  // stage is active ("transparent": the built-in back-to-front forward pass); empty: none.
  std::string fallback;
  std::vector<ParamSpec> params;
  StageAov aov;

  // True for stages whose output the lighting pass reads (they run before it); false for colour stages.
  bool feedsLighting() const;
  bool appliesTo(const Scene& scene) const;
};

const std::vector<StageInfo>& stages();
const StageInfo* findStage(const std::string& id);
// The stage that declares the AOV `aov` (StageInfo::aov: "visibility" -> shadow, "arealight" ->
// arealight, "transparency" -> transparency), or nullptr.
const StageInfo* stageWithAov(const std::string& aov);
const char* aovRuleName(AovRule r); // "output_or_neutral", "technique_resource", "color_version_coverage"
std::vector<ParamSpec> tonemapParams();

// Names used in `list --json` and docs/stages.md.
const char* predicateName(StagePredicate p);   // "always", "rect_light", "transparent_material"
const char* lightingEffectName(LightingEffect e); // "multiply_light0_direct", ...

// The colour versions in frame order (docs/stages.md): "lighting" (the lighting pass's own output),
// then each colour stage's version: "lit", "pre_post", "hdr". The resource of version v is
// "color.<v>" unless an alias (no pass changed the colour in between).
const std::vector<std::string>& colorVersions();
bool isColorVersion(const std::string& version);

// AOVs every frame can output (docs/contract.md): color, then each stage's AOV in stage order
// (visibility, ao, indirect, arealight, transparency), then depth, normal, albedo.
struct AovInfo {
  std::string name;
  int channels;
  std::string help;
};
const std::vector<AovInfo>& builtinAovs();

} // namespace rtlab
