// Output files are written to a temporary name beside the target and renamed into place, so a
// failed or interrupted run leaves no partial file (docs/contract.md).
#pragma once
#include <functional>
#include <string>

namespace rtlab {

// Calls write(tmpPath) and renames tmpPath to path. If write throws or returns false, or the
// rename fails, the temporary is removed and Error(Output) is thrown naming path.
// Temporaries in flight are registered so a SIGINT handler can remove them (removeTemporaries).
void writeFileAtomically(const std::string& path, const std::function<bool(const std::string& tmpPath)>& write);

// Convenience: writes bytes atomically.
void writeTextAtomically(const std::string& path, const std::string& contents);

// Removes every temporary file currently being written. Async-signal-safe (uses unlink only).
void removeTemporaries();

// Reads a whole file; throws Error(Input) naming path if it is missing or unreadable.
std::string readFileOrThrow(const std::string& path, const char* what = "file");

} // namespace rtlab

namespace rtlab {
// Fails early (Error(Output) naming the path) when the file's directory does not exist or is not
// writable, or the path is a directory: checked before long work so nothing is computed in vain.
void checkOutputPath(const std::string& path);
} // namespace rtlab
