// The GL error total of a test binary (docs/testing.md "GL errors"): errors a test made on purpose
// and checked, errors that rtlab child processes reported, and the report each binary writes at
// its end for scripts/gl_error_total.sh.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace rtlab::test {

// Errors that a test declared and checked (ExpectGlErrors, runProcess's expectedGlErrors): they
// are not failures and are left out of the binary's total.
void addDeliberateGlErrors(std::int64_t count);
std::int64_t deliberateGlErrors();

// Errors that child processes reported beyond what their test expected (each one already failed
// its test).
void addChildGlErrors(std::int64_t count);
std::int64_t childGlErrors();

// Sum of the "gl_errors: N ..." lines of a report (the format of docs/contract.md "GL error
// report"); -1 when `text` has none.
std::int64_t parseGlErrorReport(const std::string& text);

// Prints "GL errors in <binary>: N (M made on purpose and checked)" and writes the report
// "gl_errors: N <binary> (pid P)" and `messages`, one per line after two spaces: appended to
// RTLAB_GL_ERRORS_FILE when set (the binary runs under another test's runProcess), else to
// RTLAB_TEST_GL_ERRORS_DIR/<binary>-<pid>.txt when set (tests/CMakeLists.txt sets it for ctest). N counts `ownErrors` (this process's unexpected errors) and childGlErrors(). Returns false
// when the file could not be written.
bool writeTestBinaryGlErrorReport(const std::string& binary, std::int64_t ownErrors,
                                  const std::vector<std::string>& messages);

} // namespace rtlab::test
