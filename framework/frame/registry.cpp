#include "frame/registry.h"

#include "frame/stages.h"
#include "util/error.h"

namespace rtlab {

void TechniqueRegistry::add(TechniqueEntry entry) {
  const auto& info = entry.info;
  if (find(info.id)) throw Error(ExitCode::Internal, "technique '" + info.id + "' registered twice");
  if (!findStage(info.stage))
    throw Error(ExitCode::Internal, "technique '" + info.id + "' names unknown stage '" + info.stage + "'");
  for (const auto& p : info.params)
    if (p.key.rfind(info.id + ".", 0) != 0)
      throw Error(ExitCode::Internal, "technique '" + info.id + "' declares key '" + p.key + "' outside its prefix");
  for (const auto& v : info.debugViews)
    if (v.name.rfind(info.id + ".", 0) != 0)
      throw Error(ExitCode::Internal, "technique '" + info.id + "' declares debug view '" + v.name + "' outside its prefix");
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
  for (const auto& e : m_entries) known += (known.empty() ? "" : ", ") + e.info.id;
  usageError("unknown technique '" + id + "' (known: " + known + ", none)");
}

} // namespace rtlab
