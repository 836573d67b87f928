#include "render/renderer.h"

#include "frame/aovs.h"
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "frame/stages.h"
#include "params/param_set.h"
#include "scene/scene_params.h"
#include "shading/base_passes.h"
#include "util/error.h"

#include <algorithm>

namespace rtlab {
namespace {

Image readTexture(const gl::Texture& tex, int channels, bool withMask) {
  const int w = tex.desc().width, h = tex.desc().height;
  std::vector<float> rgba(std::size_t(w) * h * 4);
  glGetTextureImage(tex.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
  Image img(w, h, channels);
  if (withMask) img.mask.resize(std::size_t(w) * h);
  for (int y = 0; y < h; ++y) {
    const int srcRow = h - 1 - y; // GL rows are bottom to top
    for (int x = 0; x < w; ++x) {
      const float* src = &rgba[(std::size_t(srcRow) * w + x) * 4];
      for (int c = 0; c < channels; ++c) img.at(x, y, c) = src[c];
      if (withMask) img.mask[std::size_t(y) * w + x] = src[3];
    }
  }
  return img;
}

} // namespace

Renderer::Renderer(const TechniqueRegistry& registry) : m_registry(registry) {}

Renderer::~Renderer() {
  m_techniques.clear();
  m_pool.releaseAll();
}

void Renderer::setScene(const Scene& scene) {
  m_scene = scene;
  m_sceneGpu = std::make_unique<SceneGpu>(m_scene);
  m_notifier.sceneSet();
}

void Renderer::setTechniques(const std::vector<std::string>& orderedIds) {
  // A technique's imported objects die with it: the pool must not hand them out afterwards.
  m_pool.setImports({});
  for (auto it = m_techniques.begin(); it != m_techniques.end();) {
    if (std::find(orderedIds.begin(), orderedIds.end(), it->first) == orderedIds.end()) it = m_techniques.erase(it);
    else ++it;
  }
  for (const auto& id : orderedIds)
    if (!m_techniques.count(id)) m_techniques.emplace(id, m_registry.get(id).create());
  m_order = orderedIds;
  m_notifier.setActive(orderedIds);
}

bool Renderer::stageHasTechnique(const StageInfo& stage) const {
  return std::any_of(m_order.begin(), m_order.end(), [&](const std::string& id) { return m_registry.get(id).info.stage == stage.id; });
}

void Renderer::checkAov(const std::string& aov) const {
  checkAovName(aov, m_order, m_registry);
  // A debug view exists only where its technique runs: on a scene its stage does not apply to
  // (transparency without a transparent material), the technique adds no pass.
  for (const auto& id : m_order) {
    const TechniqueInfo& info = m_registry.get(id).info;
    const StageInfo* owner = findStage(info.stage);
    for (const auto& view : info.debugViews)
      if (view.name == aov && owner && m_sceneGpu && !owner->appliesTo(m_scene))
        usageError("AOV '" + aov + "' is a debug view of '" + id + "', whose stage '" + owner->id +
                   "' does not run on scene '" + m_scene.name + "' (predicate " + predicateName(owner->predicate) + " is false)");
  }
  // A technique-resource AOV (arealight) exists only where its stage's technique computes it: on a
  // scene the stage applies to, without such a technique, the frame holds no value for it (the
  // lighting pass's point approximation of rectangles is in the colour instead).
  const StageInfo* stage = stageWithAov(aov);
  if (stage && stage->aov.rule == AovRule::TechniqueResource && m_sceneGpu && stage->appliesTo(m_scene) &&
      !stageHasTechnique(*stage)) {
    std::string ids;
    for (const auto& e : m_registry.entries())
      if (e.info.stage == stage->id) ids += (ids.empty() ? "-t " : " or -t ") + e.info.id;
    usageError("AOV '" + aov + "' needs an active " + stage->id + " technique on scene '" + m_scene.name + "' (" +
               (ids.empty() ? "no " + stage->id + " technique is registered in this build" : "add " + ids) + ")");
  }
}

AovSource Renderer::aovSource(const std::string& aov, const std::string& finalColor) const {
  AovSource src;
  if (aov == "color") {
    src.resource = finalColor;
    src.colorImage = true;
    return src;
  }
  const StageInfo* stage = stageWithAov(aov);
  if (!stage) return src; // depth, normal, albedo: from the G-buffer
  switch (stage->aov.rule) {
  case AovRule::OutputOrNeutral:
    src.resource = stage->output;
    src.neutral = stage->neutral;
    break;
  case AovRule::TechniqueResource:
    src.neutral = stage->aov.neutral;
    if (stage->appliesTo(m_scene)) { // checkAov made sure a technique of the stage is active
      src.resource = aov;
      src.required = true;
    }
    break;
  case AovRule::ColorVersionCoverage:
    src.resource = colorVersionResource(stage->colorVersion);
    src.colorImage = true;
    src.coverageAlpha = true;
    break;
  }
  return src;
}

void Renderer::render(const ParamSet& params, int width, int height, const FrameOutputs& outputs, PassTimer& timer) {
  if (!m_sceneGpu) throw Error(ExitCode::Internal, "render() before setScene()");
  for (const auto& aov : outputs.aovs) checkAov(aov);
  for (const auto& version : outputs.colors)
    if (!isColorVersion(version)) throw Error(ExitCode::Internal, "unknown colour version '" + version + "'");
  applySceneParams(params, m_scene);
  m_common.uploadLights(m_scene);
  m_notifier.deliver(m_scene.lights, m_order, m_techniques);
  const FrameView view = makeFrameView(m_scene.camera, width, height);
  FrameGraph graph(m_scene, params, view, *m_sceneGpu, m_programs, m_pool, m_common);

  m_common.hdrClamp.beginFrame(outputs.countHdrClamped);
  if (outputs.countHdrClamped) graph.importBuffer(HdrClampCounters::kResource, m_common.hdrClamp.buffer());
  const std::string finalColor = addStagePasses(graph);
  addTonemapPass(graph, finalColor);

  std::vector<std::string> targets;
  for (const auto& aov : outputs.aovs)
    targets.push_back(isBuiltinAov(aov) ? addAovPass(graph, aov, aovSource(aov, finalColor)) : aovResource(aov));
  for (const auto& version : outputs.colors) targets.push_back(colorVersionResource(version));
  if (outputs.displayColor) targets.push_back(res::kColorLdr);
  if (outputs.transparentFragments) targets.push_back(addFragmentCapturePass(graph, m_fragments, outputs.captureBandBytes));
  if (outputs.surfaces)
    for (const auto* r : {&res::kPosition, &res::kGeometry, &res::kNormal, &res::kShadowPosition, &res::kShadowNormal,
                          &res::kAlbedo, &res::kMaterial})
      targets.push_back(*r);
  graph.compile(targets);
  timer.beginFrame();
  graph.run(timer);
  timer.endFrame();
  m_lastPasses.clear();
  for (const auto& p : graph.passes())
    m_lastPasses.push_back(PassInfo{p.name, p.technique, p.kept, p.compute, graph.barrierBefore(p.name)});
}

std::string Renderer::addStagePasses(FrameGraph& graph) {
  // A stage runs when its scene predicate holds and a technique of it is active, or it has a
  // built-in fallback (docs/stages.md "The stage table").
  const auto& table = stages();
  std::vector<std::vector<std::string>> techniquesOf(table.size());
  for (const auto& id : m_order) techniquesOf[std::size_t(findStage(m_techniques.at(id)->info().stage)->order)].push_back(id);
  std::vector<bool> runs(table.size());
  bool rectLightsAsPoints = true;
  for (const auto& s : table) {
    const std::size_t i = std::size_t(s.order);
    runs[i] = s.appliesTo(m_scene) && (!techniquesOf[i].empty() || !s.fallback.empty());
    if (runs[i] && s.lighting == LightingEffect::ReplaceRectLights) rectLightsAsPoints = false;
  }
  // The resource a colour writer (the lighting pass: order -1, or a colour stage) writes: named
  // after the last version it stands for, i.e. up to the next colour stage that runs. So a frame
  // whose colour stages do not run writes color.hdr directly, with no copy.
  auto writerOutput = [&](int order) {
    std::string version = order < 0 ? colorVersions().front() : table[std::size_t(order)].colorVersion;
    for (std::size_t i = std::size_t(order + 1); i < table.size(); ++i) {
      if (table[i].colorVersion.empty()) continue;
      if (runs[i]) break;
      version = table[i].colorVersion;
    }
    return colorResource(version);
  };

  m_colorResources.clear();
  std::string color; // the current colour version's resource
  auto addLighting = [&] {
    color = writerOutput(-1);
    addLightingPass(graph, color, rectLightsAsPoints);
    m_colorResources[colorVersions().front()] = color;
  };
  addGBufferPass(graph);
  for (const auto& s : table) {
    const std::size_t i = std::size_t(s.order);
    if (!s.feedsLighting() && color.empty()) addLighting();
    if (runs[i] && s.feedsLighting()) {
      for (const auto& id : techniquesOf[i]) {
        graph.setTechnique(id);
        m_techniques.at(id)->setup(graph);
      }
    } else if (runs[i] && techniquesOf[i].empty()) {
      const std::string out = writerOutput(s.order);
      addStageFallback(graph, s.fallback, color, out);
      color = out;
    } else if (runs[i]) {
      // Colour stage: each technique reads the current version and writes the next; a stacked
      // technique before the last writes an intermediate of its own.
      for (std::size_t k = 0; k < techniquesOf[i].size(); ++k) {
        const std::string& id = techniquesOf[i][k];
        const std::string out = k + 1 == techniquesOf[i].size() ? writerOutput(s.order) : "color.after_" + id;
        graph.setTechnique(id);
        graph.setColorVersions(color, out);
        m_techniques.at(id)->setup(graph);
        if (graph.isProduced(out)) color = out; // a technique that wrote nothing leaves the colour as it was
      }
      graph.setColorVersions("", "");
    }
    graph.setTechnique("");
    if (!s.colorVersion.empty()) m_colorResources[s.colorVersion] = color;
  }
  if (color.empty()) addLighting();
  return color;
}

const std::string& Renderer::colorVersionResource(const std::string& version) const {
  const auto it = m_colorResources.find(version);
  if (it == m_colorResources.end()) throw Error(ExitCode::Internal, "colour version '" + version + "' does not exist");
  return it->second;
}

Image Renderer::readColor(const std::string& version) const {
  auto& pool = const_cast<ResourcePool&>(m_pool);
  const gl::Texture* tex = pool.find(colorVersionResource(version));
  const gl::Texture* geometry = pool.find(res::kGeometry);
  if (!tex || !geometry)
    throw Error(ExitCode::Internal, "colour version '" + version + "' was not kept (FrameOutputs::colors)");
  Image img = readTexture(*tex, 3, false);
  img.mask = readTexture(*geometry, 1, true).mask;
  return img;
}

std::vector<HdrClampCount> Renderer::readHdrClamped() const { return m_common.hdrClamp.read(); }

Image Renderer::readAov(const std::string& aov) const {
  const gl::Texture* tex = const_cast<ResourcePool&>(m_pool).find(aovResource(aov));
  if (!tex) throw Error(ExitCode::Internal, "AOV '" + aov + "' was not rendered");
  return readTexture(*tex, aovChannels(aov, m_registry), true);
}

Image Renderer::readDisplayColor() const {
  const gl::Texture* tex = const_cast<ResourcePool&>(m_pool).find(res::kColorLdr);
  if (!tex) throw Error(ExitCode::Internal, "display color was not rendered");
  return readTexture(*tex, 3, false);
}

SurfaceData Renderer::readSurfaces() const {
  auto& pool = const_cast<ResourcePool&>(m_pool);
  const gl::Texture* pos = pool.find(res::kPosition);
  const gl::Texture* geo = pool.find(res::kGeometry);
  const gl::Texture* nrm = pool.find(res::kNormal);
  const gl::Texture* shadowPos = pool.find(res::kShadowPosition);
  const gl::Texture* shadowNrm = pool.find(res::kShadowNormal);
  const gl::Texture* albedo = pool.find(res::kAlbedo);
  const gl::Texture* material = pool.find(res::kMaterial);
  if (!pos || !geo || !nrm || !shadowPos || !shadowNrm || !albedo || !material) throw Error(ExitCode::Internal, "surfaces were not kept (FrameOutputs::surfaces)");
  const Image p = readTexture(*pos, 3, false), g = readTexture(*geo, 3, true), n = readTexture(*nrm, 3, false);
  const Image sp = readTexture(*shadowPos, 3, false), sn = readTexture(*shadowNrm, 3, false);
  // Alpha: metallic (albedo) and roughness (material).
  const Image am = readTexture(*albedo, 3, true), em = readTexture(*material, 3, true);
  SurfaceData s;
  s.width = p.width;
  s.height = p.height;
  const std::size_t count = s.pixelCount();
  s.position.resize(count);
  s.geometricNormal.resize(count);
  s.shadingNormal.resize(count);
  s.shadingPoint.resize(count);
  s.smoothNormal.resize(count);
  s.baseColor.resize(count);
  s.metallic.resize(count);
  s.roughness.resize(count);
  s.valid.resize(count);
  auto unit = [](glm::vec3 v) { return glm::dot(v, v) > 0.0f ? glm::normalize(v) : glm::vec3(0.0f); };
  for (std::size_t i = 0; i < count; ++i) {
    s.valid[i] = g.mask[i] >= 0.5f ? 1 : 0;
    s.position[i] = glm::vec3(p.pixels[i * 3], p.pixels[i * 3 + 1], p.pixels[i * 3 + 2]);
    s.geometricNormal[i] = unit(glm::vec3(g.pixels[i * 3], g.pixels[i * 3 + 1], g.pixels[i * 3 + 2]));
    s.shadingNormal[i] = unit(glm::vec3(n.pixels[i * 3], n.pixels[i * 3 + 1], n.pixels[i * 3 + 2]));
    s.shadingPoint[i] = glm::vec3(sp.pixels[i * 3], sp.pixels[i * 3 + 1], sp.pixels[i * 3 + 2]);
    s.smoothNormal[i] = unit(glm::vec3(sn.pixels[i * 3], sn.pixels[i * 3 + 1], sn.pixels[i * 3 + 2]));
    s.baseColor[i] = glm::vec3(am.pixels[i * 3], am.pixels[i * 3 + 1], am.pixels[i * 3 + 2]);
    s.metallic[i] = am.mask[i];
    s.roughness[i] = em.mask[i];
  }
  return s;
}

const gl::Texture* Renderer::resource(const std::string& name) { return m_pool.find(name); }

std::vector<CounterValue> Renderer::counters() const {
  std::vector<CounterValue> out;
  for (const auto& id : m_order)
    for (const auto& c : m_techniques.at(id)->counters()) out.push_back(CounterValue{id, c.name, c.value});
  return out;
}

std::vector<ResourceUse> Renderer::resources() const {
  std::vector<ResourceUse> out;
  for (const auto& e : m_pool.entries()) out.push_back(ResourceUse{e.name, e.bytes});
  if (m_sceneGpu) {
    out.push_back(ResourceUse{"scene.geometry", m_sceneGpu->geometryBytes()});
    out.push_back(ResourceUse{"scene.textures", m_sceneGpu->textureBytes()});
    if (m_sceneGpu->triangleBytes() > 0) out.push_back(ResourceUse{"scene.triangles", m_sceneGpu->triangleBytes()});
  }
  for (const auto& [id, t] : m_techniques)
    if (t->ownedBytes() > 0) out.push_back(ResourceUse{id + ".owned", t->ownedBytes()});
  return out;
}

} // namespace rtlab
