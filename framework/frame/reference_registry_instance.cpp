// The process-wide reference registry, filled by the generated registerAllReferences() (GL side,
// like the technique registry, so the registry class stays unit-testable without techniques).
#include "reference/reference_registry.h"

namespace rtlab {

const ReferenceRegistry& ReferenceRegistry::instance() {
  static const ReferenceRegistry registry = [] {
    ReferenceRegistry r;
    registerAllReferences(r);
    return r;
  }();
  return registry;
}

} // namespace rtlab
