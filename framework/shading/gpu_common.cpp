#include "shading/gpu_common.h"

#include "gl/program.h"
#include "util/error.h"
#include "util/sample_patterns.h"

#include <vector>

namespace rtlab {
namespace {

struct GpuLight {
  glm::vec4 positionType, directionRange, colorIntensity, spotCos, rectRight, rectUp;
};

float typeCode(LightType t) {
  switch (t) {
  case LightType::Directional: return 0.0f;
  case LightType::Point: return 1.0f;
  case LightType::Spot: return 2.0f;
  case LightType::Rect: return 3.0f;
  }
  return 0.0f;
}

} // namespace

void GpuCommon::uploadLights(const Scene& scene) {
  if (scene.lights.size() > std::size_t(kMaxLights))
    inputError("scene '" + scene.name + "' has " + std::to_string(scene.lights.size()) + " lights; rtlab shades at most " +
               std::to_string(kMaxLights));
  std::vector<GpuLight> data;
  for (const Light& l : scene.lights) {
    GpuLight g;
    g.positionType = glm::vec4(l.position, typeCode(l.type));
    g.directionRange = glm::vec4(glm::normalize(l.direction), l.range);
    g.colorIntensity = glm::vec4(l.color, l.intensity);
    g.spotCos = glm::vec4(std::cos(l.innerConeAngle), std::cos(l.outerConeAngle), l.twoSided ? 1.0f : 0.0f, 0);
    g.rectRight = glm::vec4(l.right, l.width);
    g.rectUp = glm::vec4(l.up, l.height);
    data.push_back(g);
  }
  if (!lights) {
    lights = gl::Buffer("lights");
    glNamedBufferStorage(lights.id(), GLsizeiptr(kMaxLights * sizeof(GpuLight)), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  if (!data.empty()) glNamedBufferSubData(lights.id(), 0, GLsizeiptr(data.size() * sizeof(GpuLight)), data.data());
  lightCount = int(data.size());
}

void GpuCommon::bindLights(gl::Program& program) const {
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, lights.id());
  program.set("uLightCount", lightCount);
}

void GpuCommon::drawFullscreen() const {
  glBindVertexArray(emptyVao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

gl::Texture makeBlueNoiseTexture(int size, std::uint32_t seed, const std::string& label) {
  gl::TextureDesc d;
  d.format = GL_R16F;
  d.width = d.height = size;
  d.wrap = GL_REPEAT;
  gl::Texture t(d, label);
  const std::vector<float> noise = blueNoise(size, seed);
  glTextureSubImage2D(t.id(), 0, 0, 0, size, size, GL_RED, GL_FLOAT, noise.data());
  return t;
}

} // namespace rtlab
