// area_mc — Monte-Carlo integration of rectangular lights on the GPU, the baseline of the arealight
// stage (docs/contract.md "Area lights"): per pixel and per light, area_mc.samples samples, each a
// uniform point of the rectangle and a GGX-sampled direction, combined by multiple importance
// sampling with the power heuristic (Veach & Guibas 1995). Unbiased, noisy, its cost grows linearly
// with the samples; the CPU reference runs the same estimator (area_mc_model.h).
// techniques/area_mc/README.md has the estimator, the patterns, the artifacts and the measured cost.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "techniques/common/arealight/arealight_composite.h"

namespace rtlab {
namespace {

constexpr int kNoiseSize = 64; // shaders/area_mc/area_mc.frag kNoiseSize

class AreaMc final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "area_mc";
    info.stage = "arealight";
    info.title = "Monte-Carlo area lights (light-area + GGX sampling, MIS)";
    info.summary = "Per pixel and light, area_mc.samples points of the rectangle and GGX directions, combined with "
                   "the power heuristic (unbiased, noisy, cost linear in the samples)";
    info.showcaseScene = "arealight";
    info.params = {
        ParamSpec::integer("area_mc.samples", "Samples", 16, 1, 4096)
            .logScale()
            .withUnit("samples")
            .withHelp("Monte-Carlo samples per pixel per rectangular light; each is one point of the rectangle and "
                      "one GGX direction"),
        ParamSpec::choice("area_mc.pattern", "Pattern", {"stratified", "r2_blue_noise"}, 0)
            .withFlags(kParamRecompile)
            .withHelp("stratified: a jittered floor(sqrt(N))^2 grid (the rest uniform), hashed per pixel; "
                      "r2_blue_noise: the R2 sequence shifted per pixel by a void-and-cluster blue-noise mask"),
        ParamSpec::choice("area_mc.strategy", "Strategy", {"mis", "light", "brdf"}, 0)
            .withHelp("mis: both, power heuristic; light: rectangle points only (fireflies on glossy surfaces); "
                      "brdf: GGX directions only (noisy on rough surfaces under a small light)"),
        ParamSpec::integer("area_mc.seed", "Seed", 1, 0, 65535)
            .withHelp("Seed of the per-pixel sample pattern (the GPU passes have no frame seed)"),
    };
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const bool blueNoise = frame.params().getEnumName("area_mc.pattern") == "r2_blue_noise";
    frame.addPass(
        "area_mc.estimate",
        [&](PassBuilder& b) {
          b.read(res::kPosition);
          b.read(res::kNormal);
          b.read(res::kGeometry);
          b.read(res::kAlbedo);
          b.read(res::kMaterial);
          b.write(kArealightResource, frameTexture(frame, GL_RGBA32F));
        },
        [this, blueNoise](PassContext& ctx) {
          std::vector<std::string> defines;
          if (blueNoise) defines.push_back("PATTERN_BLUE_NOISE");
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "area_mc/area_mc.frag"}, defines, "area_mc"});
          ctx.beginFullscreen("area_mc.estimate", {kArealightResource});
          p.use();
          ctx.texture(res::kPosition).bind(0);
          ctx.texture(res::kNormal).bind(1);
          ctx.texture(res::kGeometry).bind(2);
          ctx.texture(res::kAlbedo).bind(3);
          ctx.texture(res::kMaterial).bind(4);
          p.set("uPosition", 0)
              .set("uNormal", 1)
              .set("uGeometry", 2)
              .set("uAlbedo", 3)
              .set("uMaterial", 4)
              .set("uCameraPosition", ctx.view.cameraPosition)
              .set("uSamples", ctx.params.getInt("area_mc.samples"))
              .set("uStrategy", ctx.params.getEnum("area_mc.strategy"))
              .set("uSeed", unsigned(ctx.params.getInt("area_mc.seed")));
          if (blueNoise) {
            if (!m_noise) m_noise = makeBlueNoiseTexture(kNoiseSize, 5, "area_mc.blue-noise");
            m_noise.bind(5);
            p.set("uNoise", 5);
          }
          ctx.common.bindLights(p);
          ctx.common.drawFullscreen();
        });
    addArealightComposite(frame, "area_mc");
  }

  std::size_t ownedBytes() const override {
    return m_noise ? std::size_t(kNoiseSize) * kNoiseSize * 2 : 0; // R16F
  }

private:
  TechniqueInfo m_info = staticInfo();
  gl::Texture m_noise; // created on the first blue-noise frame
};

} // namespace

void registerTechnique_area_mc(TechniqueRegistry& registry) {
  registerTechniqueType<AreaMc>(registry);
}

} // namespace rtlab
