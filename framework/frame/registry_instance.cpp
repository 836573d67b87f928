// The process-wide registry, filled by the generated registerAllTechniques() (GL side only, so
// the registry class itself stays unit-testable without any technique linked in).
#include "frame/registry.h"

namespace rtlab {

const TechniqueRegistry& TechniqueRegistry::instance() {
  static const TechniqueRegistry registry = [] {
    TechniqueRegistry r;
    registerAllTechniques(r);
    return r;
  }();
  return registry;
}

} // namespace rtlab
