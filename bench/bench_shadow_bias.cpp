// Shadow-bias benchmark: shadow_map's acne / peter-panning trade-off, measured against an analytic
// ground truth (techniques/shadow_map/README.md shows and reads its tables).
//
// The scene is built here: a single-sided 12x12 ground at y = 0, a solid unit cube and a thin wall
// (0.06 thick) resting on it, all axis-aligned boxes, so exact binary visibility of light 0 is a
// segment-vs-box slab test. For every camera-visible pixel the world position and the geometric
// normal come from the G-buffer (the same points the technique shades); a point is truly lit when
// n.l > 0 and the segment to the light misses every box other than its own (boxes are convex).
// Pixels within kBandTexels shadow-map texels (measured in the light's image plane) of a change
// of the true visibility are a "band": there the answer depends on where texel centres fall
// (resolution aliasing, not bias), so they are counted apart. Outside the band:
//   acne  = truly lit pixels rendered shadowed (ground, and the cube's and wall's lit faces),
//   leak  = truly shadowed ground pixels rendered lit (peter-panning and bias-eroded outlines),
//   gap   = width of the lit strip between the wall and its shadow: the integral over the distance
//           d from the wall's shadowed face of the fraction of truly shadowed ground rendered lit.
// Rows vary one shadow.* parameter at a time from the defaults, for a directional (orthographic
// map) and a spot light (perspective map), each at 60 and at 10 degrees of elevation.
//   rtlab_bench_bias [--size WxH] [--frames N] [--light dir|spot|all] [--backend B] [--timing M] [--dump DIR]
#include "app/args.h"
#include "app/frame_options.h"
#include "app/measure.h"
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "image/image.h"
#include "render/renderer.h"
#include "scene/mesh_builder.h"
#include "scene/scene_params.h"
#include "shading/base_passes.h"
#include "techniques/common/shadow/shadow_depth.h"
#include "util/error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

using namespace rtlab;

namespace {

constexpr double kBandTexels = 1.5;   // half-width of the aliasing band, in shadow-map texels
constexpr double kAzimuthDeg = 30.0;  // light comes from +x, turned 30 degrees towards +z
constexpr double kGapBin = 0.01;      // world units per bin of the contact-gap profile
constexpr int kGapBins = 100;
constexpr int kGapMinPixels = 10;     // a bin needs this many truly shadowed pixels to count

struct Box {
  glm::dvec3 min, max;
};
// [0] the cube, [1] the thin wall (thin along x; its -x face is in shadow, the gap is measured there).
const Box kBoxes[2] = {{{1.0, 0.0, 0.5}, {2.0, 1.0, 1.5}}, {{-0.53, 0.0, -3.0}, {-0.47, 1.0, -1.4}}};
const glm::dvec3 kSpotTarget{0.5, 0.0, -0.5};

struct LightSetup {
  bool spot = false;
  double elevationDeg = 60.0;
  std::string name() const {
    return std::string(spot ? "spot" : "directional") + ", elevation " + std::to_string(int(elevationDeg)) + " deg";
  }
};

glm::dvec3 towardsLight(double elevationDeg) {
  const double e = glm::radians(elevationDeg), a = glm::radians(kAzimuthDeg);
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

Scene buildScene(const LightSetup& setup) {
  Scene s;
  s.name = "bias_test";
  Material m;
  m.name = "diffuse";
  m.baseColor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  s.materials.push_back(m);
  auto add = [&](Mesh mesh, const glm::vec3& at) {
    mesh.material = 0;
    s.meshes.push_back(std::move(mesh));
    s.instances.push_back({int(s.meshes.size()) - 1, glm::translate(glm::mat4(1.0f), at), false});
  };
  add(makePlane("ground", 12.0f, 12.0f, 8), glm::vec3(0.0f));
  for (int i = 0; i < 2; ++i)
    add(makeBox(i == 0 ? "cube" : "wall", glm::vec3(kBoxes[i].max - kBoxes[i].min)), glm::vec3(0.5 * (kBoxes[i].min + kBoxes[i].max)));

  Light l;
  l.name = "key";
  const glm::dvec3 up = towardsLight(setup.elevationDeg);
  if (setup.spot) {
    l.type = LightType::Spot;
    l.position = glm::vec3(kSpotTarget + 9.0 * up);
    l.direction = glm::vec3(-up);
    l.intensity = 200.0f;
    l.innerConeAngle = glm::radians(40.0f);
    l.outerConeAngle = glm::radians(50.0f);
  } else {
    l.type = LightType::Directional;
    l.direction = glm::vec3(-up);
    l.intensity = 3.0f;
  }
  s.lights.push_back(l);
  s.hasFileLights = true;
  // From the shadowed side: the cube's lit top and +z faces, its unlit -x face, the wall's unlit
  // -x face with the ground at its foot (the contact gap), and both shadows.
  s.camera.position = {-3.6f, 3.0f, 2.6f};
  s.camera.target = {0.6f, 0.2f, -0.6f};
  s.camera.fovY = 45.0f;
  fitClipPlanes(s.camera, s.worldBounds());
  s.hasFileCamera = true;
  return s;
}

// Segment p + t*d, t in (t0, t1), against an axis-aligned box (slab test).
bool segmentHitsBox(const glm::dvec3& p, const glm::dvec3& d, double t0, double t1, const Box& b) {
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-12) {
      if (p[a] < b.min[a] || p[a] > b.max[a]) return false;
      continue;
    }
    double ta = (b.min[a] - p[a]) / d[a], tb = (b.max[a] - p[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

bool insideBox(const glm::dvec3& p, const Box& b, double eps) {
  return glm::all(glm::greaterThanEqual(p, b.min - eps)) && glm::all(glm::lessThanEqual(p, b.max + eps));
}

// The analytic light 0 and the map's light space (for the band width and the frustum test).
// Directional lights and single-map spots only: the benchmark never makes a cube map.
struct Truth {
  LightSetup setup;
  LightSpace ls;
  glm::dvec3 lightPos{0}, lightDir{0}; // spot: position; directional: unit vector towards the light
  int resolution = 2048;

  glm::dvec3 toLight(const glm::dvec3& p, double& dist) const {
    if (!setup.spot) {
      dist = 1e30;
      return lightDir;
    }
    const glm::dvec3 v = lightPos - p;
    dist = glm::length(v);
    return v / dist;
  }
  double texelWorld(const glm::dvec3& p) const {
    if (!setup.spot) return ls.texelScale;
    return ls.texelScale * std::max(glm::dot(p - lightPos, glm::dvec3(ls.direction)), 0.0);
  }
  bool inMap(const glm::dvec3& p) const {
    const glm::vec4 c = ls.viewProj[0] * glm::vec4(glm::vec3(p), 1.0f);
    if (c.w <= 0.0f) return false;
    const glm::vec3 ndc = glm::vec3(c) / c.w;
    return glm::all(glm::lessThanEqual(glm::abs(ndc), glm::vec3(1.0f)));
  }
  // Exact binary visibility of a point on surface `own` (-1 ground, else a box) with normal n.
  bool lit(const glm::dvec3& p, const glm::dvec3& n, int own) const {
    double dist;
    const glm::dvec3 l = toLight(p, dist);
    if (glm::dot(n, l) <= 0.0) return false;
    for (int b = 0; b < 2; ++b)
      if (b != own && segmentHitsBox(p, l, 0.0, dist, kBoxes[b])) return false;
    return true;
  }
  // True when the visibility changes within kBandTexels map texels of p (on p's surface).
  bool inBand(const glm::dvec3& p, const glm::dvec3& n, int own, bool litHere) const {
    double dist;
    const glm::dvec3 l = toLight(p, dist);
    const double nl = glm::dot(n, l);
    if (std::abs(nl) < 0.05) return true; // surface almost along the light: texels smear over it
    const glm::dvec3 r = glm::normalize(glm::cross(l, std::abs(l.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)));
    const glm::dvec3 u = glm::cross(r, l);
    const double radius = kBandTexels * texelWorld(p);
    for (int k = 0; k < 8; ++k) {
      const double a = k * glm::pi<double>() / 4.0;
      const glm::dvec3 w = radius * (std::cos(a) * r + std::sin(a) * u);
      const glm::dvec3 q = p + w - (glm::dot(n, w) / nl) * l; // same map texel neighbourhood, on p's plane
      if (own >= 0 && !insideBox(q, kBoxes[own], 1e-4)) return true; // near an edge of the face
      if (lit(q, n, own) != litHere) return true;
    }
    return false;
  }
};

struct RowStats {
  long litGround = 0, acneGround = 0, litBox = 0, acneBox = 0, shadowGround = 0, leakGround = 0;
  long backFace = 0, backFaceLit = 0, band = 0, counted = 0;
  double gap = 0.0;
  bool gapOpen = false; // the whole measured strip was lit: gap is a lower bound
  double depthMs = 0.0, visMs = 0.0;
};

double pct(long part, long whole) { return whole > 0 ? 100.0 * double(part) / double(whole) : 0.0; }

std::vector<float> readRgba(const gl::Texture& tex) {
  std::vector<float> rgba(std::size_t(tex.desc().width) * tex.desc().height * 4);
  glGetTextureImage(tex.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
  return rgba;
}

// Compares the last frame's visibility AOV with the truth. `dump` (optional) gets a classification
// image: grey lit / dark shadowed (correct), red acne, blue leak, yellow band, green back-face lit.
RowStats evaluate(Renderer& renderer, const Truth& truth, Image* dump) {
  const Image vis = renderer.readAov("visibility");
  const gl::Texture* posTex = renderer.resource(res::kPosition);
  const gl::Texture* geoTex = renderer.resource(res::kGeometry);
  if (!posTex || !geoTex) throw Error(ExitCode::Internal, "G-buffer not available after the frame");
  const std::vector<float> pos = readRgba(*posTex), geo = readRgba(*geoTex);
  const int w = vis.width, h = vis.height;
  if (dump) *dump = Image(w, h, 3);
  RowStats s;
  std::vector<long> binShadow(kGapBins, 0), binLeak(kGapBins, 0);
  const Box& wall = kBoxes[1];
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t gi = (std::size_t(h - 1 - y) * w + x) * 4; // GL rows bottom to top
      if (geo[gi + 3] < 0.5f || vis.mask[std::size_t(y) * w + x] < 0.5f) continue;
      const glm::dvec3 p(pos[gi], pos[gi + 1], pos[gi + 2]);
      const glm::dvec3 n = glm::normalize(glm::dvec3(geo[gi], geo[gi + 1], geo[gi + 2]));
      int own = -2;
      if (n.y > 0.9 && std::abs(p.y) < 2e-3) own = -1;
      for (int b = 0; b < 2 && own == -2; ++b)
        if (insideBox(p, kBoxes[b], 2e-3)) own = b;
      if (own == -2 || !truth.inMap(p)) continue; // ground edge / outside the map: not measured
      const bool litTrue = truth.lit(p, n, own);
      const bool litRendered = vis.at(x, y, 0) > 0.5f;
      glm::vec3 color(0.0f);
      ++s.counted;
      if (own == -1 && !litTrue) { // contact-gap profile: every truly shadowed pixel of the strip
        const double d = wall.min.x - p.x; // distance from the wall's shadowed (-x) face
        if (d >= 0.0 && p.z > wall.min.z + 0.1 && p.z < wall.max.z - 0.1) {
          const int bin = int(d / kGapBin);
          if (bin < kGapBins) ++binShadow[bin], binLeak[bin] += litRendered;
        }
      }
      double dist;
      const bool backFace = own >= 0 && glm::dot(n, truth.toLight(p, dist)) <= 0.0;
      if (backFace) {
        ++s.backFace;
        s.backFaceLit += litRendered;
        color = litRendered ? glm::vec3(0.1f, 0.7f, 0.1f) : glm::vec3(0.15f);
      } else if (truth.inBand(p, n, own, litTrue)) {
        ++s.band;
        color = litRendered == litTrue ? glm::vec3(0.6f, 0.6f, 0.3f) : glm::vec3(0.9f, 0.9f, 0.1f);
      } else if (litTrue) {
        long& lit = own < 0 ? s.litGround : s.litBox;
        long& acne = own < 0 ? s.acneGround : s.acneBox;
        ++lit;
        acne += !litRendered;
        color = litRendered ? glm::vec3(0.8f) : glm::vec3(1.0f, 0.1f, 0.1f);
      } else if (own < 0) {
        ++s.shadowGround;
        s.leakGround += litRendered;
        color = litRendered ? glm::vec3(0.1f, 0.3f, 1.0f) : glm::vec3(0.3f);
      } else {
        color = glm::vec3(0.3f); // truly shadowed box face with n.l > 0 (shadowed by the other box)
      }
      if (dump)
        for (int c = 0; c < 3; ++c) dump->at(x, y, c) = color[c];
    }
  }
  // The lit strip that starts at the wall: bins from d = 0 while mostly lit, plus the partial
  // fraction of the first bin that is not (band pixels included: the gap is a world-space width).
  int b = 0;
  for (; b < kGapBins && binShadow[b] >= kGapMinPixels; ++b) {
    const double leak = double(binLeak[b]) / double(binShadow[b]);
    s.gap += kGapBin * leak;
    if (leak < 0.5) break;
  }
  s.gapOpen = b == kGapBins || (b < kGapBins && binShadow[b] < kGapMinPixels && s.gap > 0.0);
  return s;
}

struct Row {
  std::string label;
  std::vector<std::pair<std::string, std::string>> set;
};

std::vector<Row> sweepRows() {
  std::vector<Row> rows = {{"defaults", {}}, {"all biases 0", {{"shadow.constant_bias", "0"}, {"shadow.slope_bias", "0"}, {"shadow.normal_bias", "0"}}},
                           {"only constant 0.001", {{"shadow.slope_bias", "0"}, {"shadow.normal_bias", "0"}}},
                           {"only slope 1.5", {{"shadow.constant_bias", "0"}, {"shadow.normal_bias", "0"}}},
                           {"only normal 0.5", {{"shadow.constant_bias", "0"}, {"shadow.slope_bias", "0"}}}};
  for (const char* v : {"0", "0.0001", "0.005", "0.02", "0.05"}) rows.push_back({std::string("constant ") + v, {{"shadow.constant_bias", v}}});
  for (const char* v : {"0", "4"}) rows.push_back({std::string("slope ") + v, {{"shadow.slope_bias", v}}});
  for (const char* v : {"0", "2"}) rows.push_back({std::string("normal ") + v, {{"shadow.normal_bias", v}}});
  for (const char* v : {"256", "1024", "4096"}) rows.push_back({std::string("resolution ") + v, {{"shadow.resolution", v}}});
  for (const char* v : {"16", "32f"}) rows.push_back({std::string("format ") + v, {{"shadow.depth_format", v}}});
  // Front-face culling in the light pass: the map holds back faces (closed boxes), and the
  // single-sided ground is not in the map at all.
  rows.push_back({"cull front", {{"shadow.cull_front", "true"}}});
  rows.push_back({"cull front, biases 0", {{"shadow.cull_front", "true"}, {"shadow.constant_bias", "0"}, {"shadow.slope_bias", "0"}, {"shadow.normal_bias", "0"}}});
  // Depth quantization against a small constant bias alone (slope and normal offset off).
  for (const char* v : {"16", "24", "32f"})
    rows.push_back({std::string("format ") + v + ", only constant 0.0001",
                    {{"shadow.depth_format", v}, {"shadow.constant_bias", "0.0001"}, {"shadow.slope_bias", "0"}, {"shadow.normal_bias", "0"}}});
  return rows;
}

double passMs(const FrameStats& stats, const std::string& name) {
  for (const auto& p : stats.passes())
    if (p.name == name) return p.ms;
  return 0.0;
}

// World length along the light that shadow.constant_bias = 1 stands for, at distance z (perspective).
double constantBiasWorld(const Truth& t, double z) {
  const double n = t.ls.znear, f = t.ls.zfar;
  if (!t.setup.spot) return f - n;
  return (f - n) * z * z / (f * n); // 1 / (d window depth / dz)
}

void runSetup(const LightSetup& setup, const FrameOptions& options, TimingMethod timing, const std::string& dumpDir) {
  const TechniqueRegistry& registry = TechniqueRegistry::instance();
  ResolvedFrame frame;
  frame.options = options;
  frame.options.sceneSpec = "bias_test";
  frame.scene = buildScene(setup);
  frame.params = makeParamSet(frame.scene, registry);
  applySceneParams(frame.params, frame.scene);
  frame.techniques = {"shadow_map"};
  Renderer renderer(registry);
  renderer.setScene(frame.scene);
  const FrameOutputs outputs{{"visibility"}, false};

  Truth truth;
  truth.setup = setup;
  truth.lightPos = glm::dvec3(frame.scene.lights[0].position);
  truth.lightDir = -glm::normalize(glm::dvec3(frame.scene.lights[0].direction));
  {
    const LightSpace ls = shadowLightSpace(frame.scene, frame.params);
    const double zCube = setup.spot ? glm::dot(glm::dvec3(0.5 * (kBoxes[0].min + kBoxes[0].max)) - truth.lightPos, glm::dvec3(ls.direction)) : 0.0;
    truth.ls = ls;
    std::printf("\n### %s\n\n", setup.name().c_str());
    std::printf("%s map, near %.3f far %.3f; at 2048 one texel = %.4f world%s; constant bias 0.001 = %.4f world along the light%s\n\n",
                setup.spot ? "perspective" : "orthographic", ls.znear, ls.zfar, truth.texelWorld(glm::dvec3(0.5 * (kBoxes[0].min + kBoxes[0].max))),
                setup.spot ? " at the cube" : "", 0.001 * constantBiasWorld(truth, zCube), setup.spot ? " at the cube" : "");
  }
  std::printf("| setting | acne ground %% | acne boxes %% | leak ground %% | wall gap (world) | back faces lit %% | band %% | shadow.depth ms | visibility ms |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Row& row : sweepRows()) {
    for (const char* key : {"shadow.constant_bias", "shadow.slope_bias", "shadow.normal_bias", "shadow.resolution", "shadow.depth_format", "shadow.cull_front"})
      frame.params.reset(key);
    for (const auto& [key, value] : row.set) frame.params.setText(key, value);
    const FrameStats stats = renderMeasured(renderer, frame, outputs, timing, false);
    truth.ls = shadowLightSpace(frame.scene, frame.params);
    Image dump;
    RowStats s = evaluate(renderer, truth, dumpDir.empty() ? nullptr : &dump);
    s.depthMs = passMs(stats, "shadow.depth");
    s.visMs = passMs(stats, "shadow_map.visibility");
    std::printf("| %s | %.2f | %.2f | %.2f | %s%.3f | %.1f | %.1f | %.2f | %.2f |\n", row.label.c_str(), pct(s.acneGround, s.litGround),
                pct(s.acneBox, s.litBox), pct(s.leakGround, s.shadowGround), s.gapOpen ? ">= " : "", s.gap, pct(s.backFaceLit, s.backFace),
                pct(s.band, s.counted), s.depthMs, s.visMs);
    std::fflush(stdout);
    if (!dumpDir.empty()) {
      std::string name = std::string(setup.spot ? "spot" : "dir") + std::to_string(int(setup.elevationDeg)) + "_" + row.label + ".png";
      std::replace(name.begin(), name.end(), ' ', '_');
      writeImage(dumpDir + "/" + name, dump);
    }
  }
}

} // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<OptionSpec> specs = {
        {"--size", "", true, "WxH", "frame size (default 1280x720)"},
        {"--frames", "", true, "N", "measured frames per row for the pass times (default 5, after 2 warm-up)"},
        {"--light", "", true, "L", "dir|spot|all (default all)"},
        {"--backend", "", true, "B", "headless context: auto|egl|osmesa (default auto)"},
        {"--timing", "", true, "M", "pass timing: auto|gpu-query|cpu-finish (default auto)"},
        {"--dump", "", true, "DIR", "write a classification PNG per row into DIR"},
    };
    Args args("bench_bias", specs, argc, argv, 1);
    if (args.help()) {
      std::printf("%s", formatHelp("rtlab_bench_bias [options]", "shadow_map acne / peter-panning against an analytic truth", specs).c_str());
      return 0;
    }
    FrameOptions options;
    options.width = 1280, options.height = 720;
    if (args.has("--size")) parseSize(args.get("--size"), options.width, options.height);
    options.frames = args.has("--frames") ? int(parseIntOption("--frames", args.get("--frames"), 1, 1000)) : 5;
    if (args.has("--backend")) options.backend = parseBackend(args.get("--backend"));
    if (args.has("--timing")) options.timing = parseTimingChoice(args.get("--timing"));
    const std::string light = args.get("--light", "all");
    if (light != "dir" && light != "spot" && light != "all") usageError("--light must be dir, spot or all");

    auto context = createHeadlessContext(options.backend);
    const TimingMethod timing = resolveTiming(options.timing, context->info().software);
    std::printf("renderer: %s (%s), timing %s, %dx%d, pass times: median of %d frame(s)%s\n",
                context->info().renderer.c_str(), context->backendName().c_str(), timingName(timing), options.width,
                options.height, options.frames, options.frames > 1 ? " after 2 warm-up" : ", no warm-up");
    std::printf("percentages of camera-visible pixels inside the map, outside the %.1f-texel aliasing band; "
                "defaults: constant 0.001, slope 1.5, normal 0.5, resolution 2048, format 24\n", kBandTexels);
    for (bool spot : {false, true}) {
      if ((spot && light == "dir") || (!spot && light == "spot")) continue;
      for (double elevation : {60.0, 10.0}) runSetup({spot, elevation}, options, timing, args.get("--dump"));
    }
    return 0;
  } catch (const Error& e) {
    std::fprintf(stderr, "rtlab_bench_bias: error: %s\n", e.what());
    return int(e.code());
  }
}
