#include "app/sweep_plan.h"

#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "frame/selection.h"
#include "frame/stages.h"
#include "reference/reference_registry.h"
#include "scene/load.h"
#include "scene/scene_params.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/hash.h"
#include "util/version.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

namespace fs = std::filesystem;

namespace rtlab {
namespace {

constexpr const char* kPlanFile = "sweep.json";

bool endsWithNoCase(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) return false;
  return true;
}

// The scene argument as a job on another working directory must see it (load.cpp's rule).
std::string absoluteSceneSpec(const std::string& spec) {
  std::error_code ec;
  if (fs::is_regular_file(spec, ec) || endsWithNoCase(spec, ".gltf") || endsWithNoCase(spec, ".glb"))
    return fs::absolute(spec).lexically_normal().string();
  return spec;
}

std::vector<std::string> splitTechniques(const std::vector<std::string>& lists) {
  std::vector<std::string> ids;
  for (const auto& list : lists) {
    std::size_t start = 0;
    while (start <= list.size()) {
      const auto comma = list.find(',', start);
      const std::string id = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (id.empty()) usageError("invalid -t '" + list + "': empty technique id");
      if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return ids;
}

// The stages with a registered reference, in frame order.
std::string stageWithReferenceList() {
  std::string s;
  for (const auto& st : stages())
    if (ReferenceRegistry::instance().findStage(st.id)) s += (s.empty() ? "" : ", ") + st.id;
  return s;
}

// A scene with only what applySceneParams reads (lights, camera, bounds): checks a point's
// light and camera values without copying the geometry.
Scene sceneSkeleton(const Scene& scene) {
  Scene s;
  s.lights = scene.lights;
  s.camera = scene.camera;
  s.instances = scene.instances;
  for (const auto& m : scene.meshes) {
    Mesh skeleton;
    skeleton.bounds = m.bounds;
    s.meshes.push_back(std::move(skeleton));
  }
  return s;
}

void applyBaseParams(const SweepPlan& plan, ParamSet& params) {
  for (const auto& [key, value] : plan.baseParams.items()) params.setJson(key, nlohmann::json::parse(value.dump()));
}

void applyPointValues(const SweepPoint& point, ParamSet& params) {
  for (const auto& [key, text] : point.values) params.setText(key, text);
}

std::string planId(const SweepPlan& plan) {
  SweepPlan copy = plan;
  copy.id.clear();
  return Fnv1a64().text(sweepPlanToJson(copy).dump()).hex();
}

void hashVec3(Fnv1a64& h, const glm::vec3& v) { h.f32(v.x).f32(v.y).f32(v.z); }

[[noreturn]] void invalidPlan(const std::string& dir, const std::string& why) {
  inputError("invalid sweep plan '" + (fs::path(dir) / kPlanFile).string() + "': " + why);
}

} // namespace

int sweepWarmupFrames(const SweepPlan& plan) { return plan.frames > 1 ? 2 : 1; }

std::string pointName(int index) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%03d", index);
  return buf;
}

std::string pointDir(const SweepPlan& plan, int index) { return (fs::path(plan.dir) / "points" / pointName(index)).string(); }

std::string referencePath(const SweepPlan& plan, const std::string& hash) {
  return (fs::path(plan.dir) / "reference" / (hash + ".exr")).string();
}

std::string cachedReferencePath(const std::string& hash) {
  fs::path root;
  if (const char* dir = std::getenv("RTLAB_CACHE_DIR"); dir && *dir) root = dir;
  else if (const char* home = std::getenv("HOME"); home && *home) root = fs::path(home) / ".cache" / "rtlab";
  else return "";
  return (root / "reference" / (hash + ".exr")).string();
}

std::string describePoint(const SweepPoint& point) {
  std::string s = point.technique;
  for (const auto& [key, value] : point.values) s += " " + key + "=" + value;
  return s;
}

std::string shellQuote(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '/' || c == '-' || c == '+' ||
           c == ':' || c == '=' || c == ',';
  });
  if (plain) return text;
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string sceneContentHash(const Scene& scene) {
  static_assert(sizeof(Vertex) == 12 * sizeof(float), "Vertex is hashed as raw floats");
  Fnv1a64 h;
  h.text("rtlab-scene-1");
  h.u64(scene.meshes.size());
  for (const auto& m : scene.meshes) {
    h.u64(m.vertices.size()).bytes(m.vertices.data(), m.vertices.size() * sizeof(Vertex));
    h.u64(m.indices.size()).bytes(m.indices.data(), m.indices.size() * sizeof(std::uint32_t));
    h.u64(std::uint64_t(std::int64_t(m.material)));
  }
  h.u64(scene.instances.size());
  for (const auto& i : scene.instances) {
    h.u64(std::uint64_t(i.mesh)).u64(i.transparent);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) h.f32(i.transform[c][r]);
  }
  h.u64(scene.materials.size());
  for (const auto& m : scene.materials) {
    h.f32(m.baseColor.x).f32(m.baseColor.y).f32(m.baseColor.z).f32(m.baseColor.w);
    h.f32(m.metallic).f32(m.roughness).f32(m.normalScale).f32(m.occlusionStrength).f32(m.alphaCutoff);
    hashVec3(h, m.emissive);
    for (int t : {m.baseColorTexture, m.metallicRoughnessTexture, m.normalTexture, m.emissiveTexture, m.occlusionTexture})
      h.u64(std::uint64_t(std::int64_t(t)));
    h.u64(std::uint64_t(m.alphaMode)).u64(m.doubleSided);
  }
  h.u64(scene.textures.size());
  for (const auto& t : scene.textures)
    h.u64(std::uint64_t(t.width)).u64(std::uint64_t(t.height)).u64(t.srgb).bytes(t.rgba8.data(), t.rgba8.size());
  h.u64(scene.lights.size());
  for (const auto& l : scene.lights) {
    h.u64(std::uint64_t(l.type)).f32(l.intensity).f32(l.range).f32(l.innerConeAngle).f32(l.outerConeAngle);
    h.f32(l.radius).f32(l.angle).f32(l.width).f32(l.height);
    for (const auto* v : {&l.color, &l.position, &l.direction, &l.right, &l.up}) hashVec3(h, *v);
  }
  const Camera& c = scene.camera;
  hashVec3(h, c.position);
  hashVec3(h, c.target);
  hashVec3(h, c.up);
  h.f32(c.fovY).f32(c.znear).f32(c.zfar);
  h.u64(scene.hasFileCamera).u64(scene.hasFileLights);
  hashVec3(h, scene.ambient);
  hashVec3(h, scene.background);
  return h.hex();
}

const ReferenceEntry& sweepReference(const SweepPlan& plan) {
  const ReferenceEntry* reference = ReferenceRegistry::instance().findStage(plan.stage);
  if (!reference) invalidPlan(plan.dir, "stage '" + plan.stage + "' has no reference");
  return *reference;
}

std::string referenceHash(const SweepPlan& plan, const ParamSet& params) {
  Fnv1a64 h;
  h.text("rtlab-reference-1").text(versionString()).text(plan.sceneHash).text(plan.aov);
  h.u64(std::uint64_t(plan.width)).u64(std::uint64_t(plan.height)).u64(std::uint64_t(plan.spp)).u64(plan.seed);
  const ReferenceEntry& reference = sweepReference(plan);
  hashReferenceKeys(reference, params, TechniqueRegistry::instance(), h);
  // The colour before post also depends on which techniques of the other stages run.
  if (reference.inputs.has(FrameInput::PrePostColor))
    for (const auto& id : plan.baseTechniques) h.text(id);
  return h.hex();
}

SweepPlan planSweep(const Args& frameArgs, const SweepRequest& request) {
  const TechniqueRegistry& registry = TechniqueRegistry::instance();
  SweepPlan plan;
  plan.version = versionString();
  plan.commit = gitCommit();
  plan.jobs = request.jobs;
  plan.command = request.command;
  std::error_code cwdError;
  plan.cwd = fs::current_path(cwdError).string();

  // Techniques: registered, not 'none', all in one stage that has a reference.
  plan.techniques = splitTechniques(request.techniques);
  if (plan.techniques.empty()) usageError("sweep needs -t ID[,ID...]: the techniques to sweep, all of one stage");
  std::vector<SweepTechnique> swept;
  for (const auto& id : plan.techniques) {
    if (id == "none") usageError("sweep -t takes technique ids; 'none' is not one");
    const TechniqueEntry& e = registry.get(id);
    swept.push_back({id, e.info.stage});
  }
  plan.stage = swept.front().stage;
  for (const auto& t : swept) {
    if (t.stage == plan.stage) continue;
    std::string list;
    for (const auto& u : swept) list += (list.empty() ? "" : ", ") + u.id + " (" + u.stage + ")";
    usageError("sweep -t techniques must belong to one stage: " + list);
  }
  const ReferenceEntry* reference = ReferenceRegistry::instance().findStage(plan.stage);
  if (!reference)
    usageError("technique '" + plan.techniques.front() + "' is in stage '" + plan.stage +
               "', which has no reference yet; sweep needs a stage with a reference: " + stageWithReferenceList());
  plan.spp = request.spp > 0 ? request.spp : reference->defaultSpp;
  if (plan.spp < reference->minSpp || plan.spp > reference->maxSpp)
    usageError("--spp " + std::to_string(plan.spp) + " is out of range " + std::to_string(reference->minSpp) + ".." +
               std::to_string(reference->maxSpp) + " for the " + reference->aov + " reference");
  // What the points output and compare with the reference: the reference's own AOV (the stage's
  // output for shadow, ao and indirect; e.g. `bloom`, `arealight`, `transparency` for the others).
  plan.aov = reference->aov;

  // The base frame: scene, preset, --set and frame options, validated as render would.
  ResolvedFrame base = resolveFrame(frameArgs);
  plan.scene = absoluteSceneSpec(base.options.sceneSpec);
  plan.width = base.options.width;
  plan.height = base.options.height;
  plan.frames = base.options.frames;
  plan.seed = base.options.seed;
  plan.backend = frameArgs.get("--backend", "auto");
  plan.timing = frameArgs.get("--timing", "auto");
  for (const auto& id : base.techniques)
    if (registry.get(id).info.stage != plan.stage) plan.baseTechniques.push_back(id);
  for (const auto& spec : base.params.specs())
    if (!(base.params.value(spec.key) == spec.def))
      plan.baseParams[spec.key] = paramValueToJson(spec, base.params.value(spec.key));

  const Scene fresh = loadScene(plan.scene);
  plan.sceneHash = sceneContentHash(fresh);
  ParamSet params = makeParamSet(fresh, registry);
  applyBaseParams(plan, params);

  for (const auto& vary : request.varies) {
    auto [key, spec] = splitVaryArgument(vary);
    const ParamSpec& ps = params.spec(key); // unknown key: exit 2 with a suggestion
    plan.axes.push_back({key, spec, expandSweepValues(ps, spec)});
  }
  const auto grid = buildSweepGrid(swept, plan.axes);

  const Scene skeleton = sceneSkeleton(fresh);
  std::map<std::string, int> referenceIndex;
  for (const auto& g : grid) {
    SweepPoint p;
    p.index = int(plan.points.size());
    p.technique = g.technique;
    p.values = g.values;
    ParamSet pointParams = params;
    applyPointValues(p, pointParams);
    Scene check = skeleton;
    try {
      applySceneParams(pointParams, check);
    } catch (const Error& e) {
      throw Error(e.code(), std::string(e.what()) + " at sweep point " + describePoint(p));
    }
    p.reference = referenceHash(plan, pointParams);
    if (referenceIndex.emplace(p.reference, int(plan.references.size())).second)
      plan.references.push_back({p.reference, p.index});
    plan.points.push_back(std::move(p));
  }

  plan.dir = fs::absolute(request.dir).lexically_normal().string();
  if (plan.dir.size() > 1 && plan.dir.back() == '/') plan.dir.pop_back();
  std::error_code ec;
  plan.binary = fs::read_symlink("/proc/self/exe", ec).string();
  if (ec) throw Error(ExitCode::Internal, "cannot find the rtlab binary (/proc/self/exe): " + ec.message());
  plan.id = planId(plan);
  return plan;
}

nlohmann::ordered_json sweepPlanToJson(const SweepPlan& plan) {
  nlohmann::ordered_json j;
  j["schema"] = 1;
  j["id"] = plan.id;
  j["version"] = plan.version;
  j["commit"] = plan.commit;
  j["binary"] = plan.binary;
  j["dir"] = plan.dir;
  j["scene"] = plan.scene;
  j["scene_hash"] = plan.sceneHash;
  j["stage"] = plan.stage;
  j["aov"] = plan.aov;
  j["size"] = {plan.width, plan.height};
  j["frames"] = plan.frames;
  j["seed"] = plan.seed;
  j["backend"] = plan.backend;
  j["timing"] = plan.timing;
  j["spp"] = plan.spp;
  // What decides the timings besides size, frames, backend and timing (docs/sweeps.md).
  j["warmup_frames"] = sweepWarmupFrames(plan);
  j["jobs"] = plan.jobs > 0 ? nlohmann::ordered_json(plan.jobs) : nlohmann::ordered_json();
  j["command"] = plan.command;
  j["cwd"] = plan.cwd;
  j["base_techniques"] = plan.baseTechniques;
  j["base_params"] = plan.baseParams;
  j["techniques"] = plan.techniques;
  nlohmann::ordered_json axes = nlohmann::ordered_json::array();
  for (const auto& a : plan.axes) axes.push_back({{"key", a.key}, {"spec", a.spec}, {"values", a.values}});
  j["vary"] = axes;
  nlohmann::ordered_json refs = nlohmann::ordered_json::array();
  for (const auto& r : plan.references) refs.push_back({{"hash", r.hash}, {"point", r.point}});
  j["references"] = refs;
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (const auto& p : plan.points) {
    nlohmann::ordered_json values = nlohmann::ordered_json::object();
    for (const auto& [k, v] : p.values) values[k] = v;
    points.push_back({{"index", p.index}, {"technique", p.technique}, {"values", values}, {"reference", p.reference}});
  }
  j["points"] = points;
  return j;
}

std::vector<std::string> sweepJobLines(const SweepPlan& plan) {
  std::vector<std::string> lines;
  const std::string head = shellQuote(plan.binary) + " sweep ";
  for (std::size_t k = 0; k < plan.references.size(); ++k)
    lines.push_back(head + "--run-reference " + shellQuote(plan.dir) + " " + std::to_string(k));
  for (const auto& p : plan.points)
    lines.push_back(head + "--run-point " + shellQuote(plan.dir) + " " + std::to_string(p.index));
  return lines;
}

void writeSweepPlan(const SweepPlan& plan) {
  writeTextAtomically((fs::path(plan.dir) / kPlanFile).string(), sweepPlanToJson(plan).dump(2) + "\n");
  std::string jobs;
  for (const auto& line : sweepJobLines(plan)) jobs += line + "\n";
  writeTextAtomically((fs::path(plan.dir) / "jobs.txt").string(), jobs);
}

SweepPlan readSweepPlan(const std::string& dirArg) {
  const std::string dir = fs::absolute(dirArg).lexically_normal().string();
  const std::string path = (fs::path(dir) / kPlanFile).string();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    inputError("cannot read sweep plan '" + path + "': " +
               (fs::exists(dir, ec) ? "no sweep.json (plan the sweep with 'rtlab sweep ... --out DIR' first)"
                                    : "no such directory"));
  const std::string text = readFileOrThrow(path, "sweep plan");
  SweepPlan plan;
  try {
    const auto j = nlohmann::ordered_json::parse(text);
    if (j.at("schema").get<int>() != 1) invalidPlan(dir, "schema must be 1");
    plan.id = j.at("id").get<std::string>();
    plan.version = j.at("version").get<std::string>();
    plan.commit = j.at("commit").get<std::string>();
    plan.binary = j.at("binary").get<std::string>();
    plan.dir = j.at("dir").get<std::string>();
    plan.scene = j.at("scene").get<std::string>();
    plan.sceneHash = j.at("scene_hash").get<std::string>();
    plan.stage = j.at("stage").get<std::string>();
    plan.aov = j.at("aov").get<std::string>();
    plan.width = j.at("size").at(0).get<int>();
    plan.height = j.at("size").at(1).get<int>();
    plan.frames = j.at("frames").get<int>();
    plan.seed = j.at("seed").get<unsigned>();
    plan.backend = j.at("backend").get<std::string>();
    plan.timing = j.at("timing").get<std::string>();
    plan.spp = j.at("spp").get<int>();
    // Added after schema 1 was first written: absent in older plans.
    if (j.contains("jobs") && j["jobs"].is_number_integer()) plan.jobs = j["jobs"].get<int>();
    plan.command = j.value("command", std::string());
    plan.cwd = j.value("cwd", std::string());
    plan.baseTechniques = j.at("base_techniques").get<std::vector<std::string>>();
    plan.baseParams = j.at("base_params");
    plan.techniques = j.at("techniques").get<std::vector<std::string>>();
    for (const auto& a : j.at("vary"))
      plan.axes.push_back({a.at("key").get<std::string>(), a.at("spec").get<std::string>(),
                           a.at("values").get<std::vector<std::string>>()});
    for (const auto& r : j.at("references")) plan.references.push_back({r.at("hash").get<std::string>(), r.at("point").get<int>()});
    for (const auto& p : j.at("points")) {
      SweepPoint point;
      point.index = p.at("index").get<int>();
      point.technique = p.at("technique").get<std::string>();
      for (const auto& [k, v] : p.at("values").items()) point.values.emplace_back(k, v.get<std::string>());
      point.reference = p.at("reference").get<std::string>();
      if (point.index != int(plan.points.size())) invalidPlan(dir, "points out of order");
      plan.points.push_back(std::move(point));
    }
  } catch (const nlohmann::json::exception& e) {
    invalidPlan(dir, e.what());
  }
  if (!plan.baseParams.is_object()) invalidPlan(dir, "base_params must be an object");
  for (const auto& r : plan.references)
    if (r.point < 0 || r.point >= int(plan.points.size())) invalidPlan(dir, "reference point out of range");
  // The folder may have moved since planning (copied back from a cluster): trust where it is now.
  plan.dir = dir;
  return plan;
}

ResolvedFrame resolvePointFrame(const SweepPlan& plan, const SweepPoint& point) {
  const TechniqueRegistry& registry = TechniqueRegistry::instance();
  ResolvedFrame f;
  FrameOptions& o = f.options;
  o.sceneSpec = plan.scene;
  o.width = plan.width;
  o.height = plan.height;
  o.frames = plan.frames;
  o.seed = plan.seed;
  o.backend = parseBackend(plan.backend);
  o.timing = parseTimingChoice(plan.timing);
  f.scene = loadScene(plan.scene);
  if (sceneContentHash(f.scene) != plan.sceneHash)
    inputError("scene '" + plan.scene + "' changed since the sweep in '" + plan.dir + "' was planned; plan it again");
  f.params = makeParamSet(f.scene, registry);
  applyBaseParams(plan, f.params);
  TechniqueSelection selection(registry);
  for (const auto& id : plan.baseTechniques) selection.activate(id);
  selection.activate(point.technique);
  f.techniques = selection.ordered();
  applyPointValues(point, f.params);
  applySceneParams(f.params, f.scene);
  return f;
}

} // namespace rtlab
