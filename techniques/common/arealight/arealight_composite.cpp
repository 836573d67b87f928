#include "techniques/common/arealight/arealight_composite.h"

#include "gl/program_cache.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "shading/hdr_clamp.h"

namespace rtlab {

void addArealightComposite(FrameGraph& frame, const std::string& technique) {
  const std::string input = frame.colorInput(), output = frame.colorOutput();
  const std::string pass = technique + ".composite";
  frame.addPass(pass,
      [&](PassBuilder& b) {
        b.read(input);
        b.read(kArealightResource);
        b.read(res::kPosition);
        b.read(res::kGeometry);
        b.write(output, frameTexture(frame, GL_RGBA16F));
        HdrClampCounters::declareUse(frame, b);
      },
      [input, output, pass](PassContext& ctx) {
        std::vector<std::string> defines;
        if (ctx.common.hdrClamp.counting()) defines.push_back("HDR_CLAMP_COUNT");
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "arealight/composite.frag"}, defines, pass});
        ctx.beginFullscreen(pass, {output});
        p.use();
        ctx.texture(input).bind(0);
        ctx.texture(kArealightResource).bind(1);
        ctx.texture(res::kPosition).bind(2);
        ctx.texture(res::kGeometry).bind(3);
        p.set("uColor", 0)
            .set("uArealight", 1)
            .set("uPosition", 2)
            .set("uGeometry", 3)
            .set("uCameraPosition", ctx.view.cameraPosition)
            .set("uInvViewProj", ctx.view.invViewProj)
            .set("uViewportSize", glm::vec2(ctx.view.width, ctx.view.height));
        ctx.common.bindLights(p);
        ctx.common.hdrClamp.bind(p, pass);
        ctx.common.drawFullscreen();
      });
}

} // namespace rtlab
