#include "util/atomic_file.h"

#include "util/error.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>

namespace rtlab {
namespace {

// Fixed-size table so the SIGINT handler can walk it without allocating.
constexpr int kMaxTemporaries = 64;
constexpr int kMaxPath = 4096;
// A slot is claimed (Free -> Filling) before its path is copied and published (-> Ready) after,
// so two threads never write the same slot and the handler never reads a half-written path.
enum SlotState : int { kSlotFree = 0, kSlotFilling = 1, kSlotReady = 2 };
struct TempSlot {
  std::atomic<int> state{kSlotFree};
  char path[kMaxPath];
};
std::array<TempSlot, kMaxTemporaries> g_slots;

int claimSlot(const std::string& path) {
  if (path.size() + 1 > kMaxPath) return -1;
  for (int i = 0; i < kMaxTemporaries; ++i) {
    int expected = kSlotFree;
    if (!g_slots[i].state.compare_exchange_strong(expected, kSlotFilling)) continue;
    std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
    g_slots[i].state.store(kSlotReady);
    return i;
  }
  return -1;
}

void releaseSlot(int slot) {
  if (slot >= 0) g_slots[slot].state.store(kSlotFree);
}

std::string temporaryName(const std::string& path) {
  static std::atomic<int> counter{0};
  std::ostringstream os;
  // Keep the extension last so libraries that dispatch on it still see it.
  auto slash = path.find_last_of('/');
  auto dot = path.find_last_of('.');
  std::string ext = (dot != std::string::npos && (slash == std::string::npos || dot > slash)) ? path.substr(dot) : "";
  std::string stem = path.substr(0, path.size() - ext.size());
  os << stem << ".tmp-" << ::getpid() << "-" << counter++ << ext;
  return os.str();
}

} // namespace

void writeFileAtomically(const std::string& path, const std::function<bool(const std::string&)>& write) {
  const std::string tmp = temporaryName(path);
  const int slot = claimSlot(tmp);
  bool ok = false;
  std::string reason;
  try {
    ok = write(tmp);
    if (!ok) reason = std::strerror(errno ? errno : EIO);
  } catch (const Error&) {
    std::remove(tmp.c_str());
    releaseSlot(slot);
    throw;
  } catch (const std::exception& e) {
    reason = e.what();
  } catch (...) {
    reason = "unknown error";
  }
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) {
    ok = false;
    reason = std::strerror(errno);
  }
  if (!ok) {
    std::remove(tmp.c_str());
    releaseSlot(slot);
    outputError("cannot write '" + path + "': " + reason);
  }
  releaseSlot(slot);
}

void writeTextAtomically(const std::string& path, const std::string& contents) {
  writeFileAtomically(path, [&](const std::string& tmp) {
    errno = 0;
    std::ofstream out(tmp, std::ios::binary);
    if (!out) return false;
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.close();
    return static_cast<bool>(out);
  });
}

void removeTemporaries() {
  for (auto& slot : g_slots)
    if (slot.state.load() == kSlotReady) ::unlink(slot.path);
}

std::string readFileOrThrow(const std::string& path, const char* what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) inputError(std::string("cannot read ") + what + " '" + path + "': " + std::strerror(errno));
  std::ostringstream os;
  os << in.rdbuf();
  if (in.bad()) inputError(std::string("cannot read ") + what + " '" + path + "'");
  return os.str();
}

} // namespace rtlab

#include <filesystem>

namespace rtlab {
void checkOutputPath(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) outputError("empty output path");
  std::error_code ec;
  if (fs::is_directory(path, ec)) outputError("cannot write '" + path + "': it is a directory");
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir, ec)) outputError("cannot write '" + path + "': directory '" + dir.string() + "' does not exist");
  if (::access(dir.c_str(), W_OK) != 0) outputError("cannot write '" + path + "': directory '" + dir.string() + "' is not writable");
}
} // namespace rtlab
