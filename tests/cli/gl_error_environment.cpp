// The command-line test binary's GL error report (docs/testing.md "GL errors"): at the end of the
// run, the errors its rtlab child processes reported beyond what their tests expected (runProcess
// fails each such test) go to RTLAB_TEST_GL_ERRORS_DIR for scripts/gl_error_total.sh.
#include <gtest/gtest.h>

#include "gl_error_report.h"

namespace rtlab::test {
namespace {

class CliGlErrorReport : public ::testing::Environment {
public:
  void TearDown() override { writeTestBinaryGlErrorReport("rtlab_cli_tests", 0, {}); }
};

// gtest_main's RUN_ALL_TESTS runs the environments registered before it (static initialisation).
[[maybe_unused]] ::testing::Environment* const g_cliGlErrorReport =
    ::testing::AddGlobalTestEnvironment(new CliGlErrorReport);

} // namespace
} // namespace rtlab::test
