#include "techniques/common/shadow/shadow_pass.h"

#include "frame/frame_graph.h"
#include "frame/technique.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "techniques/common/shadow/shadow_depth.h"
#include "util/sample_patterns.h"

#include <algorithm>
#include <cstdint>

namespace rtlab {

void addShadowScreenPass(FrameGraph& frame, const ShadowScreenPass& pass) {
  if (pass.depthMap) addShadowDepthPass(frame);
  std::vector<std::string> defines = {shadowProjectionDefine(shadowLightSpace(frame.scene(), frame.params()))};
  defines.insert(defines.end(), pass.defines.begin(), pass.defines.end());
  frame.addPass(pass.name,
      [&](PassBuilder& b) {
        if (pass.depthMap) b.read(kShadowDepth);
        for (const auto& r : pass.reads) b.read(r);
        if (pass.declare) pass.declare(b);
        b.read(res::kShadowPosition);
        b.read(res::kShadowNormal);
        b.write(pass.output, frameTexture(frame, pass.format));
      },
      [pass, defines](PassContext& ctx) {
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", pass.fragment}, defines, pass.name});
        ctx.beginFullscreen(pass.name, {pass.output});
        p.use();
        ctx.texture(res::kShadowPosition).bind(0);
        ctx.texture(res::kShadowNormal).bind(1);
        p.set("uPosition", 0).set("uGeometry", 1);
        bindShadowSpace(ctx, p, pass.depthMap ? 2 : -1);
        if (pass.bind) pass.bind(ctx, p);
        ctx.common.drawFullscreen();
      });
}

std::vector<DebugView> softShadowDebugViews(const std::string& technique) {
  return {{technique + ".blocker_depth", 1,
           "mean blocker depth, 0 at the light's near plane .. 1 at its far plane; 0 = no blocker"},
          {technique + ".penumbra", 1, "filter radius as a fraction of " + technique + ".max_penumbra"}};
}

void addSoftShadowPasses(FrameGraph& frame, const std::string& technique, ShadowScreenPass pass) {
  const std::vector<std::string> baseDefines = pass.defines;
  const std::pair<std::string, std::string> outputs[3] = {
      {"visibility", technique + ".visibility"},
      {aovResource(technique + ".blocker_depth"), technique + ".blocker_depth"},
      {aovResource(technique + ".penumbra"), technique + ".penumbra"}};
  for (int i = 0; i < 3; ++i) {
    pass.output = outputs[i].first;
    pass.name = outputs[i].second;
    pass.format = i == 0 ? GL_R16F : GL_RGBA32F;
    pass.defines = baseDefines;
    pass.defines.push_back("OUTPUT " + std::to_string(i));
    addShadowScreenPass(frame, pass);
  }
}

DebugView lightDepthView(const std::string& technique) {
  return {technique + ".light_depth", 1,
          "light-space depth of light 0, linear from its near (0) to far (1) plane (cube maps unwrapped)"};
}

void addLightDepthView(FrameGraph& frame, const std::string& view, ShadowFilterKit& kit) {
  addShadowDepthPass(frame);
  const std::string projection = shadowProjectionDefine(shadowLightSpace(frame.scene(), frame.params()));
  const std::string out = aovResource(view);
  frame.addPass(view,
      [&](PassBuilder& b) {
        b.read(kShadowDepth);
        b.write(out, frameTexture(frame, GL_RGBA32F));
      },
      [&kit, projection, out](PassContext& ctx) {
        gl::Program& p =
            ctx.programs.get({{"common/fullscreen.vert", "shadow/light_depth.frag"}, {projection}, "light-depth-view"});
        ctx.beginFullscreen(out, {out});
        p.use();
        kit.bindRawDepth(ctx, p, "uDepth", 0);
        const LightSpace ls = shadowLightSpace(ctx.scene, ctx.params);
        p.set("uNear", ls.znear).set("uFar", ls.zfar);
        ctx.common.drawFullscreen();
      });
}

std::vector<ParamSpec> softShadowParams(const std::string& id, double maxPenumbra, double penumbraUpper,
                                        double searchUpper) {
  return {
      ParamSpec::real(id + ".min_penumbra", "Min penumbra", 1.0, 0.0, 64.0).withUnit("texels")
          .withHelp("Smallest filter radius (0 keeps contacts and zero-size lights hard)"),
      ParamSpec::real(id + ".max_penumbra", "Max penumbra", maxPenumbra, 1.0, penumbraUpper).withUnit("texels")
          .withHelp("Largest filter radius"),
      ParamSpec::real(id + ".max_search", "Max search radius", 64.0, 1.0, searchUpper).withUnit("texels")
          .withHelp("Cap of the blocker-search radius derived from the light's size"),
  };
}

void setSoftShadowUniforms(PassContext& ctx, gl::Program& p, const std::string& id) {
  const float minPenumbra = ctx.params.getFloat(id + ".min_penumbra");
  p.set("uMinPenumbra", minPenumbra)
      .set("uMaxPenumbra", std::max(ctx.params.getFloat(id + ".max_penumbra"), minPenumbra))
      .set("uMaxSearch", ctx.params.getFloat(id + ".max_search"));
}

std::vector<glm::vec2> ShadowFilterKit::taps(Pattern pattern, int count) {
  count = std::clamp(count, 1, kMaxTaps);
  if (pattern == Pattern::Grid) return gridPattern(count);
  return poissonDiskPattern(count, 7);
}

void ShadowFilterKit::ensure() {
  if (m_noise) return;
  m_noise = makeBlueNoiseTexture(kNoiseSize, 1, "blue-noise");
  const float border[4] = {1, 1, 1, 1};
  m_linearCompare = gl::Sampler("shadow.linear-compare");
  m_raw = gl::Sampler("shadow.raw-depth");
  for (GLuint s : {m_linearCompare.id(), m_raw.id()}) {
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
  }
  glSamplerParameteri(m_linearCompare.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(m_linearCompare.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(m_linearCompare.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(m_linearCompare.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glSamplerParameteri(m_raw.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(m_raw.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(m_raw.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
}

void ShadowFilterKit::bindFilter(gl::Program& p, const std::vector<glm::vec2>& taps, bool rotate, bool receiverPlane,
                                 bool linearCompare) {
  ensure();
  m_noise.bind(3);
  if (linearCompare) glBindSampler(2, m_linearCompare.id());
  p.set("uTaps", taps)
      .set("uTapCount", int(taps.size()))
      .set("uRotationNoise", 3)
      .set("uRotateTaps", rotate)
      .set("uReceiverPlaneBias", receiverPlane);
}

void ShadowFilterKit::bindRawDepth(PassContext& ctx, gl::Program& p, const char* uniform, int unit) {
  ensure();
  ctx.texture(kShadowDepth).bind(GLuint(unit));
  glBindSampler(GLuint(unit), m_raw.id());
  p.set(uniform, unit);
}

} // namespace rtlab
