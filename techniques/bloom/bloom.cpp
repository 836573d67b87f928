// Bloom — the glow of bright light scattered in the eye or the lens, as a convolution of the
// frame's bright parts with a wide point-spread function (docs/contract.md "Bloom").
// Method `gaussian`: the textbook separable Gaussian per octave at full resolution, exact up to
// floating point. Method `mip`: Jorge Jimenez, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare", SIGGRAPH 2014 Advances in Real-Time Rendering — a mip chain built with a
// 13-tap downsample (Karis average on the first level) and rebuilt with 3x3 tent upsampling, each
// level weighted so that the chain's PSF approximates the declared mean of Gaussians
// (bloom_model.h planMipChain). techniques/bloom/README.md has the formulas and the measured trade-off.
#include "frame/frame_graph.h"
#include "frame/registry.h"
#include "gl/program_cache.h"
#include "params/param_set.h"
#include "shading/base_passes.h"
#include "shading/gpu_common.h"
#include "shading/hdr_clamp.h"
#include "techniques/bloom/bloom_model.h"

#include <cfloat>

namespace rtlab {
namespace {

constexpr const char* kBright = "bloom.bright";
constexpr const char* kBlurX = "bloom.blur_x";
constexpr const char* kSum = "bloom.sum";
constexpr const char* kCounts = "bloom.counts";
constexpr int kCountsBinding = 0; // shaders/bloom/bright.frag
constexpr int kMaxViewLevels = 8; // shaders/bloom/view.frag

std::string levelName(int j) { return "bloom.level" + std::to_string(j); }
std::string upName(int j) { return "bloom.up" + std::to_string(j); }

const std::vector<std::string> kFormats = {"rgba16f", "r11g11b10f", "rgba32f"};

GLenum storageFormat(int choice) {
  switch (choice) {
  case 1: return GL_R11F_G11F_B10F;
  case 2: return GL_RGBA32F;
  default: return GL_RGBA16F;
  }
}

// The largest finite value each channel of the storage format holds: 16-bit float 65504; the
// unsigned 11-bit floats of R11G11B10F 65024, its 10-bit blue 64512; 32-bit float FLT_MAX.
glm::vec3 storageMax(GLenum format) {
  if (format == GL_R11F_G11F_B10F) return {65024.0f, 65024.0f, 64512.0f};
  if (format == GL_RGBA32F) return glm::vec3(FLT_MAX);
  return glm::vec3(65504.0f);
}

// A bloom target: linear filtering and a black border, so bilinear taps outside the frame read 0
// (outside the frame is black, as in the definition).
gl::TextureDesc bloomTexture(int width, int height, GLenum format) {
  gl::TextureDesc d;
  d.format = format;
  d.width = std::max(width, 1);
  d.height = std::max(height, 1);
  d.minFilter = d.magFilter = GL_LINEAR;
  d.wrap = GL_CLAMP_TO_BORDER;
  for (float& b : d.border) b = 0.0f;
  return d;
}


// Sets the bright pass's uniforms on a program that includes shaders/bloom/bright.glsl.
void setBrightUniforms(gl::Program& p, const bloom::Definition& d) {
  p.set("uThreshold", d.threshold).set("uKnee", d.knee * d.threshold);
}

class Bloom final : public Technique {
public:
  static TechniqueInfo staticInfo() {
    TechniqueInfo info;
    info.id = "bloom";
    info.stage = "post";
    info.title = "Bloom (Gaussian octaves; mip chain, Jimenez 2014)";
    info.summary = "Adds intensity x (soft-knee bright pass convolved with a mean of Gaussians of widths sigma*2^k) "
                   "to the linear colour";
    info.showcaseScene = "glow";
    info.params = {
        ParamSpec::choice("bloom.method", "Method", {"gaussian", "mip"}, 1)
            .withHelp("gaussian: separable Gaussian per octave at full resolution (exact, cost grows with sigma*2^k); "
                      "mip: 13-tap downsample and tent upsample chain (Jimenez 2014), cost nearly constant"),
        ParamSpec::real("bloom.threshold", "Threshold", 1.0, 0.0, 20.0)
            .withUnit("luma").withHelp("T: luma where the bright pass starts (Rec. 709 luma of the linear colour)"),
        ParamSpec::real("bloom.knee", "Knee", 0.5, 0.0, 1.0)
            .withUnit("x threshold")
            .withHelp("K/T: width of the quadratic soft knee below and above T (0: linear ramp from T, no knee)"),
        ParamSpec::real("bloom.intensity", "Intensity", 0.1, 0.0, 4.0)
            .withHelp("Scale of the blurred bright pass added to the colour (the bloom AOV's factor)"),
        ParamSpec::real("bloom.sigma", "Sigma", 2.0, 0.5, 64.0)
            .logScale().withUnit("pixels").withHelp("Width of the first octave's Gaussian, in pixels of the frame"),
        ParamSpec::integer("bloom.octaves", "Octaves", 5, 1, 10)
            .withHelp("n: the PSF is the mean of n Gaussians of widths sigma*2^k, k = 0..n-1"),
        ParamSpec::boolean("bloom.karis", "Karis average", true)
            .withHelp("mip: weight the first downsample's five 2x2 groups by 1/(1+luma) (suppresses fireflies; "
                      "does not conserve the energy of isolated bright pixels)"),
        ParamSpec::choice("bloom.format", "Storage format", kFormats, 0)
            .withFlags(kParamRealloc)
            .withHelp("Format of the bright pass, blur and mip targets; colour above its range is clamped and counted"),
        ParamSpec::boolean("bloom.hard_cut", "Hard threshold", false)
            .withHelp("Replace the soft knee by the hard cut luma > T ? c : 0 (pops as luma crosses T; for comparison)"),
    };
    info.debugViews = {
        {"bloom", 3, "intensity x (bright pass convolved with the PSF): what bloom adds to the colour (A = 1)"},
        {"bloom.bright", 3, "the soft-knee bright pass, after non-finite pixels became 0 and the storage clamp"},
        {"bloom.levels", 3,
         "mip method: the downsampled levels 1..L side by side at their own resolution (level 1 top left); "
         "mask 0 with the gaussian method"},
    };
    return info;
  }
  const TechniqueInfo& info() const override { return m_info; }

  void setup(FrameGraph& frame) override {
    const ParamSet& params = frame.params();
    const bloom::Definition d = bloom::definitionFrom(params);
    const GLenum format = storageFormat(params.getEnum("bloom.format"));
    const bool mip = params.getEnumName("bloom.method") == "mip";
    const bool counting = frame.isImported(HdrClampCounters::kResource);
    if (counting) {
      if (!m_counts) m_counts = gl::BufferObject({gl::BufferKind::Storage, 2 * sizeof(GLuint)}, kCounts);
      frame.importBuffer(kCounts, m_counts);
      m_counted = true;
    }
    addBrightPass(frame, d, format, counting);
    bloom::MipPlan plan;
    if (mip) {
      plan = bloom::planMipChain(d, frame.width(), frame.height());
      addMipPasses(frame, plan, format, params.getBool("bloom.karis"));
    } else {
      addGaussianPasses(frame, d, format);
    }
    m_capped = plan.cappedOctaves;
    addComposite(frame, "bloom.composite", frame.colorOutput(), d, plan, mip, false);
    addComposite(frame, "bloom.aov", aovResource("bloom"), d, plan, mip, true);
    addViews(frame, plan, mip);
  }

  std::size_t ownedBytes() const override { return m_counts ? 2 * sizeof(GLuint) : 0; }

  std::vector<TechniqueCounter> counters() const override {
    std::vector<TechniqueCounter> out;
    if (m_counted && m_counts) {
      glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
      const std::vector<GLuint> v = m_counts.downloadAs<GLuint>();
      out.push_back({"nonfinite_pixels", double(v[0])});
      out.push_back({"clamped_pixels", double(v[1])});
    }
    out.push_back({"capped_octaves", double(m_capped)});
    return out;
  }

private:
  // Colour before bloom -> bloom.bright: non-finite pixels become 0, channels above the storage
  // format's range are clamped to it (both counted on a counting frame), then the bright pass.
  void addBrightPass(FrameGraph& frame, const bloom::Definition& d, GLenum format, bool counting) {
    const std::string input = frame.colorInput();
    const glm::vec3 maxValue = storageMax(format);
    frame.addPass("bloom.bright",
        [&](PassBuilder& b) {
          b.read(input);
          b.write(kBright, bloomTexture(frame.width(), frame.height(), format));
          if (counting) b.readWriteBuffer(kCounts, BufferBinding::Storage, kCountsBinding);
        },
        [=](PassContext& ctx) {
          std::vector<std::string> defines;
          if (counting) {
            defines.push_back("BLOOM_COUNT");
            ctx.buffer(kCounts).clear();
          }
          if (d.hardCut) defines.push_back("HARD_CUT");
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "bloom/bright.frag"}, defines, "bloom.bright"});
          ctx.beginFullscreen("bloom.bright", {kBright});
          p.use();
          ctx.texture(input).bind(0);
          p.set("uColor", 0).set("uStorageMax", maxValue);
          setBrightUniforms(p, d);
          ctx.common.drawFullscreen();
        });
  }

  // Octave k: a horizontal pass into bloom.blur_x, then a vertical one added into bloom.sum with
  // weight 1/n (the first octave overwrites it). Taps beyond the frame read black, so each pass
  // stops at the frame's edge: no tap (and no texture) is larger than the frame.
  void addGaussianPasses(FrameGraph& frame, const bloom::Definition& d, GLenum format) {
    const gl::TextureDesc desc = bloomTexture(frame.width(), frame.height(), format);
    for (int k = 0; k < d.octaves; ++k) {
      const double sigma = bloom::octaveSigma(d, k);
      const int radius = bloom::gaussianRadius(sigma);
      const float norm = float(bloom::gaussianNormalisation(sigma, radius));
      for (int axis = 0; axis < 2; ++axis) {
        const std::string name = std::string(axis == 0 ? "bloom.blur_x" : "bloom.blur_y") + std::to_string(k);
        const std::string source = axis == 0 ? kBright : kBlurX;
        const std::string target = axis == 0 ? kBlurX : kSum;
        const int taps = std::min(radius, (axis == 0 ? frame.width() : frame.height()) - 1);
        const float scale = axis == 0 ? norm : norm / float(d.octaves);
        const bool accumulate = axis == 1 && k > 0;
        frame.addPass(name,
            [&](PassBuilder& b) {
              b.read(source);
              b.write(target, desc);
            },
            [=](PassContext& ctx) {
              gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "bloom/blur.frag"}, {}, "bloom.blur"});
              ctx.beginFullscreen(name, {target});
              if (accumulate) {
                glEnable(GL_BLEND);
                glBlendFunc(GL_ONE, GL_ONE);
              }
              p.use();
              ctx.texture(source).bind(0);
              p.set("uSource", 0)
                  .set("uDirection", axis == 0 ? glm::ivec2(1, 0) : glm::ivec2(0, 1))
                  .set("uSigma", float(sigma))
                  .set("uTaps", taps)
                  .set("uScale", scale);
              ctx.common.drawFullscreen();
            });
      }
    }
  }

  // Down: bloom.bright -> level 1 -> ... -> level L (13 taps; Karis on the first). Up: level j's
  // weighted image plus the tent-upsampled coarser result, from L-1 to 1; the composite does level 0.
  void addMipPasses(FrameGraph& frame, const bloom::MipPlan& plan, GLenum format, bool karis) {
    const int w = frame.width(), h = frame.height();
    for (int j = 1; j <= plan.levels; ++j) {
      const std::string source = j == 1 ? std::string(kBright) : levelName(j - 1);
      const std::string target = levelName(j);
      const gl::TextureDesc desc = bloomTexture(w >> j, h >> j, format);
      const bool useKaris = karis && j == 1;
      frame.addPass("bloom.down" + std::to_string(j),
          [&](PassBuilder& b) {
            b.read(source);
            b.write(target, desc);
          },
          [=](PassContext& ctx) {
            gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "bloom/downsample.frag"}, {}, "bloom.down"});
            ctx.beginFullscreen(target, {target});
            p.use();
            ctx.texture(source).bind(0);
            p.set("uSource", 0).set("uTargetSize", glm::ivec2(desc.width, desc.height)).set("uKaris", useKaris);
            ctx.common.drawFullscreen();
          });
    }
    for (int j = plan.levels - 1; j >= 1; --j) {
      const std::string level = levelName(j), target = upName(j);
      const std::string coarser = j + 1 == plan.levels ? levelName(j + 1) : upName(j + 1);
      const float levelWeight = plan.weights[std::size_t(j)];
      const float coarserWeight = j + 1 == plan.levels ? plan.weights[std::size_t(j + 1)] : 1.0f;
      const gl::TextureDesc desc = bloomTexture(w >> j, h >> j, format);
      frame.addPass("bloom.up" + std::to_string(j),
          [&](PassBuilder& b) {
            b.read(level);
            b.read(coarser);
            b.write(target, desc);
          },
          [=](PassContext& ctx) {
            gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "bloom/upsample.frag"}, {}, "bloom.up"});
            ctx.beginFullscreen(target, {target});
            p.use();
            ctx.texture(level).bind(0);
            ctx.texture(coarser).bind(1);
            p.set("uLevel", 0)
                .set("uCoarser", 1)
                .set("uLevelWeight", levelWeight)
                .set("uCoarserWeight", coarserWeight)
                .set("uTargetSize", glm::ivec2(desc.width, desc.height));
            ctx.common.drawFullscreen();
          });
    }
  }

  // The colour output (input + bloom, the HDR clamp) or, with `aov`, the bloom AOV alone (RGBA32F,
  // A = 1): one shader, so both see the same value; the AOV pass is culled unless requested.
  void addComposite(FrameGraph& frame, const std::string& name, const std::string& output, const bloom::Definition& d,
                    const bloom::MipPlan& plan, bool mip, bool aov) {
    const std::string input = frame.colorInput();
    const std::string coarser = !mip || plan.levels == 0 ? std::string() : plan.levels == 1 ? levelName(1) : upName(1);
    const float brightWeight = mip ? plan.weights[0] : 0.0f;
    const float coarserWeight = mip && plan.levels == 1 ? plan.weights[1] : 1.0f;
    const float intensity = d.intensity;
    frame.addPass(name,
        [&](PassBuilder& b) {
          if (!aov) b.read(input);
          if (mip) b.read(kBright);
          else b.read(kSum);
          if (!coarser.empty()) b.read(coarser);
          b.write(output, frameTexture(frame, aov ? GL_RGBA32F : GL_RGBA16F));
          if (!aov) HdrClampCounters::declareUse(frame, b);
        },
        [=](PassContext& ctx) {
          std::vector<std::string> defines;
          if (aov) defines.push_back("OUTPUT_AOV");
          if (mip) defines.push_back("METHOD_MIP");
          if (!coarser.empty()) defines.push_back("HAS_COARSER");
          if (!aov && ctx.common.hdrClamp.counting()) defines.push_back("HDR_CLAMP_COUNT");
          gl::Program& p = ctx.programs.get({{"common/fullscreen.vert", "bloom/composite.frag"}, defines, name});
          ctx.beginFullscreen(name, {output});
          p.use();
          if (!aov) ctx.texture(input).bind(0);
          ctx.texture(mip ? std::string(kBright) : std::string(kSum)).bind(1);
          if (!coarser.empty()) ctx.texture(coarser).bind(2);
          p.set("uColor", 0)
              .set("uBloomBase", 1)
              .set("uCoarser", 2)
              .set("uBaseWeight", brightWeight)
              .set("uCoarserWeight", coarserWeight)
              .set("uIntensity", intensity);
          if (!aov) ctx.common.hdrClamp.bind(p, name);
          ctx.common.drawFullscreen();
        });
  }

  void addViews(FrameGraph& frame, const bloom::MipPlan& plan, bool mip) {
    const std::string bright = aovResource("bloom.bright");
    frame.addPass("bloom.view_bright",
        [&](PassBuilder& b) {
          b.read(kBright);
          b.write(bright, frameTexture(frame, GL_RGBA32F));
        },
        [=](PassContext& ctx) {
          gl::Program& p =
              ctx.programs.get({{"common/fullscreen.vert", "bloom/view.frag"}, {"VIEW_BRIGHT"}, "bloom.view_bright"});
          ctx.beginFullscreen(bright, {bright});
          p.use();
          ctx.texture(kBright).bind(0);
          p.set("uBright", 0);
          ctx.common.drawFullscreen();
        });
    const std::string levels = aovResource("bloom.levels");
    const int shown = mip ? std::min(plan.levels, kMaxViewLevels) : 0;
    frame.addPass("bloom.view_levels",
        [&](PassBuilder& b) {
          for (int j = 1; j <= shown; ++j) b.read(levelName(j));
          b.write(levels, frameTexture(frame, GL_RGBA32F));
        },
        [=](PassContext& ctx) {
          gl::Program& p =
              ctx.programs.get({{"common/fullscreen.vert", "bloom/view.frag"}, {"VIEW_LEVELS"}, "bloom.view_levels"});
          ctx.beginFullscreen(levels, {levels});
          p.use();
          std::vector<int> units(kMaxViewLevels, 0);
          for (int j = 1; j <= shown; ++j) {
            ctx.texture(levelName(j)).bind(GLuint(j));
            units[std::size_t(j - 1)] = j;
          }
          p.set("uLevels", units).set("uLevelCount", shown).set("uFrameSize", glm::ivec2(ctx.view.width, ctx.view.height));
          ctx.common.drawFullscreen();
        });
  }

  TechniqueInfo m_info = staticInfo();
  gl::BufferObject m_counts;
  bool m_counted = false;
  int m_capped = 0;
};

} // namespace

void registerTechnique_bloom(TechniqueRegistry& registry) { registerTechniqueType<Bloom>(registry); }

} // namespace rtlab
