#include "gl/state.h"

#include <algorithm>
#include <sstream>

namespace rtlab::gl {
namespace {

int limit(GLenum pname, int tracked) {
  GLint n = 0;
  glGetIntegerv(pname, &n);
  return std::clamp(int(n), 0, tracked);
}

// How many of each indexed binding the snapshot covers in this context.
struct Counts {
  int images, storage, atomics, samplers, drawBuffers;
};

Counts counts() {
  return Counts{limit(GL_MAX_IMAGE_UNITS, kTrackedBindings), limit(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, kTrackedBindings),
                limit(GL_MAX_ATOMIC_COUNTER_BUFFER_BINDINGS, kTrackedBindings),
                limit(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, kTrackedSamplerUnits), limit(GL_MAX_DRAW_BUFFERS, kTrackedBindings)};
}

std::string indexed(const char* prefix, int i, const char* field) {
  return std::string(prefix) + "[" + std::to_string(i) + "]." + field;
}

// One place lists the fields: with `read` each value comes from glGet*, without it the known value.
StateSnapshot build(bool read) {
  const Counts n = counts();
  StateSnapshot s;
  auto add = [&](std::string name, double known, double actual) { s.fields.emplace_back(std::move(name), read ? actual : known); };
  auto enabled = [&](const char* name, GLenum cap) { add(name, 0, read ? double(glIsEnabled(cap)) : 0); };
  auto integer = [&](const char* name, GLenum pname, double known) {
    GLint v = 0;
    if (read) glGetIntegerv(pname, &v);
    add(name, known, double(v));
  };
  auto real = [&](const char* name, GLenum pname, double known) {
    GLfloat v = 0;
    if (read) glGetFloatv(pname, &v);
    add(name, known, double(v));
  };
  auto integerAt = [&](std::string name, GLenum pname, int i, double known) {
    GLint v = 0;
    if (read) glGetIntegeri_v(pname, GLuint(i), &v);
    add(std::move(name), known, double(v));
  };

  enabled("cull_face.enabled", GL_CULL_FACE);
  integer("cull_face.mode", GL_CULL_FACE_MODE, GL_BACK);
  integer("front_face", GL_FRONT_FACE, GL_CCW);
  enabled("blend.enabled", GL_BLEND);
  integer("blend.src_rgb", GL_BLEND_SRC_RGB, GL_ONE);
  integer("blend.dst_rgb", GL_BLEND_DST_RGB, GL_ZERO);
  integer("blend.src_alpha", GL_BLEND_SRC_ALPHA, GL_ONE);
  integer("blend.dst_alpha", GL_BLEND_DST_ALPHA, GL_ZERO);
  integer("blend.equation_rgb", GL_BLEND_EQUATION_RGB, GL_FUNC_ADD);
  integer("blend.equation_alpha", GL_BLEND_EQUATION_ALPHA, GL_FUNC_ADD);
  enabled("depth.test", GL_DEPTH_TEST);
  integer("depth.func", GL_DEPTH_FUNC, GL_LESS);
  integer("depth.mask", GL_DEPTH_WRITEMASK, GL_TRUE);
  enabled("depth.clamp", GL_DEPTH_CLAMP);
  for (int i = 0; i < n.drawBuffers; ++i) {
    GLboolean mask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    if (read) glGetBooleani_v(GL_COLOR_WRITEMASK, GLuint(i), mask);
    add(indexed("color_mask", i, "rgba"), 15, double(mask[0] | mask[1] << 1 | mask[2] << 2 | mask[3] << 3));
  }
  enabled("polygon_offset.fill", GL_POLYGON_OFFSET_FILL);
  real("polygon_offset.factor", GL_POLYGON_OFFSET_FACTOR, 0);
  real("polygon_offset.units", GL_POLYGON_OFFSET_UNITS, 0);
  enabled("scissor.test", GL_SCISSOR_TEST);
  enabled("stencil.test", GL_STENCIL_TEST);
  enabled("rasterizer_discard", GL_RASTERIZER_DISCARD);
  for (int i = 0; i < n.images; ++i) integerAt(indexed("image_unit", i, "texture"), GL_IMAGE_BINDING_NAME, i, 0);
  for (int i = 0; i < n.storage; ++i)
    integerAt(indexed("storage_buffer", i, "buffer"), GL_SHADER_STORAGE_BUFFER_BINDING, i, 0);
  for (int i = 0; i < n.atomics; ++i)
    integerAt(indexed("atomic_counter_buffer", i, "buffer"), GL_ATOMIC_COUNTER_BUFFER_BINDING, i, 0);
  integer("storage_buffer.generic", GL_SHADER_STORAGE_BUFFER_BINDING, 0);
  integer("atomic_counter_buffer.generic", GL_ATOMIC_COUNTER_BUFFER_BINDING, 0);
  integer("draw_indirect_buffer", GL_DRAW_INDIRECT_BUFFER_BINDING, 0);
  integer("dispatch_indirect_buffer", GL_DISPATCH_INDIRECT_BUFFER_BINDING, 0);
  GLint active = GL_TEXTURE0;
  if (read) glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  for (int i = 0; i < n.samplers; ++i) {
    GLint sampler = 0;
    if (read) {
      glActiveTexture(GLenum(GL_TEXTURE0 + i));
      glGetIntegerv(GL_SAMPLER_BINDING, &sampler);
    }
    add(indexed("sampler_unit", i, "sampler"), 0, double(sampler));
  }
  if (read) glActiveTexture(GLenum(active));
  add("active_texture", GL_TEXTURE0, double(active));
  integer("program", GL_CURRENT_PROGRAM, 0);
  integer("vertex_array", GL_VERTEX_ARRAY_BINDING, 0);
  integer("framebuffer.draw", GL_DRAW_FRAMEBUFFER_BINDING, 0);
  integer("framebuffer.read", GL_READ_FRAMEBUFFER_BINDING, 0);
  return s;
}

} // namespace

const double* StateSnapshot::find(const std::string& name) const {
  for (const auto& [n, v] : fields)
    if (n == name) return &v;
  return nullptr;
}

StateSnapshot captureState() { return build(true); }
StateSnapshot knownState() { return build(false); }

void restoreKnownState() {
  const Counts n = counts();
  glDisable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  glDisable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ZERO);
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_CLAMP);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, 0.0f);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_RASTERIZER_DISCARD);
  if (n.images > 0) glBindImageTextures(0, n.images, nullptr);
  if (n.storage > 0) glBindBuffersBase(GL_SHADER_STORAGE_BUFFER, 0, n.storage, nullptr);
  if (n.atomics > 0) glBindBuffersBase(GL_ATOMIC_COUNTER_BUFFER, 0, n.atomics, nullptr);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  glBindBuffer(GL_ATOMIC_COUNTER_BUFFER, 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  if (n.samplers > 0) glBindSamplers(0, n.samplers, nullptr);
  glActiveTexture(GL_TEXTURE0);
  glUseProgram(0);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::string firstDifference(const StateSnapshot& actual, const StateSnapshot& expected) {
  const std::size_t n = std::min(actual.fields.size(), expected.fields.size());
  for (std::size_t i = 0; i < n; ++i) {
    const auto& [name, value] = actual.fields[i];
    const auto& [expectedName, expectedValue] = expected.fields[i];
    if (name != expectedName) return "field " + std::to_string(i) + " is '" + name + "', expected '" + expectedName + "'";
    if (value != expectedValue) {
      std::ostringstream out;
      out << name << " is " << value << ", expected " << expectedValue;
      return out.str();
    }
  }
  if (actual.fields.size() != expected.fields.size())
    return std::to_string(actual.fields.size()) + " fields, expected " + std::to_string(expected.fields.size());
  return "";
}

} // namespace rtlab::gl
