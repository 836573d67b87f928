// The shared headless context (render_fixture.h) and the GL debug helpers: version and profile,
// renderer info, the per-frame GL error counter, and backend name parsing.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "gl/debug.h"
#include "gl_error_check.h"
#include "platform/context.h"
#include "render_fixture.h"
#include "util/error.h"
#include "util/log.h"

namespace rtlab {
namespace {

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

TEST(Context, ReportsGl45Core) {
  testContext().makeCurrent();
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45) << "GL " << major << "." << minor;
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT) << "profile mask " << profile;
  EXPECT_EQ(drainGlErrors(), 0);
}

TEST(Context, ReportsRendererAndBackend) {
  const Context& context = testContext();
  EXPECT_FALSE(context.info().renderer.empty());
  EXPECT_FALSE(context.info().version.empty());
  EXPECT_FALSE(context.info().glsl.empty());
  const std::string name = context.backendName();
  EXPECT_TRUE(name == "egl-surfaceless" || name == "egl-device" || name == "osmesa") << name;
  EXPECT_FALSE(context.isWindow());
}

TEST(Context, BackendIsTheOneAskedForAndEglUnderCi) {
  // RTLAB_TEST_BACKEND names the backend the whole binary runs on (render_main.cpp); unset, the auto
  // choice tries EGL first and falls back to OSMesa. Under CI that fallback would run every render
  // test on OSMesa instead of EGL with nothing failing: there it fails (docs/testing.md, "Skip
  // conditions").
  const std::string name = testContext().backendName();
  const bool egl = name.rfind("egl-", 0) == 0;
  const char* asked = std::getenv("RTLAB_TEST_BACKEND");
  const char* ci = std::getenv("CI");
  if (asked && std::string(asked) == "osmesa") EXPECT_EQ(name, "osmesa");
  else if (asked && std::string(asked) == "egl") EXPECT_TRUE(egl) << name;
  else if (ci && *ci) EXPECT_TRUE(egl) << "CI is set and the auto backend fell back to " << name;
  else if (!egl) std::printf("note: EGL is unavailable; the render tests run on %s\n", name.c_str());
}

TEST(Context, SoftwareFlagMatchesRenderer) {
  const GlInfo& info = testContext().info();
  const std::string renderer = lowercase(info.renderer);
  const bool mesaSoftware = renderer.find("llvmpipe") != std::string::npos ||
                            renderer.find("softpipe") != std::string::npos ||
                            renderer.find("swrast") != std::string::npos;
  EXPECT_EQ(info.software, mesaSoftware) << info.renderer;
}

TEST(Context, DrainGlErrorsCountsADeliberateErrorOnce) {
  testContext().makeCurrent();
  drainGlErrors(); // whatever an earlier test left
  ExpectGlErrors expected(1); // declared: not a failure of this test (docs/testing.md "GL errors")
  glEnable(0xFFFF);           // GL_INVALID_ENUM
  const int first = drainGlErrors();
  const int second = drainGlErrors();
  EXPECT_GE(first, 1);
  EXPECT_EQ(second, 0);
}

TEST(Context, ObjectLabelsRoundTrip) {
  testContext().makeCurrent();
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  setObjectLabel(GL_BUFFER, buffer, "test buffer");
  char label[64] = {};
  GLsizei length = 0;
  glGetObjectLabel(GL_BUFFER, buffer, sizeof label, &length, label);
  glDeleteBuffers(1, &buffer);
  EXPECT_EQ(std::string(label, static_cast<size_t>(length)), "test buffer");
  EXPECT_EQ(drainGlErrors(), 0);
}

TEST(Context, ParseBackend) {
  EXPECT_EQ(parseBackend("auto"), Backend::Auto);
  EXPECT_EQ(parseBackend("egl"), Backend::Egl);
  EXPECT_EQ(parseBackend("osmesa"), Backend::OsMesa);
  try {
    parseBackend("vulkan");
    FAIL() << "parseBackend accepted 'vulkan'";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Usage);
    EXPECT_NE(std::string(e.what()).find("vulkan"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace rtlab
