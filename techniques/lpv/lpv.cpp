// lpv — light propagation volumes (Kaplanyan & Dachsbacher 2010, "Cascaded Light Propagation
// Volumes for Real-Time Indirect Illumination"), a technique of the indirect stage
// (docs/stages.md): the VPLs of light 0's light-space G-buffer (techniques/common/rsm/) injected
// into a grid as 2-band SH intensity distributions, propagated cell to cell lpv.iterations times
// (blocked by a geometry volume of the same texels' surfels), and the sum of the iterates looked
// up per pixel as irradiance. One cascade. The volume is rebuilt every frame from that frame's
// G-buffer, so a moved light 0 (light0.* keys) is seen at once and nothing is kept between frames.
// techniques/lpv/README.md has the coefficients, the energy argument, the guards and the measured
// cost and error.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "techniques/common/rsm/rsm_gbuffer.h"
#include "techniques/lpv/lpv_model.h"

#include <algorithm>
#include <array>
#include <string>

namespace rtlab {
namespace {

const std::array<std::string, 3> kChannels = {"r", "g", "b"};

// The three colour volumes of one set ("lpv.a.r", "lpv.a.g", "lpv.a.b").
std::array<std::string, 3> volumeSet(const std::string& set) {
  return {"lpv." + set + ".r", "lpv." + set + ".g", "lpv." + set + ".b"};
}

const std::string kGeometryVolume = "lpv.geometry";

gl::TextureDesc volumeDesc(int n) {
  gl::TextureDesc d;
  d.target = GL_TEXTURE_3D;
  d.format = GL_RGBA32F; // 16-bit halves lose the small per-VPL fluxes when summed (README "Guards")
  d.width = d.height = d.depth = n;
  d.minFilter = d.magFilter = GL_LINEAR;
  d.wrap = GL_CLAMP_TO_EDGE;
  return d;
}

lpv::GridFit gridFit(const Scene& scene, const ParamSet& params) {
  return lpv::fitGrid(scene.worldBounds(), params.getInt("lpv.grid"));
}

void setGridUniforms(gl::Program& p, const lpv::GridFit& g, const ParamSet& params) {
  p.set("uGridOrigin", g.origin)
      .set("uCellSize", g.cellSize)
      .set("uGridSize", g.n)
      .set("uShBands", params.getInt("lpv.sh_bands"));
}

void bindVolumes(PassContext& ctx, gl::Program& p, const std::array<std::string, 3>& set, int firstUnit,
                 const std::string& uniformPrefix) {
  for (int c = 0; c < 3; ++c) {
    ctx.texture(set[std::size_t(c)]).bind(GLuint(firstUnit + c));
    p.set(uniformPrefix + "RGB"[c], firstUnit + c);
  }
}

// Injection into `targets` (the light volume's three colours, or the geometry volume): one point
// per light-space texel, blended additively into the layered 3D target (shaders/lpv/inject.*).
void addInjection(FrameGraph& frame, const std::string& name, const std::vector<std::string>& targets,
                  const gl::TextureDesc& desc, bool geometry) {
  frame.addPass(
      name,
      [&](PassBuilder& b) {
        b.read(kRsmFlux);
        b.read(kRsmNormal);
        b.read(kRsmPosition);
        for (const std::string& t : targets)
          b.write(t, desc);
      },
      [targets, geometry, name, size = desc.width](PassContext& ctx) {
        std::vector<std::string> defines;
        if (geometry) defines.push_back("GEOMETRY_VOLUME");
        gl::Program& p = ctx.programs.get({{"lpv/inject.vert", "lpv/inject.geom", "lpv/inject.frag"},
                                           defines,
                                           geometry ? "lpv.geometry" : "lpv.inject"});
        const gl::Framebuffer& fbo = ctx.framebuffer(name, targets);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, size, size);
        const float zero[4] = {0, 0, 0, 0};
        for (std::size_t i = 0; i < targets.size(); ++i)
          glClearNamedFramebufferfv(fbo.id(), GL_COLOR, GLint(i), zero);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        glDisable(GL_DEPTH_TEST);
        p.use();
        bindRsm(ctx, p, 0);
        setGridUniforms(p, gridFit(ctx.scene, ctx.params), ctx.params);
        p.set("uInjectionOffset", ctx.params.getFloat("lpv.injection_offset")).set("uTargetSize", size);
        const LightSpace ls = rsmLightSpace(ctx.scene, rsmResolution(ctx));
        const int res = rsmResolution(ctx);
        glBindVertexArray(ctx.common.emptyVao.id());
        glDrawArrays(GL_POINTS, 0, res * res * ls.faces());
        glBindVertexArray(0);
      });
}

class Lpv final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "lpv";
    info.stage = "indirect";
    info.title = "Light propagation volumes (Kaplanyan & Dachsbacher 2010)";
    info.summary = "Light 0's VPLs injected into a grid as 2-band SH, propagated cell to cell with a geometry "
                   "volume's occlusion, looked up trilinearly as irradiance (one cascade)";
    info.showcaseScene = "cornell";
    info.params = {
        ParamSpec::integer("lpv.grid", "Grid", 32, 16, 64)
            .withUnit("cells per axis")
            .withFlags(kParamRealloc)
            .withHelp("Cells per axis of the cubic grid fitted to the scene's bounds (cell = longest side / "
                      "(grid - 1)); cost grows as grid^3, walls thinner than a cell leak"),
        ParamSpec::integer("lpv.iterations", "Iterations", 8, 0, 64)
            .withUnit("steps")
            .withHelp("Propagation steps: light travels one cell per step; 0 lights only the injected cells"),
        ParamSpec::integer("lpv.sh_bands", "SH bands", 2, 1, 2)
            .withHelp("2: four coefficients per colour (directional); 1: the constant band only (isotropic cells)"),
        ParamSpec::real("lpv.injection_offset", "Injection offset", 0.5, 0.0, 1.0)
            .withUnit("cells")
            .withHelp("Distance along the VPL's normal, in cells, at which it is injected; 0 lets surfaces light "
                      "themselves"),
        ParamSpec::real("lpv.lookup_offset", "Lookup offset", 0.0, 0.0, 1.0)
            .withUnit("cells")
            .withHelp("Distance along the surface normal, in cells, at which the volume is read; 0 reads at the "
                      "surface, where a wall on a cell face averages the cells on both its sides (leaks)"),
        ParamSpec::boolean("lpv.occlusion", "Occlusion", true)
            .withHelp("Block propagation by the geometry volume (the light-space texels as surfels)"),
        ParamSpec::integer("lpv.rsm_resolution", "VPL map resolution", 256, 64, 1024)
            .logScale()
            .withUnit("texels")
            .withFlags(kParamRealloc)
            .withHelp("Side of light 0's light-space G-buffer whose texels are the VPLs and surfels"),
        ParamSpec::real("lpv.intensity", "Intensity", 1.0, 0.0, 4.0)
            .withHelp("Multiplier of the indirect irradiance (1 = physical)"),
        ParamSpec::real("lpv.slice_height", "Slice height", 0.1, 0.0, 1.0)
            .withHelp("Debug view lpv.slice: the horizontal layer at this fraction of the grid's height"),
    };
    info.debugViews = {
        {"lpv.slice", 3, "one horizontal slice of the summed volume (x right, z down): fluence flux / cell^2"},
        {"lpv.injected", 3, "at each surface, the fluence of the injected volume's cell containing it"},
        {"lpv.geometry", 1, "at each surface, the geometry volume's largest blocking probability nearby"},
    };
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const ParamSet& params = frame.params();
    const int n = params.getInt("lpv.grid");
    const int iterations = params.getInt("lpv.iterations");
    const bool occlusion = params.getBool("lpv.occlusion");
    addRsmGBufferPass(frame, params.getInt("lpv.rsm_resolution"));

    const gl::TextureDesc volume = volumeDesc(n);
    const auto injected = volumeSet("a");
    addInjection(frame, "lpv.inject", {injected.begin(), injected.end()}, volume, false);
    if (occlusion && iterations > 0) addInjection(frame, "lpv.geometry", {kGeometryVolume}, volumeDesc(n + 1), true);

    const float k = lpv::solidAngleNormalisation();
    for (int i = 1; i <= iterations; ++i) {
      const auto src = volumeSet(i % 2 == 1 ? "a" : "b");
      const auto dst = volumeSet(i % 2 == 1 ? "b" : "a");
      const auto sum = volumeSet("sum");
      frame.addComputePass(
          "lpv.propagate" + std::to_string(i), ComputeGrid::of(dst[0]),
          [&](PassBuilder& b) {
            for (const std::string& s : src)
              b.read(s);
            if (occlusion) b.read(kGeometryVolume);
            for (int c = 0; c < 3; ++c)
              b.writeImage(dst[std::size_t(c)], volume, c);
            for (int c = 0; c < 3; ++c) {
              if (i == 1)
                b.writeImage(sum[std::size_t(c)], volume, 3 + c);
              else
                b.readWriteImage(sum[std::size_t(c)], 3 + c);
            }
          },
          [src, occlusion, first = i == 1, k](PassContext& ctx) -> gl::Program& {
            gl::Program& p = ctx.programs.get({{"lpv/propagate.comp"}, {}, "lpv.propagate"});
            bindVolumes(ctx, p, src, 0, "uSrc");
            if (occlusion) ctx.texture(kGeometryVolume).bind(3);
            setGridUniforms(p, gridFit(ctx.scene, ctx.params), ctx.params);
            p.set("uOcclusion", occlusion)
                .set("uFirst", first)
                .set("uFrontSolidAngle", lpv::kFrontSolidAngle * k)
                .set("uSideSolidAngle", lpv::kSideSolidAngle * k);
            return p;
          });
    }
    const auto result = volumeSet(iterations == 0 ? "a" : "sum");

    frame.addPass(
        "lpv.lookup",
        [&](PassBuilder& b) {
          b.read(res::kPosition);
          b.read(res::kNormal);
          b.read(res::kGeometry);
          for (const std::string& r : result)
            b.read(r);
          b.write("indirect", frameTexture(frame, GL_RGBA32F));
        },
        [result](PassContext& ctx) {
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "lpv/lookup.frag"}, {}, "lpv.lookup"});
          ctx.beginFullscreen("lpv.lookup", {"indirect"});
          p.use();
          ctx.texture(res::kPosition).bind(0);
          ctx.texture(res::kNormal).bind(1);
          ctx.texture(res::kGeometry).bind(2);
          p.set("uPosition", 0).set("uNormal", 1).set("uGeometry", 2);
          bindVolumes(ctx, p, result, 3, "uSum");
          setGridUniforms(p, gridFit(ctx.scene, ctx.params), ctx.params);
          p.set("uIntensity", ctx.params.getFloat("lpv.intensity"))
              .set("uLookupOffset", ctx.params.getFloat("lpv.lookup_offset"));
          ctx.common.drawFullscreen();
        });

    addView(frame, "lpv.slice", "VIEW_SLICE", {result.begin(), result.end()});
    addView(frame, "lpv.injected", "VIEW_INJECTED", {injected.begin(), injected.end()});
    if (occlusion && iterations > 0)
      addView(frame, "lpv.geometry", "VIEW_GEOMETRY", {kGeometryVolume});
    else
      addEmptyGeometryView(frame);
  }

private:
  // A debug view pass (shaders/lpv/view.frag), culled unless the view is requested.
  static void addView(FrameGraph& frame, const std::string& view, const std::string& define,
                      const std::vector<std::string>& volumes) {
    const std::string out = aovResource(view);
    frame.addPass(
        view,
        [&](PassBuilder& b) {
          b.read(res::kPosition);
          b.read(res::kGeometry);
          for (const std::string& v : volumes)
            b.read(v);
          b.write(out, frameTexture(frame, GL_RGBA32F));
        },
        [out, define, volumes, view](PassContext& ctx) {
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "lpv/view.frag"}, {define}, view});
          ctx.beginFullscreen(view, {out});
          p.use();
          ctx.texture(res::kPosition).bind(0);
          ctx.texture(res::kGeometry).bind(1);
          p.set("uPosition", 0).set("uGeometry", 1);
          // The geometry volume is one texture: all three samplers point at it (a sampler left on
          // unit 0 would clash with uPosition's type there).
          for (std::size_t c = 0; c < 3; ++c) {
            const std::size_t v = std::min(c, volumes.size() - 1);
            ctx.texture(volumes[v]).bind(GLuint(2 + v));
            p.set(std::string("uVolume") + "RGB"[c], int(2 + v));
          }
          const lpv::GridFit g = gridFit(ctx.scene, ctx.params);
          setGridUniforms(p, g, ctx.params);
          const int layer = std::min(int(ctx.params.getFloat("lpv.slice_height") * float(g.n)), g.n - 1);
          p.set("uSliceLayer", layer);
          ctx.common.drawFullscreen();
        });
  }
  // Without occlusion there is no geometry volume: the view is 0 on every surface.
  static void addEmptyGeometryView(FrameGraph& frame) {
    const std::string out = aovResource("lpv.geometry");
    frame.addPass(
        "lpv.geometry_view", [&](PassBuilder& b) { b.write(out, frameTexture(frame, GL_RGBA32F)); },
        [out](PassContext& ctx) {
          ctx.beginFullscreen("lpv.geometry_view", {out});
          const float zero[4] = {0, 0, 0, 0};
          glClearBufferfv(GL_COLOR, 0, zero);
        });
  }

  TechniqueInfo m_info = staticInfo();
};

} // namespace

void registerTechnique_lpv(TechniqueRegistry& registry) {
  registerTechniqueType<Lpv>(registry);
}

} // namespace rtlab
