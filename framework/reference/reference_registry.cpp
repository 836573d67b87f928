#include "reference/reference_registry.h"

#include "frame/registry.h"
#include "frame/stages.h"
#include "params/sweep_spec.h"
#include "scene/scene_params.h"
#include "util/error.h"
#include "util/hash.h"
#include "util/suggest.h"

#include <algorithm>

namespace rtlab {
namespace {

constexpr const char* kLightPattern = "light<N>.";

bool wellFormedPattern(const std::string& p) {
  if (p == kLightPattern) return true;
  if (p.empty() || p.front() == '.') return false;
  return std::all_of(p.begin(), p.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
  });
}

bool matches(const std::string& pattern, const std::string& key) {
  if (pattern == kLightPattern) return isLightKey(key);
  if (pattern.back() == '.') return key.rfind(pattern, 0) == 0;
  return key == pattern;
}

} // namespace

ReferenceFrame::ReferenceFrame(const ReferenceEntry& entry, const Scene& scene, const ParamSet& params, int spp,
                               unsigned seed, bool progress)
    : m_entry(entry), m_scene(scene), m_params(params), m_spp(spp), m_seed(seed), m_progress(progress) {}

const SurfaceData& ReferenceFrame::surfaces() const {
  if (!m_entry.inputs.has(FrameInput::SurfacePoints) || !m_surfaces)
    throw Error(ExitCode::Internal, "reference '" + m_entry.aov + "' reads surface points it did not declare");
  return *m_surfaces;
}

const Image& ReferenceFrame::prePostColor() const {
  if (!m_entry.inputs.has(FrameInput::PrePostColor) || !m_prePostColor)
    throw Error(ExitCode::Internal, "reference '" + m_entry.aov + "' reads the colour before post it did not declare");
  return *m_prePostColor;
}

const CapturedFragments& ReferenceFrame::transparentFragments() const {
  if (!m_entry.inputs.has(FrameInput::TransparentFragments) || !m_fragments)
    throw Error(ExitCode::Internal, "reference '" + m_entry.aov + "' reads transparent fragments it did not declare");
  return *m_fragments;
}

const Image& ReferenceFrame::opaqueColor() const {
  if (!m_entry.inputs.has(FrameInput::TransparentFragments) || !m_opaqueColor)
    throw Error(ExitCode::Internal, "reference '" + m_entry.aov + "' reads the opaque colour it did not declare");
  return *m_opaqueColor;
}

float ReferenceFrame::getFloat(const std::string& key) const {
  if (!m_entry.definesKey(key))
    throw Error(ExitCode::Internal, "reference '" + m_entry.aov + "' reads key '" + key + "' it does not declare");
  return m_params.getFloat(key);
}

bool ReferenceEntry::definesKey(const std::string& key) const {
  return std::any_of(keys.begin(), keys.end(), [&](const std::string& p) { return matches(p, key); });
}

void ReferenceRegistry::add(ReferenceEntry entry) {
  const std::string what = "reference '" + entry.aov + "'";
  const bool wellFormed = !entry.aov.empty() && std::all_of(entry.aov.begin(), entry.aov.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
  });
  if (!wellFormed) throw Error(ExitCode::Internal, what + ": the AOV must be non-empty [a-z0-9_.]");
  if (findAov(entry.aov)) throw Error(ExitCode::Internal, what + " registered twice");
  if (!rtlab::findStage(entry.stage)) throw Error(ExitCode::Internal, what + " names unknown stage '" + entry.stage + "'");
  if (const ReferenceEntry* other = findStage(entry.stage))
    throw Error(ExitCode::Internal, what + ": stage '" + entry.stage + "' already has reference '" + other->aov + "'");
  if (entry.channels != 1 && entry.channels != 3) throw Error(ExitCode::Internal, what + " must have 1 or 3 channels");
  for (const auto& k : entry.keys)
    if (!wellFormedPattern(k)) throw Error(ExitCode::Internal, what + " declares malformed key '" + k + "'");
  if (entry.minSpp < 1 || entry.minSpp > entry.defaultSpp || entry.defaultSpp > entry.maxSpp)
    throw Error(ExitCode::Internal, what + " needs 1 <= minSpp <= defaultSpp <= maxSpp");
  if (!entry.compute) throw Error(ExitCode::Internal, what + " has no compute function");
  m_entries.push_back(std::move(entry));
}

const ReferenceEntry* ReferenceRegistry::findAov(const std::string& aov) const {
  for (const auto& e : m_entries)
    if (e.aov == aov) return &e;
  return nullptr;
}

const ReferenceEntry* ReferenceRegistry::findStage(const std::string& stage) const {
  for (const auto& e : m_entries)
    if (e.stage == stage) return &e;
  return nullptr;
}

std::string ReferenceRegistry::choices(const std::string& separator) const {
  std::string s;
  for (const auto& e : m_entries) s += (s.empty() ? "" : separator) + e.aov;
  return s;
}

const ReferenceEntry& ReferenceRegistry::get(const std::string& aov) const {
  if (const ReferenceEntry* e = findAov(aov)) return *e;
  std::vector<std::string> aovs;
  for (const auto& e : m_entries) aovs.push_back(e.aov);
  usageError("unknown reference AOV '" + aov + "'" + didYouMean(aov, aovs) + " (choices: " + choices() + ")");
}

Scene sceneForReference(const Scene& scene, const ParamSet& params, const ReferenceEntry& entry) {
  Scene out = scene;
  applySceneParams(params, out);
  if (!entry.inputs.has(FrameInput::Materials)) {
    for (auto& m : out.materials) m = Material{};
    out.textures.clear();
  }
  return out;
}

bool referenceDependsOnKey(const ReferenceEntry& entry, const std::string& key, const TechniqueRegistry& techniques) {
  if (entry.definesKey(key)) return true;
  if (!entry.inputs.has(FrameInput::PrePostColor) && !entry.inputs.has(FrameInput::TransparentFragments)) return false;
  const std::string prefix = key.substr(0, key.find('.'));
  if (prefix == "tonemap") return false; // after post
  std::string stage = rtlab::findStage(prefix) ? prefix : "";
  if (const TechniqueEntry* t = techniques.find(prefix)) stage = t->info.stage;
  return stage != entry.stage && stage != "post";
}

void hashReferenceKeys(const ReferenceEntry& entry, const ParamSet& params, const TechniqueRegistry& techniques,
                       Fnv1a64& h) {
  for (const auto& spec : params.specs()) {
    if (!referenceDependsOnKey(entry, spec.key, techniques)) continue;
    const ParamValue& v = params.value(spec.key);
    h.text(spec.key).f64(v.v[0]).f64(v.v[1]).f64(v.v[2]);
  }
}

} // namespace rtlab
