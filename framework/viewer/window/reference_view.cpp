#include "viewer/window/reference_view.h"

#include "frame/aovs.h"
#include "frame/registry.h"
#include "frame/stages.h"
#include "reference/live_metrics.h"
#include "reference/reference.h"
#include "reference/reference_registry.h"
#include "scene/scene_params.h"
#include "util/error.h"
#include "util/hash.h"
#include "viewer/window/frame_display.h"

#include <algorithm>

namespace rtlab {
namespace {

// Whether the frame can output `aov` with these techniques: a built-in AOV, or a debug view of an
// active technique of `stage`.
bool producedIn(const std::string& aov, const std::string& stage, const std::vector<std::string>& active) {
  if (isBuiltinAov(aov)) return true;
  const TechniqueRegistry& techniques = TechniqueRegistry::instance();
  return std::any_of(active.begin(), active.end(), [&](const std::string& id) {
    const TechniqueInfo& info = techniques.get(id).info;
    return info.stage == stage && std::any_of(info.debugViews.begin(), info.debugViews.end(),
                                              [&](const DebugView& v) { return v.name == aov; });
  });
}

// The frame's techniques outside `stage`: what the colour before post depends on besides the keys.
std::vector<std::string> techniquesOutside(const std::vector<std::string>& active, const std::string& stage) {
  std::vector<std::string> ids;
  for (const auto& id : active)
    if (TechniqueRegistry::instance().get(id).info.stage != stage) ids.push_back(id);
  return ids;
}

} // namespace

std::string referenceAovFor(const ViewerState& state) {
  const ReferenceRegistry& references = ReferenceRegistry::instance();
  if (state.view.mode != DebugMode::Off && references.findAov(state.view.aov)) return state.view.aov;
  const std::vector<std::string> active = state.selection.ordered();
  for (const StageInfo& stage : stages()) { // in frame order: shadow, ao, indirect, ..., post
    const ReferenceEntry* entry = references.findStage(stage.id);
    if (entry && !state.selection.activeIn(stage.id).empty() && producedIn(entry->aov, stage.id, active))
      return entry->aov;
  }
  return "visibility";
}

bool isProgressiveReferenceAov(const std::string& aov) {
  return isReferenceAov(aov);
}

void addReferenceInputs(const std::string& aov, FrameOutputs& outputs) {
  const ReferenceEntry* entry = ReferenceRegistry::instance().findAov(aov);
  if (isProgressiveReferenceAov(aov) || (entry && entry->inputs.has(FrameInput::SurfacePoints)))
    outputs.surfaces = true;
  if (entry && entry->inputs.has(FrameInput::PrePostColor) &&
      std::find(outputs.colors.begin(), outputs.colors.end(), kPrePostColorVersion) == outputs.colors.end())
    outputs.colors.push_back(kPrePostColorVersion);
}

void ReferenceView::cancel() {
  if (m_active) {
    if (m_oneShot)
      m_job.cancel();
    else
      m_reference.cancel();
  }
  m_active = false;
}

void ReferenceView::stop(ViewerState& state) {
  cancel();
  if (m_texture) { // a restart would replace them: not kept while compare mode is off
    m_texture.reset();
    m_snapshot = ProgressiveSnapshot{};
  }
  m_startedKey.clear();
  m_settlingKey.clear();
  m_metrics = {};
  state.reference.running = false;
}

std::string ReferenceView::keyFor(const ViewerState& state, unsigned seed, int width, int height,
                                  const std::string& aov) const {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  // The progressive references: technique parameters are not in the key (they change the frame,
  // not the ground truth).
  if (isProgressiveReferenceAov(aov))
    return state.sceneSpec + "|" + aov + "|" + size + "|" + state.params.toJson({"light", "camera.", "ao.radius"}).dump();
  // A one-shot reference: what it declares and, when it reads the colour before post, everything
  // that colour depends on (reference_registry.h referenceDependsOnKey), the techniques of the
  // other stages included; a reloaded scene computes it again.
  const ReferenceEntry& entry = ReferenceRegistry::instance().get(aov);
  Fnv1a64 h;
  hashReferenceKeys(entry, state.params, TechniqueRegistry::instance(), h);
  std::string key = "once|" + state.sceneSpec + "#" + std::to_string(state.sceneGeneration) + "|" + aov + "|" +
                    size + "|" + std::to_string(seed) + "|" + h.hex() + "|";
  for (const auto& id : techniquesOutside(state.selection.ordered(), entry.stage))
    key += id + ",";
  return key;
}

void ReferenceView::update(ViewerState& state, Renderer& renderer, unsigned seed, int width, int height) {
  m_width = width;
  m_height = height;
  const std::string aov = referenceAovFor(state);
  const unsigned long revision = state.params.revision();
  const bool paramsStill = revision == m_lastRevision;
  m_lastRevision = revision;
  // Everything the reference depends on, built again only when a parameter, the scene, the size,
  // the AOV or the techniques moved.
  KeyInputs inputs{state.sceneGeneration, revision, width, height, aov, state.selection.ordered()};
  if (!(inputs == m_keyInputs)) {
    m_keyInputs = std::move(inputs);
    m_key = keyFor(state, seed, width, height, aov);
  }
  if (m_key != m_startedKey) {
    // While the inputs change from frame to frame (the camera, a light or a key being dragged),
    // the old reference is only cancelled and cleared; it restarts, reading its inputs back once,
    // when they have held still for a frame.
    const bool settled = m_key == m_settlingKey;
    m_settlingKey = m_key;
    if (!settled) {
      cancel();
      m_snapshot = ProgressiveSnapshot{};
      m_texture.reset();
      m_metrics = {};
      state.reference = {};
      state.reference.aov = aov;
      return;
    }
    m_startedKey = m_key;
    restart(state, renderer, seed, aov);
    if (!m_active) return;
  }
  if (!takeLatest(state)) return; // nothing of this view yet
  // While a parameter is being dragged the frame changes every frame: it is read back and
  // measured once it holds still.
  if (paramsStill) measure(state, renderer, width, height, aov);
}

bool ReferenceView::takeLatest(ViewerState& state) {
  auto& status = state.reference;
  if (m_oneShot) {
    status.running = m_job.running();
    if (const std::string error = m_job.error(); !error.empty()) status.error = error;
    ReferenceJobResult result;
    result.generation = m_snapshot.generation;
    if (m_job.latest(result)) {
      m_snapshot = ProgressiveSnapshot{std::move(result.image), result.samples, result.generation, true};
      uploadImage(m_snapshot.image, m_texture, "viewer.reference");
      status.samples = result.samples;
      status.seconds = result.seconds;
    }
    return m_snapshot.generation == m_job.generation();
  }
  status.running = m_reference.running();
  status.samples = m_reference.samples();
  if (const std::string error = m_reference.error(); !error.empty()) status.error = error;
  if (m_reference.latest(m_snapshot)) uploadImage(m_snapshot.image, m_texture, "viewer.reference");
  return m_snapshot.generation == m_reference.generation();
}

void ReferenceView::restart(ViewerState& state, Renderer& renderer, unsigned seed, const std::string& aov) {
  cancel();
  m_metrics = {};
  m_snapshot = ProgressiveSnapshot{};
  m_texture.reset();
  auto& status = state.reference;
  status = {};
  status.aov = aov;
  m_oneShot = !isProgressiveReferenceAov(aov);
  try {
    if (m_oneShot)
      restartOneShot(state, renderer, seed, aov);
    else
      restartProgressive(state, renderer, seed, aov);
    m_active = true;
  } catch (const Error& e) {
    status.error = e.what();
    m_active = false;
  }
}

void ReferenceView::restartProgressive(ViewerState& state, Renderer& renderer, unsigned seed, const std::string& aov) {
  ProgressiveOptions options;
  options.seed = seed;
  options.aoRadius = state.params.getFloat("ao.radius");
  // A reused BVH needs only the lights and the camera: the meshes and textures are not copied
  // for a restart after a camera or light change.
  Scene view;
  view.lights = state.scene.lights;
  view.camera = state.scene.camera;
  applySceneParams(state.params, view);
  auto prepared = m_reference.preparedScene();
  if (prepared && m_sceneGeneration == state.sceneGeneration) {
    m_reference.start(prepared, view, renderer.readSurfaces(), aov, options);
  } else {
    Scene scene = state.scene;
    scene.lights = std::move(view.lights);
    scene.camera = view.camera;
    m_reference.start(scene, renderer.readSurfaces(), aov, options);
  }
  m_sceneGeneration = state.sceneGeneration;
}

void ReferenceView::restartOneShot(ViewerState& state, Renderer& renderer, unsigned seed, const std::string& aov) {
  const ReferenceEntry& entry = ReferenceRegistry::instance().get(aov);
  state.reference.exact = !entry.samples();
  ReferenceJobInput input{entry, sceneForReference(state.scene, state.params, entry), state.params,
                          entry.defaultSpp, seed, std::nullopt, std::nullopt, std::nullopt, std::nullopt};
  if (entry.inputs.has(FrameInput::SurfacePoints)) input.surfaces = renderer.readSurfaces();
  if (entry.inputs.has(FrameInput::PrePostColor)) {
    // The frame's own colour before post is the reference's input only when the reference measures
    // the post stage: for another stage it would hold that stage's techniques (`rtlab reference`
    // renders it without them).
    if (entry.stage != "post")
      throw Error(ExitCode::Usage, "reference '" + aov + "' reads the colour before post without the " + entry.stage +
                                       " stage's techniques: not available in the viewer");
    input.prePostColor = renderer.readColor(kPrePostColorVersion);
  }
  if (entry.inputs.has(FrameInput::TransparentFragments)) captureTransparency(state, entry, input);
  m_job.start(std::move(input));
}

void ReferenceView::captureTransparency(ViewerState& state, const ReferenceEntry& entry, ReferenceJobInput& input) {
  if (!m_captureRenderer || m_captureScene != state.sceneGeneration) {
    m_captureRenderer = std::make_unique<Renderer>(TechniqueRegistry::instance());
    m_captureRenderer->setScene(state.scene);
    m_captureScene = state.sceneGeneration;
  }
  m_captureRenderer->setTechniques(techniquesOutside(state.selection.ordered(), entry.stage));
  FrameOutputs outputs;
  outputs.colors = {kOpaqueColorVersion};
  outputs.transparentFragments = true;
  PassTimer timer(TimingMethod::CpuFinish);
  m_captureRenderer->render(state.params, m_width, m_height, outputs, timer);
  input.transparentFragments = m_captureRenderer->readTransparentFragments();
  input.opaqueColor = m_captureRenderer->readColor(kOpaqueColorVersion);
}

void ReferenceView::measure(ViewerState& state, Renderer& renderer, int width, int height, const std::string& aov) {
  // The metrics follow both the reference and the frame (technique parameters). FLIP costs a
  // frame or more on a loaded CPU, so they are measured again each time the reference's sample
  // count reaches the next power of two (16, 32, 64, ...), not after every batch.
  int bucket = 0;
  while ((2 << bucket) <= m_snapshot.samples)
    ++bucket;
  MetricsInputs inputs{m_snapshot.generation, bucket, state.params.revision(), state.selection.ordered()};
  if (inputs == m_metrics) return;
  m_metrics = std::move(inputs);
  auto& status = state.reference;
  // A one-shot reference is complete: measured against as soon as it is there. A progressive one
  // is not read back before it is good enough to measure against.
  LiveMetricsPolicy policy;
  if (m_oneShot) policy.minSamples = std::max(1, m_snapshot.samples);
  if (!liveReferenceReady(m_snapshot, width, height, policy, &status.waiting)) return;
  const LiveMetrics live = computeLiveMetrics(renderer.readAov(aov), m_snapshot, policy);
  status.waiting = live.reason;
  if (!live.ready) return;
  status.rmse = live.metrics.rmse;
  status.flip = live.metrics.flip;
  status.metricsSamples = live.referenceSamples;
}

} // namespace rtlab
