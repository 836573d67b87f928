// Exercise regions in shipped shader sources (docs/exercises.md "Regions"): the part of a file a
// student writes, marked with line comments, with its task text and a stub that compiles and gives
// a neutral value. The shipped file stays the solution; the student's copy replaces the solution
// lines of the chosen regions by their stubs.
#pragma once
#include <set>
#include <string>
#include <vector>

namespace rtlab {

struct ExerciseRegion {
  std::string name;
  int beginLine = 0;                  // 1-based line of "// exercise(NAME): begin"
  int endLine = 0;                    // 1-based line of "// exercise: end"
  std::vector<std::string> task;      // the task text, one entry per "// task:" line
  std::vector<std::string> solution;  // the solution lines, as shipped
  std::vector<std::string> stub;      // the stub's code lines, uncommented
};

// Every region of a file's text, in order. A malformed marker is Error(Input)
// "FILE:LINE: ..." (`file` names the text in messages). A student's copy has no stub sections:
// parse it with `studentCopy` true (the lines between the task and the end are its code).
std::vector<ExerciseRegion> parseExerciseRegions(const std::string& text, const std::string& file,
                                                 bool studentCopy = false);

// The student's copy of `text`: regions named in `chosen` keep their begin, task and end lines, and
// get kStubNotice and their stub code (neutral values) in place of the solution; the other
// regions lose their marker, task and stub lines and keep the solution. Lines outside regions are
// unchanged.
std::string studentCopy(const std::string& text, const std::string& file, const std::set<std::string>& chosen);

// The comment inserted above each stub in a student's copy.
extern const char* const kStubNotice;

} // namespace rtlab
