// Helpers shared by the unit tests: expecting an rtlab::Error with its exit code and message
// parts, per-test scratch directories, and small file utilities.
#pragma once
#include "util/error.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <set>
#include <string>

namespace rtlab::test {

struct Caught {
  bool thrown = false;
  ExitCode code = ExitCode::Ok;
  std::string message;
};

template <typename F>
Caught catchError(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return {true, e.code(), e.what()};
  } catch (const std::exception& e) {
    return {true, ExitCode::Ok, std::string("not an rtlab::Error: ") + e.what()};
  }
  return {};
}

inline void checkCaught(const Caught& c, ExitCode code, std::initializer_list<std::string> parts) {
  ASSERT_TRUE(c.thrown) << "expected an rtlab::Error, nothing was thrown";
  EXPECT_EQ(int(c.code), int(code)) << c.message;
  for (const auto& p : parts)
    EXPECT_NE(c.message.find(p), std::string::npos) << "message \"" << c.message << "\" does not contain \"" << p << "\"";
}

// A fresh, empty directory for the running test: RTLAB_TEST_TMP/<area>/<suite>.<test>-<pid>.
inline std::filesystem::path freshTestDir(const std::string& area) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(RTLAB_TEST_TMP) / area /
                              (std::string(info->test_suite_name()) + "." + info->name() + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::set<std::string> dirEntries(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// `text` with the first occurrence of `find` replaced (a failed expectation when there is none).
inline std::string replacedOnce(std::string text, const std::string& find, const std::string& replace) {
  const auto at = text.find(find);
  EXPECT_NE(at, std::string::npos) << find;
  if (at == std::string::npos) return text;
  return text.replace(at, find.size(), replace);
}

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

} // namespace rtlab::test

// Expects `stmt` to throw rtlab::Error with `code` and a message containing every given part.
#define EXPECT_RTLAB_ERROR(stmt, code, ...)                                            \
  do {                                                                                 \
    SCOPED_TRACE(#stmt);                                                               \
    ::rtlab::test::checkCaught(::rtlab::test::catchError([&] { stmt; }), code, {__VA_ARGS__}); \
  } while (0)
