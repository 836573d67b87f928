#include "techniques/common/rsm/rsm_gbuffer.h"

#include "frame/frame_graph.h"
#include "gl/program_cache.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "shading/scene_gpu.h"
#include "util/error.h"

#include <glm/glm.hpp>

#include <vector>

namespace rtlab {
namespace {

gl::TextureDesc mapDesc(const LightSpace& ls, int resolution, GLenum format) {
  gl::TextureDesc d;
  d.target = GL_TEXTURE_2D_ARRAY;
  d.layers = ls.faces();
  d.width = d.height = resolution;
  d.format = format;
  return d;
}

// The uniforms of shaders/rsm/common/rsm.glsl but the samplers.
void setRsmSpace(gl::Program& p, const LightSpace& ls, int resolution) {
  std::vector<glm::mat4> viewProj(6, ls.viewProj[0]), inverse(6, glm::inverse(ls.viewProj[0]));
  for (int f = 0; f < ls.faces(); ++f) {
    viewProj[std::size_t(f)] = ls.viewProj[f];
    inverse[std::size_t(f)] = glm::inverse(ls.viewProj[f]);
  }
  p.set("uRsmProjection", int(ls.projection))
      .set("uRsmResolution", resolution)
      .set("uRsmViewProj", viewProj)
      .set("uRsmInvViewProj", inverse)
      .set("uRsmLightPosition", ls.position)
      .set("uRsmLightDirection", ls.direction)
      .set("uRsmTexelScale", ls.texelScale);
}

} // namespace

LightSpace rsmLightSpace(const Scene& scene, int resolution) {
  if (scene.lights.empty()) throw Error(ExitCode::Internal, "scene has no light 0");
  if (scene.lights[0].type == LightType::Rect)
    usageError(
        "light 0 is rectangular: the light-space G-buffer (rsm, lpv) supports directional, spot and point lights");
  return computeLightSpace(scene.lights[0], scene.worldBounds(), resolution);
}

// The maps are their own textures, not the shadow stage's "shadow.depth" with colour added: that
// map has the shadow stage's resolution, depth format, slope bias and culling (all shadow.*
// parameters), and a depth-comparison sampler; these need rsm's resolution and no bias. Only the
// light-space fit is shared (computeLightSpace).
void addRsmGBufferPass(FrameGraph& frame, int resolution) {
  if (frame.isProduced(kRsmFlux)) return;
  const LightSpace ls = rsmLightSpace(frame.scene(), resolution);
  const gl::TextureDesc flux = mapDesc(ls, resolution, GL_RGBA32F);
  const gl::TextureDesc normal = mapDesc(ls, resolution, GL_RGBA16F);
  const gl::TextureDesc position = mapDesc(ls, resolution, GL_RGBA32F);
  const gl::TextureDesc depth = mapDesc(ls, resolution, GL_DEPTH_COMPONENT32F);
  for (int face = 0; face < ls.faces(); ++face) {
    const std::string name = ls.faces() == 1 ? std::string("rsm.gbuffer") : "rsm.gbuffer.face" + std::to_string(face);
    frame.addPass(
        name,
        [&](PassBuilder& b) {
          b.writeAttachment(kRsmFlux, flux, 0, face);
          b.writeAttachment(kRsmNormal, normal, 0, face);
          b.writeAttachment(kRsmPosition, position, 0, face);
          b.writeAttachment(kRsmDepth, depth, 0, face);
        },
        [ls, face, resolution, name](PassContext& ctx) {
          gl::Program& p = ctx.programs.get({{"shading/surface.vert", "rsm/gbuffer.frag"}, {}, "rsm.gbuffer"});
          const gl::Framebuffer& fbo = ctx.framebuffer(name, {kRsmFlux, kRsmNormal, kRsmPosition}, kRsmDepth);
          glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
          glViewport(0, 0, resolution, resolution);
          glEnable(GL_DEPTH_TEST);
          glDepthFunc(GL_LESS);
          glDepthMask(GL_TRUE);
          glDisable(GL_BLEND);
          glDisable(GL_CULL_FACE);
          const float zero[4] = {0, 0, 0, 0}, one = 1.0f;
          for (int i = 0; i < 3; ++i)
            glClearNamedFramebufferfv(fbo.id(), GL_COLOR, i, zero);
          glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &one);
          p.use();
          ctx.common.bindLights(p);
          setRsmSpace(p, ls, resolution);
          p.set("uViewProj", ls.viewProj[face]);
          ctx.sceneGpu.draw(p, SceneGpu::Filter::Opaque, true);
        });
  }
}

int rsmResolution(const PassContext& ctx) {
  return ctx.texture(kRsmFlux).desc().width;
}

void bindRsm(PassContext& ctx, gl::Program& p, int firstUnit) {
  const int resolution = rsmResolution(ctx);
  ctx.texture(kRsmFlux).bind(GLuint(firstUnit));
  ctx.texture(kRsmNormal).bind(GLuint(firstUnit + 1));
  ctx.texture(kRsmPosition).bind(GLuint(firstUnit + 2));
  p.set("uRsmFlux", firstUnit).set("uRsmNormal", firstUnit + 1).set("uRsmPosition", firstUnit + 2);
  setRsmSpace(p, rsmLightSpace(ctx.scene, resolution), resolution);
}

void addRsmFluxView(FrameGraph& frame, int resolution, const std::string& view) {
  addRsmGBufferPass(frame, resolution);
  const std::string out = aovResource(view);
  frame.addPass(
      view,
      [&](PassBuilder& b) {
        b.read(kRsmFlux);
        b.read(kRsmNormal);
        b.read(kRsmPosition);
        b.write(out, frameTexture(frame, GL_RGBA32F));
      },
      [out](PassContext& ctx) {
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "rsm/flux_view.frag"}, {}, "rsm.flux-view"});
        ctx.beginFullscreen(out, {out});
        p.use();
        bindRsm(ctx, p, 0);
        ctx.common.drawFullscreen();
      });
}

} // namespace rtlab
