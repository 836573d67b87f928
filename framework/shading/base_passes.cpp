#include "shading/base_passes.h"

#include "frame/frame_graph.h"
#include "frame/resource_pool.h"
#include "frame/stages.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/gpu_common.h"
#include "shading/scene_gpu.h"
#include "util/error.h"

#include <algorithm>

namespace rtlab {

gl::TextureDesc frameTexture(const FrameGraph& frame, GLenum format) {
  gl::TextureDesc d;
  d.format = format;
  d.width = frame.width();
  d.height = frame.height();
  return d;
}

std::string aovResource(const std::string& aov) { return "aov." + aov; }

std::string colorResource(const std::string& version) { return "color." + version; }

namespace {

// How lighting.frag consumes each effect of a stage that feeds it: the define that enables the
// code, and the sampler the output is bound to.
struct LightingInput {
  LightingEffect effect;
  const char* define;
  const char* sampler;
};
constexpr LightingInput kLightingInputs[] = {
    {LightingEffect::MultiplyLight0Direct, "HAS_VISIBILITY", "uVisibility"},
    {LightingEffect::MultiplyAmbientIndirect, "HAS_AO", "uAo"},
    {LightingEffect::AddIndirect, "HAS_INDIRECT", "uIndirect"},
};

const LightingInput& lightingInput(const StageInfo& stage) {
  for (const auto& in : kLightingInputs)
    if (in.effect == stage.lighting) return in;
  throw Error(ExitCode::Internal, std::string("lighting.frag has no input for effect ") + lightingEffectName(stage.lighting));
}

} // namespace

void addGBufferPass(FrameGraph& frame) {
  frame.addPass("gbuffer",
      [&](PassBuilder& b) {
        b.write(res::kPosition, frameTexture(frame, GL_RGBA32F));
        b.write(res::kNormal, frameTexture(frame, GL_RGBA16F));
        b.write(res::kGeometry, frameTexture(frame, GL_RGBA16F));
        b.write(res::kAlbedo, frameTexture(frame, GL_RGBA8));
        b.write(res::kMaterial, frameTexture(frame, GL_RGBA16F));
        b.write(res::kShadowPosition, frameTexture(frame, GL_RGBA32F));
        b.write(res::kShadowNormal, frameTexture(frame, GL_RGBA16F));
        b.write(res::kDepth, frameTexture(frame, GL_DEPTH_COMPONENT32F));
      },
      [](PassContext& ctx) {
        const gl::Framebuffer& fbo = ctx.framebuffer("gbuffer",
            {res::kPosition, res::kNormal, res::kGeometry, res::kAlbedo, res::kMaterial, res::kShadowPosition,
             res::kShadowNormal},
            res::kDepth);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, ctx.view.width, ctx.view.height);
        const float zero[4] = {0, 0, 0, 0};
        for (int i = 0; i < 7; ++i) glClearNamedFramebufferfv(fbo.id(), GL_COLOR, i, zero);
        const float one = 1.0f;
        glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &one);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
        gl::Program& p = ctx.programs.get({{"shading/surface.vert", "shading/surface.geom", "shading/gbuffer.frag"}, {}, "gbuffer"});
        p.set("uViewProj", ctx.view.viewProj)
            .set("uCameraPosition", ctx.view.cameraPosition)
            .set("uCameraForward", ctx.view.cameraForward);
        ctx.sceneGpu.draw(p, SceneGpu::Filter::Opaque, true);
      });
}

void addLightingPass(FrameGraph& frame, const std::string& output, bool rectLightsAsPoints) {
  frame.addPass("lighting",
      [&](PassBuilder& b) {
        for (const auto* r : {&res::kPosition, &res::kNormal, &res::kGeometry, &res::kAlbedo, &res::kMaterial}) b.read(*r);
        for (const auto& stage : stages())
          if (stage.feedsLighting()) b.readIfPresent(stage.output);
        b.write(output, frameTexture(frame, GL_RGBA16F));
        HdrClampCounters::declareUse(frame, b);
      },
      [output, rectLightsAsPoints](PassContext& ctx) {
        std::vector<std::string> defines;
        for (const auto& stage : stages())
          if (stage.feedsLighting() && ctx.has(stage.output)) defines.push_back(lightingInput(stage).define);
        if (!rectLightsAsPoints) defines.push_back("SKIP_RECT_LIGHTS");
        if (ctx.common.hdrClamp.counting()) defines.push_back("HDR_CLAMP_COUNT");
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "shading/lighting.frag"}, defines, "lighting"});
        ctx.beginFullscreen("lighting", {output});
        p.use();
        int unit = 0;
        auto bind = [&](const char* uniform, const std::string& resource) {
          ctx.texture(resource).bind(GLuint(unit));
          p.set(uniform, unit++);
        };
        bind("uPosition", res::kPosition);
        bind("uNormal", res::kNormal);
        bind("uGeometry", res::kGeometry);
        bind("uAlbedo", res::kAlbedo);
        bind("uMaterial", res::kMaterial);
        for (const auto& stage : stages())
          if (stage.feedsLighting() && ctx.has(stage.output)) bind(lightingInput(stage).sampler, stage.output);
        p.set("uCameraPosition", ctx.view.cameraPosition)
            .set("uInvViewProj", ctx.view.invViewProj)
            .set("uViewportSize", glm::vec2(ctx.view.width, ctx.view.height))
            .set("uAmbient", ctx.scene.ambient)
            .set("uBackground", ctx.scene.background);
        ctx.common.bindLights(p);
        // The G-buffer's emission clamp is counted here, per visible pixel (docs/stages.md).
        ctx.common.hdrClamp.bind(p, "gbuffer", "uEmissionClampSlot");
        ctx.common.hdrClamp.bind(p, "lighting");
        ctx.common.drawFullscreen();
      });
}

void addStageFallback(FrameGraph& frame, const std::string& fallback, const std::string& input, const std::string& output) {
  if (fallback == "transparent") addTransparentPass(frame, input, output);
  else throw Error(ExitCode::Internal, "no built-in fallback pass '" + fallback + "'");
}

void addTransparentPass(FrameGraph& frame, const std::string& input, const std::string& output) {
  frame.addPass("transparent",
      [&](PassBuilder& b) {
        b.read(input);
        b.read(res::kDepth);
        b.write(output, frameTexture(frame, GL_RGBA16F));
        HdrClampCounters::declareUse(frame, b);
      },
      [input, output](PassContext& ctx) {
        // Blending composites over the opaque colour, so the output starts as a copy of the input
        // (the input version stays readable: docs/stages.md "Colour versions").
        const gl::Texture& src = ctx.texture(input);
        glCopyImageSubData(src.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.texture(output).id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                           src.desc().width, src.desc().height, 1);
        const gl::Framebuffer& fbo = ctx.framebuffer("transparent", {output}, res::kDepth);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, ctx.view.width, ctx.view.height);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_FALSE);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        std::vector<std::string> defines;
        if (ctx.common.hdrClamp.counting()) defines.push_back("HDR_CLAMP_COUNT");
        gl::Program& p = ctx.programs.get({{"shading/surface.vert", "shading/forward.frag"}, defines, "forward"});
        setLayerUniforms(p, ctx);
        ctx.common.hdrClamp.bind(p, "transparent");
        ctx.sceneGpu.draw(p, SceneGpu::Filter::Transparent, true, ctx.view.cameraPosition);
      });
}

void setLayerUniforms(gl::Program& p, const PassContext& ctx) {
  p.set("uViewProj", ctx.view.viewProj)
      .set("uCameraPosition", ctx.view.cameraPosition)
      .set("uAmbient", ctx.scene.ambient);
  ctx.common.bindLights(p);
}

void addTonemapPass(FrameGraph& frame, const std::string& color) {
  frame.addPass("tonemap",
      [&](PassBuilder& b) {
        b.read(color);
        b.write(res::kColorLdr, frameTexture(frame, GL_RGBA16F));
      },
      [color](PassContext& ctx) {
        ctx.beginFullscreen("tonemap", {res::kColorLdr});
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "shading/tonemap.frag"}, {}, "tonemap"});
        p.use();
        ctx.texture(color).bind(0);
        p.set("uColor", 0)
            .set("uExposure", ctx.params.getFloat("tonemap.exposure"))
            .set("uOperator", ctx.params.getEnum("tonemap.operator"))
            .set("uEncodeSrgb", false);
        ctx.common.drawFullscreen();
      });
}

std::string addAovPass(FrameGraph& frame, const std::string& aov, const AovSource& aovSource) {
  const std::string out = aovResource(aov);
  std::string define;
  if (aov == "depth") define = "AOV_DEPTH";
  else if (aov == "normal") define = "AOV_NORMAL";
  else if (aov == "albedo") define = "AOV_ALBEDO";
  else if (aovSource.colorImage) define = "AOV_COLOR";
  const std::string source = aovSource.resource;
  const bool required = aovSource.required, coverage = aovSource.coverageAlpha;
  const float defaultValue = aovSource.neutral;
  frame.addPass(out,
      [&](PassBuilder& b) {
        for (const auto* r : {&res::kPosition, &res::kNormal, &res::kGeometry, &res::kAlbedo}) b.read(*r);
        if (!source.empty() && required) b.read(source);
        else if (!source.empty()) b.readIfPresent(source);
        b.write(out, frameTexture(frame, GL_RGBA32F));
      },
      [=](PassContext& ctx) {
        std::vector<std::string> defines;
        if (!define.empty()) defines.push_back(define);
        if (coverage) defines.push_back("AOV_COVERAGE_ALPHA");
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "shading/aov.frag"}, defines, "aov"});
        ctx.beginFullscreen(out, {out});
        p.use();
        ctx.texture(res::kPosition).bind(0);
        ctx.texture(res::kNormal).bind(1);
        ctx.texture(res::kGeometry).bind(2);
        ctx.texture(res::kAlbedo).bind(3);
        const bool hasSource = !source.empty() && ctx.has(source);
        if (hasSource) ctx.texture(source).bind(4);
        p.set("uPosition", 0).set("uNormal", 1).set("uGeometry", 2).set("uAlbedo", 3).set("uSource", 4)
            .set("uHasSource", hasSource).set("uDefault", defaultValue);
        ctx.common.drawFullscreen();
      });
  return out;
}

} // namespace rtlab
