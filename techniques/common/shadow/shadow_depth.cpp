#include "techniques/common/shadow/shadow_depth.h"

#include "frame/frame_graph.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/gpu_common.h"
#include "shading/scene_gpu.h"
#include "util/error.h"

#include <cmath>

namespace rtlab {
namespace {

GLenum depthFormat(const ParamSet& params) {
  switch (params.getEnum("shadow.depth_format")) {
  case 0: return GL_DEPTH_COMPONENT16;
  case 1: return GL_DEPTH_COMPONENT24;
  default: return GL_DEPTH_COMPONENT32F;
  }
}

} // namespace

LightSpace shadowLightSpace(const Scene& scene, const ParamSet& params) {
  if (scene.lights.empty()) throw Error(ExitCode::Internal, "scene has no light 0");
  return computeLightSpace(scene.lights[0], scene.worldBounds(), params.getInt("shadow.resolution"));
}

std::string shadowProjectionDefine(const LightSpace& ls) {
  return "SHADOW_PROJECTION " + std::to_string(int(ls.projection));
}

void addShadowDepthPass(FrameGraph& frame) {
  if (frame.isProduced(kShadowDepth)) return;
  const LightSpace ls = shadowLightSpace(frame.scene(), frame.params());
  gl::TextureDesc desc;
  desc.target = ls.projection == LightProjection::Cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
  desc.format = depthFormat(frame.params());
  desc.width = desc.height = frame.params().getInt("shadow.resolution");
  desc.wrap = ls.projection == LightProjection::Cube ? GL_CLAMP_TO_EDGE : GL_CLAMP_TO_BORDER;
  desc.depthCompare = true;
  frame.addPass("shadow.depth", [&](PassBuilder& b) { b.write(kShadowDepth, desc); },
      [ls](PassContext& ctx) {
        gl::Texture& map = ctx.texture(kShadowDepth);
        gl::Program& p = ctx.programs.get({{"shadow/depth_only.vert", "shadow/depth_only.frag"}, {}, "depth-only"});
        glViewport(0, 0, map.desc().width, map.desc().height);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        const float slope = ctx.params.getFloat("shadow.slope_bias");
        if (slope > 0.0f) {
          glEnable(GL_POLYGON_OFFSET_FILL);
          glPolygonOffset(slope, 0.0f);
        }
        if (ctx.params.getBool("shadow.cull_front")) {
          glEnable(GL_CULL_FACE);
          glCullFace(GL_FRONT);
        } else {
          glDisable(GL_CULL_FACE);
        }
        for (int face = 0; face < ls.faces(); ++face) {
          const gl::Framebuffer& fbo =
              ctx.framebuffer("shadow.depth", {}, kShadowDepth, ls.projection == LightProjection::Cube ? face : -1);
          glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
          const float one = 1.0f;
          glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &one);
          p.set("uViewProj", ls.viewProj[face]);
          ctx.sceneGpu.draw(p, SceneGpu::Filter::Opaque, false);
        }
      });
}

void bindShadowSpace(PassContext& ctx, gl::Program& p, int unit) {
  const LightSpace ls = shadowLightSpace(ctx.scene, ctx.params);
  if (unit >= 0) {
    ctx.texture(kShadowDepth).bind(GLuint(unit));
    p.set("uShadowMap", unit);
  }
  const Light& light = ctx.scene.lights.at(0);
  // PCSS/VSSM/MSM light size: disk radius (spot, point) or tan(angular radius) (directional).
  const float lightSize = light.type == LightType::Directional ? std::tan(glm::radians(light.angle)) : light.radius;
  p.set("uLightViewProj", ls.viewProj[0])
      .set("uLightSize", lightSize)
      .set("uLightPosition", ls.position)
      .set("uLightDirection", ls.direction)
      .set("uLightNear", ls.znear)
      .set("uLightFar", ls.zfar)
      .set("uTexelScale", ls.texelScale)
      .set("uMapResolution", float(ctx.params.getInt("shadow.resolution")))
      .set("uNormalBias", ctx.params.getFloat("shadow.normal_bias"))
      .set("uConstantBias", ctx.params.getFloat("shadow.constant_bias"));
}

} // namespace rtlab
