// Linearly transformed cosines — Eric Heitz, Jonathan Dupuy, Stephen Hill and David Neubelt,
// "Real-Time Polygonal-Light Shading with Linearly Transformed Cosines", ACM TOG 35(4) (SIGGRAPH
// 2016). Approximates the arealight stage's integral (docs/contract.md "Area lights": the radiance
// each rectangular light adds, unshadowed, with the frame's BRDF) in closed form: the GGX lobe of
// each pixel's (roughness, theta_v) is a clamped cosine under a fitted linear transform M, so the
// integral over the light is the cosine's over the polygon taken through M^-1 (Lambert's polygon
// formula), scaled by the lobe's tabulated magnitude and Fresnel; the diffuse term is the same
// formula with M = I. techniques/ltc/README.md has the formulas, the guards, the artifacts and the
// measured cost; assets/ltc/README.md the fit.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "techniques/common/arealight/arealight_composite.h"
#include "techniques/ltc/ltc_lut.h"
#include "util/paths.h"

#include <memory>

namespace rtlab {
namespace {

const std::vector<std::string> kTableSizes = {"16", "32", "64"};

// The fitted table, read once per process (assets/ltc/ggx.json: 0.3 MB of JSON).
const LtcTable& shippedTable() {
  static std::unique_ptr<LtcTable> table;
  if (!table) table = std::make_unique<LtcTable>(LtcTable::load(assetPath("ltc/ggx.json")));
  return *table;
}

struct Settings {
  int tableSize = 64;
  std::vector<std::string> defines;
  int diffuseFresnel = 1;
};

Settings settingsFrom(const ParamSet& params) {
  Settings s;
  s.tableSize = std::stoi(params.getEnumName("ltc.table_size"));
  if (params.getEnumName("ltc.edge") == "acos") s.defines.push_back("LTC_EDGE_ACOS");
  if (params.getEnumName("ltc.horizon") == "sphere") s.defines.push_back("LTC_HORIZON_SPHERE");
  s.diffuseFresnel = params.getEnumName("ltc.diffuse_fresnel") == "average" ? 1 : 0;
  return s;
}

class Ltc final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "ltc";
    info.stage = "arealight";
    info.title = "Linearly transformed cosines (Heitz et al. 2016)";
    info.summary = "Closed-form rectangular lights: the GGX lobe as a linearly transformed clamped cosine from a "
                   "fitted table, the light polygon through M^-1, clipped to the horizon, integrated edge by edge";
    info.showcaseScene = "arealight";
    info.params = {
        ParamSpec::choice("ltc.table_size", "Table size", kTableSizes, 2)
            .withFlags(kParamRealloc)
            .withHelp("Texels per side of the LTC tables: 64 is the fit (assets/ltc/ggx.json); 16 and 32 are "
                      "resampled from it bilinearly at their own grid points (techniques/ltc/README.md)"),
        ParamSpec::choice("ltc.edge", "Edge integral", {"acos", "rational"}, 1)
            .withFlags(kParamRecompile)
            .withHelp("Per edge theta/(2 pi sin theta) (a x b): acos = the textbook formula (wrong for tiny and distant "
                      "lights, where a.b is 1 or just below it), rational = Heitz's rational fit, no acos"),
        ParamSpec::choice("ltc.horizon", "Horizon", {"clip", "sphere"}, 0)
            .withFlags(kParamRecompile)
            .withHelp("clip = the polygon clipped exactly to the shading point's horizon (Sutherland-Hodgman); "
                      "sphere = Heitz 2017: the unclipped polygon's vector form factor as a sphere, its clipped "
                      "form factor from the table (cheaper, approximate where a light straddles the horizon)"),
        ParamSpec::choice("ltc.diffuse_fresnel", "Diffuse Fresnel", {"none", "average"}, 1)
            .withHelp("The diffuse term's (1 - F(v.h)) factor, which varies over the light: none = dropped (diffuse "
                      "too bright by about F0), average = (1 - F0)(1 - the table's diffuse_fresnel at theta_v), its "
                      "cosine-weighted hemispherical mean"),
    };
    info.debugViews = {
        {"ltc.diffuse", 3, "diffuse radiance of the rectangular lights (the Lambert term through LTC with M = I)"},
        {"ltc.specular", 3, "specular radiance of the rectangular lights (the fitted LTC times F0 (magnitude - "
                            "fresnel) + fresnel)"},
        {"ltc.fit_error", 1, "the table's fit error at each pixel's (roughness, theta_v) cell (assets/ltc/README.md)"},
    };
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const Settings s = settingsFrom(frame.params());
    if (m_lut.size() != s.tableSize) m_lut.build(resampleLtcTable(shippedTable(), s.tableSize));
    addShade(frame, "ltc.shade", kArealightResource, s, "", GL_RGBA32F);
    addArealightComposite(frame, "ltc");
    addShade(frame, "ltc.view_diffuse", aovResource("ltc.diffuse"), s, "LTC_OUTPUT_DIFFUSE", GL_RGBA32F);
    addShade(frame, "ltc.view_specular", aovResource("ltc.specular"), s, "LTC_OUTPUT_SPECULAR", GL_RGBA32F);
    addShade(frame, "ltc.view_fit_error", aovResource("ltc.fit_error"), s, "LTC_OUTPUT_FIT_ERROR", GL_RGBA32F);
  }

  std::size_t ownedBytes() const override { return m_lut.bytes(); }

private:
  // One full-screen pass over the G-buffer: shaders/ltc/arealight.frag with `output` (empty for
  // the `arealight` resource, else a debug view's define).
  void addShade(FrameGraph& frame, const std::string& pass, const std::string& out, const Settings& s,
                const std::string& output, GLenum format) {
    std::vector<std::string> defines = s.defines;
    if (!output.empty()) defines.push_back(output);
    const int diffuseFresnel = s.diffuseFresnel;
    frame.addPass(pass,
        [&](PassBuilder& b) {
          b.read(res::kPosition);
          b.read(res::kNormal);
          b.read(res::kGeometry);
          b.read(res::kAlbedo);
          b.read(res::kMaterial);
          b.write(out, frameTexture(frame, format));
        },
        [this, pass, out, defines, diffuseFresnel](PassContext& ctx) {
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "ltc/arealight.frag"}, defines, pass});
          ctx.beginFullscreen(pass, {out});
          p.use();
          ctx.texture(res::kPosition).bind(0);
          ctx.texture(res::kNormal).bind(1);
          ctx.texture(res::kGeometry).bind(2);
          ctx.texture(res::kAlbedo).bind(3);
          ctx.texture(res::kMaterial).bind(4);
          m_lut.matrix().bind(5);
          m_lut.scale().bind(6);
          m_lut.sphere().bind(7);
          p.set("uPosition", 0)
              .set("uNormal", 1)
              .set("uGeometry", 2)
              .set("uAlbedo", 3)
              .set("uMaterial", 4)
              .set("uLtcMatrix", 5)
              .set("uLtcScale", 6)
              .set("uLtcSize", float(m_lut.size()))
              .set("uCameraPosition", ctx.view.cameraPosition)
              .set("uDiffuseFresnel", diffuseFresnel);
          p.set("uLtcSphere", 7); // used by ltc.horizon=sphere only (a missing uniform is ignored)
          ctx.common.bindLights(p);
          ctx.common.drawFullscreen();
        });
  }

  TechniqueInfo m_info = staticInfo();
  LtcLut m_lut;
};

} // namespace

void registerTechnique_ltc(TechniqueRegistry& registry) { registerTechniqueType<Ltc>(registry); }

} // namespace rtlab
