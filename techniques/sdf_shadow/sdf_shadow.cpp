// sdf_shadow — soft shadows by sphere tracing a signed distance field towards light 0 (Hart 1996,
// "Sphere tracing"; the penumbra estimators of Quilez 2010 and 2018). The SDF is the scene's opaque
// triangles baked on the CPU (techniques/common/sdf/) into one volume per opaque instance (or one
// over the scene: sdf_shadow.volumes) packed in a 3D texture, rebuilt only when the geometry
// changes; the march takes the minimum over the volumes. Per pixel, from the G-buffer's shading
// point lifted by tmin along its normal, the march keeps the running minimum of k*h/t (classic) or
// of the improved estimate through the previous step's sphere (improved), with
// k = k_scale / sin(theta_L) from the light's own size (light0.angle, or asin(light0.radius /
// distance)). techniques/sdf_shadow/README.md has the guards, the artifacts and the measured cost
// and error.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "gl/buffer.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "techniques/common/sdf/sdf_texture.h"
#include "techniques/common/shadow/shadow_pass.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab {
namespace {

const std::string kVolume = "sdf_shadow.volume";
const std::string kCounts = "sdf_shadow.counts";
constexpr int kCountsBinding = 0; // shaders/sdf_shadow/visibility.frag
constexpr int kVolumeUnit = 3;

class SdfShadow final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "sdf_shadow";
    info.stage = "shadow";
    info.title = "SDF ray-marched soft shadows (Quilez 2010, 2018)";
    info.summary = "Sphere tracing a baked signed distance field towards light 0; the penumbra from the closest "
                   "miss angle, k = 1/sin of the light's angular radius";
    info.params = {
        ParamSpec::choice("sdf_shadow.volumes", "SDF volumes", {"scene", "per_instance"}, 1)
            .withFlags(kParamRealloc)
            .withHelp("scene: one volume over the padded bounds of all opaque geometry; per_instance: one per "
                      "opaque instance over its own bounds (small objects get fine voxels; the march takes the "
                      "minimum over them). More than 16 opaque instances, or more than 256^3 voxels in all: one "
                      "scene volume (counter sdf_volumes). Rebuilds the SDF"),
        ParamSpec::integer("sdf_shadow.resolution", "SDF resolution", 64, 32, 256)
            .logScale()
            .withUnit("voxels")
            .withFlags(kParamRealloc)
            .withHelp("Voxels along the longest axis of each volume's padded bounds (cubic voxels); walls "
                      "thinner than about a voxel leak. Rebuilds the SDF"),
        ParamSpec::integer("sdf_shadow.padding", "SDF padding", 2, 1, 8)
            .withUnit("voxels")
            .withFlags(kParamRealloc)
            .withHelp("Empty voxels around the geometry's bounds on every side. Rebuilds the SDF"),
        ParamSpec::real("sdf_shadow.k_scale", "k scale", 1.0, 0.01, 1000.0)
            .logScale()
            .withHelp("Multiplies the hardness k = 1/sin(light's angular radius) (1: the light's own size; "
                      "larger: harder, 1000 is the hard shadow); k is kept at least 1"),
        ParamSpec::choice("sdf_shadow.estimator", "Estimator", {"classic", "improved"}, 1)
            .withHelp("classic: min k*h/t (Quilez 2010); improved: the closest point between this step's and "
                      "the previous step's spheres (Quilez 2018), fewer artifacts at sharp occluder edges"),
        ParamSpec::integer("sdf_shadow.max_steps", "Max steps", 64, 16, 256)
            .logScale()
            .withUnit("steps")
            .withHelp("Step budget per pixel; a ray that runs out returns its running minimum (counted)"),
        ParamSpec::real("sdf_shadow.min_step", "Min step", 0.02, 0.005, 0.5)
            .logScale()
            .withUnit("scene units")
            .withHelp("Smallest step (guarantees progress along grazing rays)"),
        ParamSpec::real("sdf_shadow.max_step", "Max step", 0.2, 0.005, 0.5)
            .logScale()
            .withUnit("scene units")
            .withHelp("Largest step (never below the min step): larger skips penumbra minima (banding)"),
        ParamSpec::real("sdf_shadow.tmin", "tmin", 0.05, 0.01, 1.0)
            .logScale()
            .withUnit("scene units")
            .withHelp("The march starts at the shading point + normal * tmin, at t = tmin (never t = 0); small "
                      "values self-shadow through the SDF's interpolation error"),
        ParamSpec::real("sdf_shadow.hit_epsilon", "Hit epsilon", 1e-4, 1e-5, 1e-3)
            .logScale()
            .withUnit("scene units")
            .withHelp("A step whose distance is below epsilon * max(1, t) is a hit (visibility 0); never below "
                      "the float spacing of the position"),
        ParamSpec::real("sdf_shadow.slice_height", "Slice height", 0.1, 0.0, 1.0)
            .withHelp("Debug view sdf_shadow.slice: the horizontal layer at this fraction of the height of the "
                      "box around the volumes"),
    };
    info.debugViews = {
        {"sdf_shadow.slice", 3,
         "one horizontal slice of the SDF (x right, z down): grey outside (bands every 4 voxels), red inside, "
         "black at the surface"},
        {"sdf_shadow.steps", 1, "steps taken per pixel / sdf_shadow.max_steps (1: ran out of steps)"},
    };
    info.showcaseScene = "contact";
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void sceneChanged(const SceneChange& change) override {
    if (change.geometry) m_sdf.geometryChanged();
  }

  void setup(FrameGraph& frame) override {
    const ParamSet& params = frame.params();
    const auto layout = params.getEnumName("sdf_shadow.volumes") == "per_instance" ? SdfTexture::Layout::PerInstance
                                                                                  : SdfTexture::Layout::Scene;
    m_sdf.update(frame.scene(), layout, params.getInt("sdf_shadow.resolution"), params.getInt("sdf_shadow.padding"));
    if (!m_counts) m_counts = gl::BufferObject({gl::BufferKind::Storage, sizeof(GLuint)}, kCounts);
    frame.importTexture(kVolume, m_sdf.texture());
    frame.importBuffer(kCounts, m_counts);
    const std::pair<std::string, std::string> outputs[3] = {{"visibility", "sdf_shadow.visibility"},
                                                            {aovResource("sdf_shadow.steps"), "sdf_shadow.steps"},
                                                            {aovResource("sdf_shadow.slice"), "sdf_shadow.slice"}};
    for (int i = 0; i < 3; ++i) {
      ShadowScreenPass pass;
      pass.name = outputs[i].second;
      pass.output = outputs[i].first;
      pass.format = i == 0 ? GL_R16F : GL_RGBA32F;
      pass.fragment = "sdf_shadow/visibility.frag";
      pass.defines = {"OUTPUT " + std::to_string(i), "SDF_MAX_VOLUMES " + std::to_string(SdfTexture::kMaxVolumes)};
      pass.depthMap = false;
      pass.reads = {kVolume};
      if (i == 0)
        pass.declare = [](PassBuilder& b) { b.readWriteBuffer(kCounts, BufferBinding::Storage, kCountsBinding); };
      pass.bind = [this, i](PassContext& ctx, gl::Program& p) {
        if (i == 0) {
          m_counts.clear();
          glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCountsBinding, m_counts.id());
        }
        m_sdf.bind(p, kVolumeUnit);
        setTraceUniforms(ctx, p);
      };
      addShadowScreenPass(frame, pass);
    }
  }

  std::size_t ownedBytes() const override { return m_sdf.bytes() + (m_counts ? m_counts.desc().bytes : 0); }

  std::vector<TechniqueCounter> counters() const override {
    std::vector<TechniqueCounter> out;
    if (m_counts) {
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      out.push_back({"exhausted_rays", double(m_counts.downloadAs<GLuint>().at(0))});
    }
    out.push_back({"sdf_builds", double(m_sdf.builds())});
    out.push_back({"sdf_cache_hits", double(m_sdf.cacheHits())});
    out.push_back({"sdf_shared_hits", double(m_sdf.sharedHits())});
    out.push_back({"sdf_build_ms", m_sdf.lastBuildMs()});
    out.push_back({"sdf_voxels", double(m_sdf.voxels())});
    out.push_back({"sdf_volumes", double(m_sdf.volumes())});
    return out;
  }

private:
  // Light 0's kind and size (no private copy: light0.angle / light0.radius) and the march's knobs.
  static void setTraceUniforms(PassContext& ctx, gl::Program& p) {
    const Light& light = ctx.scene.lights.at(0);
    const bool directional = light.type == LightType::Directional;
    const ParamSet& params = ctx.params;
    const float minStep = params.getFloat("sdf_shadow.min_step");
    p.set("uDirectional", directional)
        .set("uLightPoint", light.position)
        .set("uLightTravel", glm::normalize(light.direction))
        .set("uSinAngle", directional ? std::sin(std::min(glm::radians(light.angle), glm::half_pi<float>())) : 0.0f)
        .set("uLightRadius", directional ? 0.0f : light.radius)
        .set("uKScale", params.getFloat("sdf_shadow.k_scale"))
        .set("uImproved", params.getEnumName("sdf_shadow.estimator") == "improved")
        .set("uSteps", params.getInt("sdf_shadow.max_steps"))
        .set("uMinStep", minStep)
        .set("uMaxStep", std::max(params.getFloat("sdf_shadow.max_step"), minStep))
        .set("uTmin", params.getFloat("sdf_shadow.tmin"))
        .set("uHitEpsilon", params.getFloat("sdf_shadow.hit_epsilon"))
        .set("uSliceHeight", params.getFloat("sdf_shadow.slice_height"));
  }

  TechniqueInfo m_info = staticInfo();
  SdfTexture m_sdf{kVolume};
  gl::BufferObject m_counts;
};

} // namespace

void registerTechnique_sdf_shadow(TechniqueRegistry& registry) { registerTechniqueType<SdfShadow>(registry); }

} // namespace rtlab
