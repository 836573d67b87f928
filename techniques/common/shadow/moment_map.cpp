#include "techniques/common/shadow/moment_map.h"

#include "frame/frame_graph.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "shading/scene_gpu.h"
#include "techniques/common/shadow/shadow_depth.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

std::string momentSatResource(const std::string& technique) { return technique + ".sat"; }

ParamSpec momentSatBitsParam(const std::string& technique) {
  return ParamSpec::choice(technique + ".sat_bits", "Table bits", {"32", "64"}, 0)
      .withFlags(kParamRealloc)
      .withHelp("Integer width of the summed-area table's sums: 64 keeps each stored moment exactly (the 32-bit "
                "table's step is what limits a small box's variance), at twice the table's memory and passes");
}

int momentSatBits(const ParamSet& params, const std::string& technique) {
  return params.getEnumName(technique + ".sat_bits") == "64" ? 64 : 32;
}

float momentSatScale(const ParamSet& params, const MomentMapConfig& config) {
  // The widest box a lookup makes: boxMoments (shaders/shadow/common/moments.glsl) takes at least half a
  // texel; the visibility shaders clamp the search to [1, max_search] and the filter to
  // [min_penumbra, max_penumbra]. A half-width r spans at most floor(2r) + 2 texels, and never
  // more than the map.
  const std::string& id = config.technique;
  const double radius = std::max({0.5, double(params.getFloat(id + ".max_search")),
                                  double(params.getFloat(id + ".min_penumbra")),
                                  double(params.getFloat(id + ".max_penumbra"))});
  const double size = params.getInt("shadow.resolution");
  const double width = std::min(size, std::floor(2.0 * radius) + 2.0);
  // Every moment lies in [0,1] (z^k of z in [0,1], and the optimized transform maps [0,1] into
  // [0,1]), so |moment - offset| <= 0.5 with the offset and 1 without; 1% margin for 16-bit
  // storage's rounding. A box's sum, with up to half a unit of rounding per texel, must fit in
  // a signed 32-bit integer (64-bit: 2^49 at the defaults, 2^45 at the widest box; a float moment
  // minus the offset, times such a power of two, is an integer, so each texel's value is exact).
  const double magnitude = (config.satOffset ? 0.5 : 1.0) * 1.01;
  const int bits = momentSatBits(params, id);
  const double units = (std::ldexp(1.0, bits - 1) / (width * width) - 0.5) / magnitude;
  return float(std::ldexp(1.0, int(std::floor(std::log2(units)))));
}

void addMomentMapPasses(FrameGraph& frame, const MomentMapConfig& config) {
  const LightSpace ls = shadowLightSpace(frame.scene(), frame.params());
  if (ls.projection == LightProjection::Cube)
    usageError(config.technique + " supports directional lights and spot lights whose cone fits in 120 degrees; light 0 "
               "needs a cube map (use shadow_map, pcf or pcss)");
  const int size = frame.params().getInt("shadow.resolution");
  const std::string moments = config.technique + ".moments";
  const std::string depth = config.technique + ".moments_depth";
  const std::string sat = momentSatResource(config.technique);
  gl::TextureDesc momentDesc;
  momentDesc.format = config.format;
  momentDesc.width = momentDesc.height = size;
  gl::TextureDesc depthDesc = momentDesc;
  depthDesc.format = GL_DEPTH_COMPONENT24;
  gl::TextureDesc satDesc = momentDesc;
  satDesc.format = config.moments == 2 ? GL_RG32UI : GL_RGBA32UI;
  // 64-bit sums: the low words in the left half, the high words in the right half (sat.comp, WIDE).
  const bool wide = momentSatBits(frame.params(), config.technique) == 64;
  if (wide) satDesc.width = 2 * size;
  const std::string satImageFormat = config.moments == 2 ? "rg32ui" : "rgba32ui";
  std::vector<std::string> defines = {"MOMENTS " + std::to_string(config.moments)};
  if (config.optimized) defines.push_back("OPTIMIZED");

  frame.addPass(moments,
      [&](PassBuilder& b) {
        b.write(moments, momentDesc);
        b.write(depth, depthDesc);
      },
      [=](PassContext& ctx) {
        gl::Program& p = ctx.programs.get({{"shadow/moments.vert", "shadow/moments.frag"}, defines, moments});
        const gl::Framebuffer& fbo = ctx.framebuffer(moments, {moments}, depth);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, size, size);
        // Empty texels (no geometry) hold the far plane: z = 1.
        const float far[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        float clear[4] = {1.0f, 1.0f, 0.0f, 0.0f};
        if (config.moments == 4 && !config.optimized) std::copy(far, far + 4, clear);
        if (config.optimized) {
          // The optimized transform of z = 1: the column sums of the matrix plus the offset.
          clear[0] = float(-2.07224649 + 32.23703778 - 68.571074599 + 39.3703274134 + 0.035955884801);
          clear[1] = float(13.7948857237 - 59.4683975703 + 82.0359750338 - 35.364903257);
          clear[2] = float(0.105877704 - 1.9077466311 + 9.3496555107 - 6.6543490743);
          clear[3] = float(9.7924062118 - 33.7652110555 + 47.9456096605 - 23.9728048165);
        }
        glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clear);
        const float one = 1.0f;
        glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &one);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        const LightSpace light = shadowLightSpace(ctx.scene, ctx.params);
        p.set("uViewProj", light.viewProj[0])
            .set("uLightPosition", light.position)
            .set("uLightDirection", light.direction)
            .set("uLightNear", light.znear)
            .set("uLightFar", light.zfar);
        ctx.sceneGpu.draw(p, SceneGpu::Filter::Opaque, false);
      });

  // The table in two compute passes of shaders/shadow/sat.comp, one invocation per line: row scans
  // from the moments into the table, then column scans in place. The graph binds the table to image
  // unit 0 and plans the barriers (docs/frame-graph.md "Barriers"): image access before the column
  // scans, texture fetch before the first pass that samples the table.
  const glm::vec4 satOffset(config.satOffset ? 0.5f : 0.0f);
  const auto satProgram = [=](PassContext& ctx, int axis) -> gl::Program& {
    std::vector<std::string> satDefines = {"AXIS " + std::to_string(axis), "FORMAT " + satImageFormat};
    if (wide) satDefines.push_back("WIDE");
    gl::Program& p = ctx.programs.get({{"shadow/sat.comp"}, satDefines, "sat"});
    return p.set("uSize", size).set("uOffset", satOffset).set("uScale", momentSatScale(ctx.params, config));
  };
  const ComputeGrid lines = ComputeGrid::fixed({size, 1, 1});
  frame.addComputePass(sat + ".rows", lines,
      [&](PassBuilder& b) {
        b.read(moments);
        b.writeImage(sat, satDesc, 0);
      },
      [=](PassContext& ctx) -> gl::Program& {
        ctx.texture(moments).bind(0);
        return satProgram(ctx, 0).set("uInput", 0);
      });
  frame.addComputePass(sat + ".columns", lines, [&](PassBuilder& b) { b.readWriteImage(sat, 0); },
      [=](PassContext& ctx) -> gl::Program& { return satProgram(ctx, 1); });
}

void addMomentView(FrameGraph& frame, const std::string& technique, const std::string& view) {
  const std::string moments = technique + ".moments";
  const std::string out = aovResource(view);
  frame.addPass(view,
      [&](PassBuilder& b) {
        b.read(moments);
        b.write(out, frameTexture(frame, GL_RGBA32F));
      },
      [moments, out](PassContext& ctx) {
        // SHADOW_PROJECTION 0 shows the stored value as it is (it is already linear).
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "shadow/light_depth.frag"}, {"SHADOW_PROJECTION 0"}, "moment-view"});
        ctx.beginFullscreen(out, {out});
        p.use();
        ctx.texture(moments).bind(0);
        p.set("uDepth", 0).set("uNear", 0.0f).set("uFar", 1.0f);
        ctx.common.drawFullscreen();
      });
}

void bindMomentSat(PassContext& ctx, gl::Program& p, const MomentMapConfig& config, int unit) {
  ctx.texture(momentSatResource(config.technique)).bind(GLuint(unit));
  p.set("uSat", unit)
      .set("uSatOffset", glm::vec4(config.satOffset ? 0.5f : 0.0f))
      .set("uSatScale", momentSatScale(ctx.params, config))
      .set("uSatWide", momentSatBits(ctx.params, config.technique) == 64);
}

} // namespace rtlab
