// rtlab view: the frame in a window (GLFW). The lecture viewer's panels, toggles and A/B views
// come with their own piece of work; this shows the frame, re-rendered every refresh, and can
// take a screenshot after N frames for scripts and tests.
#include "app/commands.h"
#include "app/frame_options.h"
#include "frame/registry.h"
#include "frame/renderer.h"
#include "gl/debug.h"
#include "shading/base_passes.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/log.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <iostream>

namespace rtlab {

int runView(int argc, char** argv) {
  auto specs = frameOptionSpecs();
  specs.push_back({"--screenshot", "", true, "FILE", "after --frames N frames, save the window's image (PNG) and exit"});
  Args args("view", specs, argc, argv, 2);
  if (args.help()) {
    std::cout << formatHelp("rtlab view [scene and frame options] [--frames N --screenshot FILE]",
                            "Shows the frame in a window (needs a display). Esc or closing the window quits.\n"
                            "--backend applies to headless commands only; a window always uses GLFW.", specs);
    return 0;
  }
  ResolvedFrame frame = resolveFrame(args);
  const std::string screenshot = args.get("--screenshot");
  if (!screenshot.empty()) {
    if (imageFormatFromPath(screenshot) != ImageFormat::Png) usageError("--screenshot must be a .png file");
    checkOutputPath(screenshot);
  }
  saveRequestedPreset(frame);
  auto context = createWindowContext(frame.options.width, frame.options.height, "rtlab — " + frame.scene.name);
  const TechniqueRegistry& registry = TechniqueRegistry::instance();
  Renderer renderer(registry);
  renderer.setScene(frame.scene);
  renderer.setTechniques(frame.techniques);
  PassTimer timer(resolveTiming(frame.options.timing, context->info().software));
  FrameOutputs outputs;
  outputs.displayColor = true;
  gl::Program& present = renderer.programs().get({{"common/fullscreen.vert", "shading/present.frag"}, {}, "present"});
  GpuCommon common;
  int rendered = 0;
  while (!context->shouldClose()) {
    context->pollEvents();
    if (glfwGetKey(context->window(), GLFW_KEY_ESCAPE) == GLFW_PRESS) break;
    int w = 0, h = 0;
    context->framebufferSize(w, h);
    if (w <= 0 || h <= 0) continue; // minimized
    renderer.render(frame.params, w, h, outputs, timer);
    drainGlErrors();
    ++rendered;
    if (!screenshot.empty() && rendered >= frame.options.frames) {
      writeImage(screenshot, renderer.readDisplayColor(), PngEncoding::Srgb);
      break;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, w, h);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    present.use();
    renderer.resource(res::kColorLdr)->bind(0);
    present.set("uImage", 0);
    common.drawFullscreen();
    context->swapBuffers();
  }
  return 0;
}

} // namespace rtlab
