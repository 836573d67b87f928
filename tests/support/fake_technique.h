// A registry entry with no GL behind it, for unit tests of registries, scripts, bookmarks and the
// viewer's actions: its create() is never called by those tests.
#pragma once
#include "frame/registry.h"

#include <string>
#include <vector>

namespace rtlab::test {

inline TechniqueEntry fakeTechnique(const std::string& id, const std::string& stage, std::vector<ParamSpec> params = {},
                                    std::vector<DebugView> views = {}) {
  TechniqueEntry e;
  e.info.id = id;
  e.info.stage = stage;
  e.info.title = id;
  e.info.params = std::move(params);
  e.info.debugViews = std::move(views);
  e.create = [] { return std::unique_ptr<Technique>(); };
  return e;
}

} // namespace rtlab::test
