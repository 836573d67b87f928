#include "techniques/common/transparency/abuffer_error.h"

#include "frame/frame_graph.h"
#include "gl/program_cache.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"

namespace rtlab {

const char* AbufferError::viewHelp() {
  return "per pixel, max over RGB of |this composite - the exact A-buffer's| (an A-buffer of 128 fragments "
         "per pixel runs for this view only)";
}

void AbufferError::add(FrameGraph& frame, const std::string& technique, const std::string& composite) {
  const std::string exact = technique + ".exact.color";
  AbufferSetup s;
  s.prefix = technique + ".exact";
  s.maxFragments = 128;
  s.colorIn = frame.colorInput();
  s.colorOut = exact;
  s.deferPool = true; // no pool unless the view is shown
  m_exact.add(frame, s);
  const std::string view = aovResource(viewName(technique)), label = technique + ".error";
  frame.addPass(label,
      [&](PassBuilder& b) {
        b.read(composite);
        b.read(exact);
        b.write(view, frameTexture(frame, GL_RGBA32F));
      },
      [=](PassContext& ctx) {
        gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "transparency/error.frag"}, {}, "transparency.error"});
        ctx.beginFullscreen(label, {view});
        p.use();
        ctx.texture(composite).bind(0);
        ctx.texture(exact).bind(1);
        p.set("uComposite", 0).set("uExact", 1);
        ctx.common.drawFullscreen();
      });
}

} // namespace rtlab
