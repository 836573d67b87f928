#include "techniques/common/ao/ao_pass.h"

#include "frame/frame_graph.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"

#include <glm/glm.hpp>

namespace rtlab {
namespace {

struct AoLayout {
  int scale = 1; // 1 full resolution, 2 half
  int width = 0, height = 0;
};

AoLayout aoLayout(const FrameGraph& frame, const std::string& technique) {
  AoLayout l;
  l.scale = frame.params().getBool(technique + ".half_resolution") ? 2 : 1;
  l.width = (frame.width() + l.scale - 1) / l.scale;
  l.height = (frame.height() + l.scale - 1) / l.scale;
  return l;
}

gl::TextureDesc aoTexture(const AoLayout& l, GLenum format) {
  gl::TextureDesc d;
  d.format = format;
  d.width = l.width;
  d.height = l.height;
  return d;
}

// View-space xy at linear depth 1 seen through frame pixel coordinate f: with a perspective
// projection P (clip.w = -z), ndc.x = (P00 x + P20 z) / -z, so x / depth = (ndc.x + P20) / P00,
// ndc.x = 2 f.x / width - 1: x = depth * (f.x * 2 / (width P00) + (P20 - 1) / P00), and alike y.
glm::vec4 viewRay(const FrameView& v) {
  const glm::mat4& p = v.proj;
  return {2.0f / (float(v.width) * p[0][0]), 2.0f / (float(v.height) * p[1][1]), (p[2][0] - 1.0f) / p[0][0],
          (p[2][1] - 1.0f) / p[1][1]};
}

// The uniforms of shaders/ao/common/ao_common.glsl and bilateral.glsl, ao.view on unit 0.
void bindAoCommon(PassContext& ctx, gl::Program& p, const AoLayout& l) {
  ctx.texture(aores::kView).bind(0);
  const float radius = ctx.params.getFloat("ao.radius");
  p.set("uAoView", 0)
      .set("uProj", ctx.view.proj)
      .set("uViewRay", viewRay(ctx.view))
      .set("uAoSize", glm::ivec2(l.width, l.height))
      .set("uFullSize", glm::ivec2(ctx.view.width, ctx.view.height))
      .set("uScale", l.scale)
      .set("uRadius", radius)
      .set("uPlaneSigma", 0.1f * radius);
}

void addPrepare(FrameGraph& frame, const std::string& technique, const AoLayout& l) {
  const std::string name = technique + ".prepare";
  frame.addPass(
      name,
      [&](PassBuilder& b) {
        b.read(res::kPosition);
        b.read(res::kNormal);
        b.read(res::kGeometry);
        b.write(aores::kView, aoTexture(l, GL_RGBA32F));
      },
      [name, l](PassContext& ctx) {
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "ao/prepare.frag"}, {}, "ao.prepare"});
        ctx.beginFullscreen(name, {aores::kView});
        p.use();
        ctx.texture(res::kPosition).bind(0);
        ctx.texture(res::kNormal).bind(1);
        ctx.texture(res::kGeometry).bind(2);
        p.set("uPosition", 0)
            .set("uNormal", 1)
            .set("uGeometry", 2)
            .set("uView", ctx.view.view)
            .set("uScale", l.scale)
            .set("uFullSize", glm::ivec2(ctx.view.width, ctx.view.height));
        ctx.common.drawFullscreen();
      });
}

// The estimator writing `output` (ao.raw, or with AO_PATTERN the pattern view at frame size).
void addEstimator(FrameGraph& frame, const AoEstimatorPass& pass, AoKit& kit, const AoLayout& l,
                  const std::string& name, const std::string& output, bool pattern) {
  std::vector<std::string> defines = pass.defines;
  if (pattern) defines.push_back("AO_PATTERN");
  frame.addPass(
      name,
      [&](PassBuilder& b) {
        b.read(aores::kView);
        b.write(output, pattern ? frameTexture(frame, GL_RGBA32F) : aoTexture(l, GL_R16F));
      },
      [pass, defines, l, name, output, pattern, &kit](PassContext& ctx) {
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", pass.fragment}, defines, name});
        ctx.beginFullscreen(name, {output});
        p.use();
        bindAoCommon(ctx, p, l);
        kit.bindNoise(p);
        if (pattern) p.set("uPatternPixel", glm::ivec2(l.width / 2, l.height / 2));
        if (pass.bind) pass.bind(ctx, p);
        ctx.common.drawFullscreen();
      });
}

void addBlur(FrameGraph& frame, const std::string& technique, const AoLayout& l, const std::string& source,
             const std::string& output, glm::ivec2 direction) {
  const std::string name = technique + (direction.x ? ".blur_x" : ".blur_y");
  frame.addPass(
      name,
      [&](PassBuilder& b) {
        b.read(source);
        b.read(aores::kView);
        b.write(output, aoTexture(l, GL_R16F));
      },
      [=](PassContext& ctx) {
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "ao/blur.frag"}, {}, "ao.blur"});
        ctx.beginFullscreen(name, {output});
        p.use();
        bindAoCommon(ctx, p, l);
        ctx.texture(source).bind(1);
        p.set("uSource", 1)
            .set("uDirection", direction)
            .set("uBlurRadius", ctx.params.getInt(technique + ".blur_radius"));
        ctx.common.drawFullscreen();
      });
}

// Resolves `source` (AO resolution) to frame resolution into `output`: the stage's "ao" (R16F) or
// a debug view (RGBA32F with mask); `nearest` skips the depth-aware upsampling.
void addResolve(FrameGraph& frame, const std::string& name, const AoLayout& l, const std::string& source,
                const std::string& output, bool aov, bool nearest) {
  std::vector<std::string> defines;
  if (aov) defines.push_back("OUTPUT_AOV");
  if (nearest) defines.push_back("NEAREST");
  frame.addPass(
      name,
      [&](PassBuilder& b) {
        b.read(source);
        b.read(aores::kView);
        b.read(res::kPosition);
        b.write(output, frameTexture(frame, aov ? GL_RGBA32F : GL_R16F));
      },
      [=](PassContext& ctx) {
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "ao/resolve.frag"}, defines, "ao.resolve"});
        ctx.beginFullscreen(name, {output});
        p.use();
        bindAoCommon(ctx, p, l);
        ctx.texture(source).bind(1);
        ctx.texture(res::kPosition).bind(2);
        p.set("uSource", 1).set("uPosition", 2);
        ctx.common.drawFullscreen();
      });
}

} // namespace

std::vector<ParamSpec> aoFilterParams(const std::string& t) {
  return {
      ParamSpec::boolean(t + ".blur", "Bilateral blur", true)
          .withHelp("Depth- and normal-aware separable blur of the raw AO (removes the rotation noise)"),
      ParamSpec::integer(t + ".blur_radius", "Blur radius", 2, 1, 8)
          .withUnit("AO pixels")
          .withHelp(
              "Half-width of each blur direction; Gaussian sigma = radius/2 (half-resolution pixels when halved)"),
      ParamSpec::boolean(t + ".half_resolution", "Half resolution", false)
          .withFlags(kParamRealloc)
          .withHelp("Estimate at half width and height, then upsample depth-aware to the frame"),
  };
}

std::vector<DebugView> aoDebugViews(const std::string& t) {
  return {{t + ".raw", 1, "AO straight from the estimator, before the blur (nearest-upsampled at half resolution)"},
          {t + ".blurred", 1, "AO after the blur and the upsampling (the stage output)"},
          {t + ".pattern", 3,
           "the samples of the centre pixel: green unoccluded, red occluded, the pixel white, raw AO grey"}};
}

void AoKit::bindNoise(gl::Program& program) {
  if (!m_noise) m_noise = makeBlueNoiseTexture(kNoiseSize, 3, "ao.blue-noise");
  m_noise.bind(1);
  program.set("uAoNoise", 1);
}

void addAoPasses(FrameGraph& frame, const AoEstimatorPass& pass, AoKit& kit) {
  const std::string& t = pass.technique;
  const AoLayout l = aoLayout(frame, t);
  const bool blur = frame.params().getBool(t + ".blur");
  // At full resolution the last pass writes the stage output itself (no resolve copy).
  const bool full = l.scale == 1;
  const std::string raw = full && !blur ? std::string("ao") : aores::kRaw;
  const std::string filtered = !blur ? raw : full ? std::string("ao") : aores::kBlurred;
  addPrepare(frame, t, l);
  addEstimator(frame, pass, kit, l, t + ".estimate", raw, false);
  if (blur) {
    addBlur(frame, t, l, raw, aores::kBlurX, {1, 0});
    addBlur(frame, t, l, aores::kBlurX, filtered, {0, 1});
  }
  if (!full) addResolve(frame, t + ".resolve", l, filtered, "ao", false, false);
  addResolve(frame, t + ".view_raw", l, raw, aovResource(t + ".raw"), true, true);
  addResolve(frame, t + ".view_blurred", l, filtered, aovResource(t + ".blurred"), true, false);
  addEstimator(frame, pass, kit, l, t + ".view_pattern", aovResource(t + ".pattern"), true);
}

void AoTechnique::setup(FrameGraph& frame) {
  AoEstimatorPass pass = estimator(frame.params());
  pass.technique = m_info.id;
  addAoPasses(frame, pass, m_kit);
}

TechniqueInfo AoTechnique::withAoChain(TechniqueInfo info) {
  for (auto& p : aoFilterParams(info.id))
    info.params.push_back(std::move(p));
  info.debugViews = aoDebugViews(info.id);
  return info;
}

} // namespace rtlab
