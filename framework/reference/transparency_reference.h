// The transparency stage's reference (docs/contract.md "Transparency"): the exact Over of every
// captured transparent fragment (shading/fragment_capture.h), sorted per pixel by depth and
// composited back to front onto the opaque colour, in double precision on the CPU. It shares no
// code with the `abuffer` technique but the layer shading of the capture.
#pragma once
#include "image/image.h"
#include "shading/fragment_capture.h"

#include <atomic>

namespace rtlab {

class ReferenceRegistry;

// R = a1 C1 + (1 - a1)(a2 C2 + (1 - a2)(... C_opaque)), fragment 1 the nearest. Fragments of equal
// depth are ordered by their radiance and alpha (an arbitrary but deterministic order: the
// definition leaves coplanar layers' order open). The mask: the opaque colour's, or 1 where a
// fragment is. Checks `cancel` between rows (then Error(Interrupted)). Error(Internal) for a
// fragment outside the image or an opaque colour of another size.
Image compositeOver(const CapturedFragments& captured, const Image& opaque, const std::atomic<bool>* cancel = nullptr);

// `rtlab reference --aov transparency`.
void registerTransparencyReference(ReferenceRegistry& registry);

} // namespace rtlab
