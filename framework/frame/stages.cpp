#include "frame/stages.h"

#include "scene/scene.h"

#include <algorithm>

namespace rtlab {

bool StageInfo::feedsLighting() const {
  return lighting == LightingEffect::MultiplyLight0Direct || lighting == LightingEffect::MultiplyAmbientIndirect ||
         lighting == LightingEffect::AddIndirect;
}

bool StageInfo::appliesTo(const Scene& scene) const {
  switch (predicate) {
  case StagePredicate::Always: return true;
  case StagePredicate::RectLight: return scene.hasAreaLight();
  case StagePredicate::TransparentMaterial: return scene.hasTransparency();
  }
  return true;
}

const std::vector<StageInfo>& stages() {
  static const std::vector<StageInfo> list = [] {
    std::vector<StageInfo> s;
    auto add = [&](StageInfo st) {
      st.order = int(s.size());
      s.push_back(std::move(st));
    };
    //        id, order, exclusive, predicate, output, neutral, lighting effect, colour version, fallback, params, AOV
    StageInfo shadow{"shadow", 0, true, StagePredicate::Always, "visibility", 1.0f, LightingEffect::MultiplyLight0Direct, "", "", {}, {}};
    shadow.params = {
        ParamSpec::integer("shadow.resolution", "Map resolution", 2048, 256, 4096)
            .logScale().withUnit("texels").withFlags(kParamRealloc)
            .withHelp("Width and height of the light-space depth map (per cube face for point lights)"),
        ParamSpec::choice("shadow.depth_format", "Depth format", {"16", "24", "32f"}, 1)
            .withFlags(kParamRealloc).withHelp("Depth buffer format of the light-space map: 16-bit, 24-bit or 32-bit float"),
        ParamSpec::real("shadow.constant_bias", "Constant bias", 0.001, 0.0, 0.05)
            .withUnit("depth [0,1]").withHelp("Subtracted from the receiver's light-space depth before the comparison"),
        ParamSpec::real("shadow.slope_bias", "Slope bias", 1.5, 0.0, 4.0)
            .withUnit("x depth slope").withHelp("Polygon offset factor in the light pass: bias proportional to the depth slope"),
        ParamSpec::real("shadow.normal_bias", "Normal offset", 0.5, 0.0, 2.0)
            .withUnit("texels").withHelp("Receiver moved along its geometric normal by this many shadow-map texels"),
        ParamSpec::boolean("shadow.cull_front", "Cull front faces", false)
            .withHelp("Render back faces only into the map (closed meshes only; single-sided planes then cast no shadow)"),
    };
    shadow.aov = {"visibility", 1, "fraction of light 0 visible from the surface point (1 without a shadow technique)",
                  AovRule::OutputOrNeutral};
    add(shadow);
    StageInfo ao{"ao", 0, true, StagePredicate::Always, "ao", 1.0f, LightingEffect::MultiplyAmbientIndirect, "", "", {}, {}};
    ao.params = {ParamSpec::real("ao.radius", "AO radius", 0.5, 0.01, 10.0)
                     .logScale().withUnit("scene units")
                     .withHelp("Occluders farther than this from the point do not occlude (every AO technique and the reference)")};
    ao.aov = {"ao", 1, "ambient occlusion within ao.radius (1 without an AO technique)", AovRule::OutputOrNeutral};
    add(ao);
    add(StageInfo{"indirect", 0, true, StagePredicate::Always, "indirect", 0.0f, LightingEffect::AddIndirect, "", "", {},
                  {"indirect", 3, "one-bounce diffuse irradiance (0 without an indirect technique)", AovRule::OutputOrNeutral}});
    add(StageInfo{"arealight", 0, true, StagePredicate::RectLight, "color", 0.0f, LightingEffect::ReplaceRectLights, "lit", "", {},
                  {"arealight", 3,
                   "radiance of the rectangular lights, unshadowed (0 without a rectangular light; needs an arealight "
                   "technique where there is one)",
                   AovRule::TechniqueResource, 0.0f}});
    add(StageInfo{"transparency", 0, true, StagePredicate::TransparentMaterial, "color", 0.0f, LightingEffect::TransformColor,
                  "pre_post", "transparent", {},
                  {"transparency", 3,
                   "linear colour after the transparency stage (pre_post); A = 1 where a surface or a transparent layer covers",
                   AovRule::ColorVersionCoverage, 0.0f}});
    add(StageInfo{"post", 0, false, StagePredicate::Always, "color", 0.0f, LightingEffect::TransformColor, "hdr", "", {}, {}});
    return s;
  }();
  return list;
}

const StageInfo* findStage(const std::string& id) {
  for (const auto& s : stages())
    if (s.id == id) return &s;
  return nullptr;
}

const StageInfo* stageWithAov(const std::string& aov) {
  for (const auto& s : stages())
    if (!s.aov.name.empty() && s.aov.name == aov) return &s;
  return nullptr;
}

const char* aovRuleName(AovRule r) {
  switch (r) {
  case AovRule::OutputOrNeutral: return "output_or_neutral";
  case AovRule::TechniqueResource: return "technique_resource";
  case AovRule::ColorVersionCoverage: return "color_version_coverage";
  }
  return "output_or_neutral";
}

const char* predicateName(StagePredicate p) {
  switch (p) {
  case StagePredicate::Always: return "always";
  case StagePredicate::RectLight: return "rect_light";
  case StagePredicate::TransparentMaterial: return "transparent_material";
  }
  return "always";
}

const char* lightingEffectName(LightingEffect e) {
  switch (e) {
  case LightingEffect::MultiplyLight0Direct: return "multiply_light0_direct";
  case LightingEffect::MultiplyAmbientIndirect: return "multiply_ambient_indirect";
  case LightingEffect::AddIndirect: return "add_indirect";
  case LightingEffect::ReplaceRectLights: return "replace_rect_lights";
  case LightingEffect::TransformColor: return "transform_color";
  }
  return "transform_color";
}

const std::vector<std::string>& colorVersions() {
  static const std::vector<std::string> list = [] {
    std::vector<std::string> v{"lighting"};
    for (const auto& s : stages())
      if (!s.colorVersion.empty()) v.push_back(s.colorVersion);
    return v;
  }();
  return list;
}

bool isColorVersion(const std::string& version) {
  const auto& v = colorVersions();
  return std::find(v.begin(), v.end(), version) != v.end();
}

std::vector<ParamSpec> tonemapParams() {
  return {
      ParamSpec::real("tonemap.exposure", "Exposure", 1.0, 0.01, 100.0)
          .logScale().withHelp("Scene radiance is multiplied by this before the tone curve"),
      ParamSpec::choice("tonemap.operator", "Operator", {"aces", "reinhard", "clamp"}, 0)
          .withHelp("Tone curve: ACES filmic fit (Narkowicz 2015), Reinhard x/(1+x), or clamp to [0,1] "
                    "(no curve: the baseline that shows why HDR needs one)"),
  };
}

const std::vector<AovInfo>& builtinAovs() {
  static const std::vector<AovInfo> list = [] {
    std::vector<AovInfo> l{{"color", 3, "final image: linear radiance in EXR/PFM, tone-mapped sRGB in PNG"}};
    for (const auto& s : stages())
      if (!s.aov.name.empty()) l.push_back({s.aov.name, s.aov.channels, s.aov.help});
    l.push_back({"depth", 1, "linear view depth, scene units"});
    l.push_back({"normal", 3, "world-space shading normal, unit length"});
    l.push_back({"albedo", 3, "base color (linear)"});
    return l;
  }();
  return list;
}

} // namespace rtlab
