#include "frame/registry.h"

#include "frame/aovs.h"
#include "frame/stages.h"
#include "util/error.h"
#include "util/suggest.h"

#include <algorithm>

namespace rtlab {

void TechniqueRegistry::add(TechniqueEntry entry) {
  const auto& info = entry.info;
  // Ids are CLI tokens (-t a,b) and key prefixes: lower-case [a-z0-9_], and none of the words or
  // prefixes the frame owns ("none" deactivates all; stage ids, tonemap, camera, light<N> are keys).
  const bool wellFormed = !info.id.empty() && std::all_of(info.id.begin(), info.id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
  if (!wellFormed) throw Error(ExitCode::Internal, "technique id '" + info.id + "' must be non-empty [a-z0-9_]");
  const bool lightPrefix = info.id.rfind("light", 0) == 0 && info.id.size() > 5 &&
                           std::all_of(info.id.begin() + 5, info.id.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (info.id == "none" || info.id == "tonemap" || info.id == "camera" || findStage(info.id) || lightPrefix)
    throw Error(ExitCode::Internal, "technique id '" + info.id + "' is reserved");
  if (find(info.id)) throw Error(ExitCode::Internal, "technique '" + info.id + "' registered twice");
  if (!findStage(info.stage))
    throw Error(ExitCode::Internal, "technique '" + info.id + "' names unknown stage '" + info.stage + "'");
  for (const auto& p : info.params)
    if (p.key.rfind(info.id + ".", 0) != 0)
      throw Error(ExitCode::Internal, "technique '" + info.id + "' declares key '" + p.key + "' outside its prefix");
  // A debug view is named `<id>.<view>`, or exactly `<id>` when it is the technique's own output
  // (the AOV `bloom` of the technique bloom); never like a built-in AOV.
  for (const auto& v : info.debugViews) {
    if (v.name != info.id && v.name.rfind(info.id + ".", 0) != 0)
      throw Error(ExitCode::Internal, "technique '" + info.id + "' declares debug view '" + v.name + "' outside its prefix");
    if (isBuiltinAov(v.name))
      throw Error(ExitCode::Internal, "technique '" + info.id + "' declares debug view '" + v.name + "', a built-in AOV");
  }
  m_entries.push_back(std::move(entry));
}

const TechniqueEntry* TechniqueRegistry::find(const std::string& id) const {
  for (const auto& e : m_entries)
    if (e.info.id == id) return &e;
  return nullptr;
}

const TechniqueEntry& TechniqueRegistry::get(const std::string& id) const {
  if (const auto* e = find(id)) return *e;
  std::string known;
  std::vector<std::string> ids;
  for (const auto& e : m_entries) {
    known += e.info.id + ", ";
    ids.push_back(e.info.id);
  }
  ids.push_back("none");
  usageError("unknown technique '" + id + "'" + didYouMean(id, ids) + " (known: " + known + "none)");
}

} // namespace rtlab
