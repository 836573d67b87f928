// The rtlab commands (docs/contract.md "Commands"). Each returns the process exit code or throws Error.
#pragma once

namespace rtlab {

int runList(int argc, char** argv);
int runRender(int argc, char** argv);
int runView(int argc, char** argv);
int runShowcase(int argc, char** argv);
int runReference(int argc, char** argv);
int runCompare(int argc, char** argv);
int runSweep(int argc, char** argv);
int runExercise(int argc, char** argv);

} // namespace rtlab
