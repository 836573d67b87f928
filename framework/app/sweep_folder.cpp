#include "app/sweep_folder.h"

#include "util/error.h"

#include <algorithm>
#include <filesystem>
#include <vector>

namespace fs = std::filesystem;

namespace rtlab {
namespace {

const char* const kFiles[] = {"sweep.json", "jobs.txt", "results.csv", "report.html"};
const char* const kFolders[] = {"points", "reference", "logs"};

bool isTemporaryOf(const std::string& name, const std::string& file) {
  const auto dot = file.rfind('.');
  const std::string stem = file.substr(0, dot), ext = file.substr(dot);
  const std::string prefix = stem + ".tmp-";
  return name.size() > prefix.size() + ext.size() && name.compare(0, prefix.size(), prefix) == 0 &&
         name.compare(name.size() - ext.size(), ext.size(), ext) == 0;
}

} // namespace

bool isSweepEntry(const std::string& name) {
  for (const char* f : kFiles)
    if (name == f || isTemporaryOf(name, f)) return true;
  return std::any_of(std::begin(kFolders), std::end(kFolders), [&](const char* d) { return name == d; });
}

void prepareSweepFolder(const std::string& dir, bool force) {
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) return; // created by the caller
  if (!fs::is_directory(status)) outputError("sweep folder '" + dir + "' exists and is not a directory");
  std::vector<std::string> own, foreign;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    (isSweepEntry(it->path().filename().string()) ? own : foreign).push_back(it->path().filename().string());
  if (ec) outputError("cannot read sweep folder '" + dir + "': " + ec.message());
  std::sort(foreign.begin(), foreign.end());
  if (!foreign.empty())
    outputError("sweep folder '" + dir + "' is not empty and holds more than a sweep ('" + foreign.front() + "'" +
                (foreign.size() > 1 ? " and " + std::to_string(foreign.size() - 1) + " more" : std::string()) +
                "); give a new or empty folder (--force replaces only a folder that holds nothing but a sweep)");
  if (own.empty()) return;
  if (!force)
    outputError("sweep folder '" + dir + "' already holds a sweep; give another folder, or --force to replace it");
  for (const auto& name : own) {
    fs::remove_all(fs::path(dir) / name, ec); // never follows a symbolic link
    if (ec) outputError("cannot replace the sweep in '" + dir + "': removing '" + name + "': " + ec.message());
  }
}

} // namespace rtlab
