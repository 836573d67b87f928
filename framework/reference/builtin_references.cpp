// The three references of the Embree ray caster (reference/reference.h), registered per stage, and
// the transparency stage's (reference/transparency_reference.h), which belongs to no technique.
// (docs/measuring.md "References per stage"). They share the ray caster, so they live here rather
// than in a technique's folder.
#include "reference/reference_registry.h"
#include "reference/transparency_reference.h"

namespace rtlab {
namespace {

// One reference of the ray caster: the frame's surface points and the scene (with its materials:
// transparent surfaces neither receive nor cast, and indirect bounces off the albedo).
ReferenceEntry embreeReference(const std::string& aov, const std::string& stage, int channels, std::string help,
                               std::vector<std::string> keys) {
  ReferenceEntry e;
  e.aov = aov;
  e.stage = stage;
  e.help = std::move(help);
  e.channels = channels;
  e.inputs = {FrameInput::SurfacePoints, FrameInput::Materials};
  e.keys = std::move(keys);
  e.minSpp = kReferenceMinSpp;
  e.maxSpp = kReferenceMaxSpp;
  e.defaultSpp = 64;
  const bool readsRadius = e.definesKey("ao.radius");
  e.compute = [aov, readsRadius](const ReferenceFrame& frame, ReferenceStats& stats) {
    ReferenceOptions options;
    options.spp = frame.spp();
    options.seed = frame.seed();
    if (readsRadius) options.aoRadius = frame.getFloat("ao.radius");
    options.progress = frame.progress();
    return renderReference(frame.scene(), frame.surfaces(), aov, options, stats);
  };
  return e;
}

} // namespace

void registerBuiltinReferences(ReferenceRegistry& registry) {
  // The lights and the camera define every one of them (where the surface points are, where the
  // light comes from); ao also its radius (docs/contract.md, "ao").
  registry.add(embreeReference("visibility", "shadow", 1, "light 0's visibility from each surface point",
                               {"light<N>.", "camera."}));
  registry.add(embreeReference("ao", "ao", 1, "ambient occlusion within ao.radius", {"light<N>.", "camera.", "ao.radius"}));
  registry.add(embreeReference("indirect", "indirect", 3, "one diffuse bounce of direct light",
                               {"light<N>.", "camera."}));
  registerTransparencyReference(registry);
}

} // namespace rtlab
