// util/atomic_file: outputs appear complete or not at all, and failures leave no temporaries.
#include "util/atomic_file.h"
#include "util/error.h"

#include <gtest/gtest.h>

#include "test_util.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rtlab;

namespace {

fs::path freshDir() { return rtlab::test::freshTestDir("atomic_file"); }
using rtlab::test::slurp;
std::set<std::string> entries(const fs::path& dir) { return rtlab::test::dirEntries(dir); }




bool touch(const std::string& path, const std::string& text = "partial") {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return bool(out);
}

ExitCode codeOf(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const Error& e) {
    return e.code();
  }
  return ExitCode::Ok;
}

} // namespace

TEST(AtomicFile, WritesExactContent) {
  const fs::path dir = freshDir();
  const std::string target = (dir / "out.bin").string();
  const std::string content("line 1\nline 2\r\n\0\xff binary", 23);
  writeTextAtomically(target, content);
  EXPECT_EQ(slurp(target), content);
  EXPECT_EQ(entries(dir), std::set<std::string>{"out.bin"});
}

TEST(AtomicFile, TemporaryIsBesideTargetAndKeepsExtension) {
  const fs::path dir = freshDir();
  const fs::path target = dir / "image.exr";
  std::string seen;
  writeFileAtomically(target.string(), [&](const std::string& tmp) {
    seen = tmp;
    return touch(tmp, "x");
  });
  EXPECT_EQ(fs::path(seen).parent_path(), dir);
  EXPECT_EQ(fs::path(seen).extension(), ".exr");
  EXPECT_NE(fs::path(seen).filename(), target.filename());
  EXPECT_EQ(entries(dir), std::set<std::string>{"image.exr"});
}

TEST(AtomicFile, WriterReturningFalseLeavesNothing) {
  const fs::path dir = freshDir();
  const std::string target = (dir / "out.txt").string();
  try {
    writeFileAtomically(target, [](const std::string& tmp) { return !touch(tmp); });
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Output);
    EXPECT_NE(std::string(e.what()).find(target), std::string::npos) << e.what();
  }
  EXPECT_TRUE(entries(dir).empty());
}

TEST(AtomicFile, WriterThrowingLeavesNothing) {
  const fs::path dir = freshDir();
  const std::string target = (dir / "out.txt").string();
  const ExitCode code = codeOf([&] {
    writeFileAtomically(target, [](const std::string& tmp) -> bool {
      touch(tmp);
      throw std::runtime_error("encoder exploded");
    });
  });
  EXPECT_EQ(code, ExitCode::Output);
  EXPECT_TRUE(entries(dir).empty());
}

TEST(AtomicFile, WriterThrowingNonStandardLeavesNothing) {
  const fs::path dir = freshDir();
  const std::string target = (dir / "out.txt").string();
  const ExitCode code = codeOf([&] {
    writeFileAtomically(target, [](const std::string& tmp) -> bool {
      touch(tmp);
      throw 42;
    });
  });
  EXPECT_EQ(code, ExitCode::Output);
  EXPECT_TRUE(entries(dir).empty());
}

TEST(AtomicFile, WriterThrowingErrorLeavesNothing) {
  const fs::path dir = freshDir();
  const std::string target = (dir / "out.txt").string();
  const ExitCode code = codeOf([&] {
    writeFileAtomically(target, [](const std::string& tmp) -> bool {
      touch(tmp);
      outputError("cannot encode");
    });
  });
  EXPECT_EQ(code, ExitCode::Output);
  EXPECT_TRUE(entries(dir).empty());
}

TEST(AtomicFile, FailureKeepsExistingTarget) {
  const fs::path dir = freshDir();
  const std::string target = (dir / "keep.txt").string();
  writeTextAtomically(target, "old content");
  EXPECT_EQ(codeOf([&] { writeFileAtomically(target, [](const std::string& tmp) { return !touch(tmp, "new"); }); }),
            ExitCode::Output);
  EXPECT_EQ(slurp(target), "old content");
  EXPECT_EQ(codeOf([&] {
              writeFileAtomically(target, [](const std::string& tmp) -> bool {
                touch(tmp, "new");
                throw std::runtime_error("late failure");
              });
            }),
            ExitCode::Output);
  EXPECT_EQ(slurp(target), "old content");
  EXPECT_EQ(entries(dir), std::set<std::string>{"keep.txt"});
}

TEST(AtomicFile, SuccessReplacesExistingTarget) {
  const fs::path dir = freshDir();
  const std::string target = (dir / "replace.txt").string();
  writeTextAtomically(target, "a much longer old content");
  writeTextAtomically(target, "new");
  EXPECT_EQ(slurp(target), "new");
  EXPECT_EQ(entries(dir), std::set<std::string>{"replace.txt"});
}

TEST(AtomicFile, MissingDirectoryIsOutputError) {
  const fs::path dir = freshDir();
  const std::string target = (dir / "missing" / "out.txt").string();
  try {
    writeTextAtomically(target, "x");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Output);
    EXPECT_NE(std::string(e.what()).find(target), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  EXPECT_TRUE(entries(dir).empty());
}

TEST(AtomicFile, TargetThatIsADirectoryLeavesNoTemporary) {
  const fs::path dir = freshDir();
  fs::create_directories(dir / "taken.txt");
  fs::create_directories(dir / "taken.txt" / "child"); // rename onto a non-empty directory fails
  EXPECT_EQ(codeOf([&] { writeTextAtomically((dir / "taken.txt").string(), "x"); }), ExitCode::Output);
  EXPECT_EQ(entries(dir), std::set<std::string>{"taken.txt"});
}

TEST(AtomicFile, RemoveTemporariesDeletesFilesInFlight) {
  const fs::path dir = freshDir();
  const std::string target = (dir / "out.txt").string();
  bool existedBefore = false, existedAfter = true;
  const ExitCode code = codeOf([&] {
    writeFileAtomically(target, [&](const std::string& tmp) {
      touch(tmp);
      existedBefore = fs::exists(tmp);
      removeTemporaries(); // what the SIGINT handler does
      existedAfter = fs::exists(tmp);
      return true;
    });
  });
  EXPECT_TRUE(existedBefore);
  EXPECT_FALSE(existedAfter);
  EXPECT_EQ(code, ExitCode::Output); // nothing left to rename
  EXPECT_TRUE(entries(dir).empty());
}

TEST(AtomicFile, ReadFileOrThrowReportsMissingFileAsInput) {
  const fs::path dir = freshDir();
  const std::string path = (dir / "nope.json").string();
  try {
    readFileOrThrow(path, "preset");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::Input);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  writeTextAtomically(path, "{}");
  EXPECT_EQ(readFileOrThrow(path), "{}");
}
