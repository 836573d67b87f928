// The transparency techniques' debug view of their error: per pixel, the largest absolute
// difference over R, G and B between the technique's composite and the exact A-buffer of the same
// frame (techniques/common/transparency/abuffer_passes.h, max_fragments 128, run under the technique's own
// prefix). Its passes run only when the view is requested (the graph culls them otherwise), so a
// technique pays for it only then; the A-buffer's node pool is allocated when it first runs and kept
// until the scene's geometry changes or the technique is turned off. wboit and depth_peeling use it (their READMEs).
#pragma once
#include "techniques/common/transparency/abuffer_passes.h"

#include <string>

namespace rtlab {

class FrameGraph;

class AbufferError {
public:
  // Adds "<technique>.exact.*" (the A-buffer over frame.colorInput()) and the pass writing the
  // debug view "<technique>.error" from `composite` (the technique's output colour).
  void add(FrameGraph& frame, const std::string& technique, const std::string& composite);
  std::size_t ownedBytes() const { return m_exact.ownedBytes(); }
  void release() { m_exact.release(); }

  // The view's entry for TechniqueInfo::debugViews.
  static std::string viewName(const std::string& technique) { return technique + ".error"; }
  static const char* viewHelp();

private:
  AbufferPasses m_exact;
};

} // namespace rtlab
