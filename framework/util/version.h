// Version and git commit, generated at configure time (cmake/version.cmake).
#pragma once

namespace rtlab {
const char* versionString();
const char* gitCommit();
} // namespace rtlab
