#include "shading/scene_gpu.h"

#include <algorithm>
#include <cstddef>
#include <cmath>

namespace rtlab {
namespace {

enum TextureUnit : GLuint { kUnitBaseColor = 0, kUnitMetallicRoughness = 1, kUnitNormal = 2, kUnitEmissive = 3, kUnitOcclusion = 4 };

gl::Texture makeSolid(const std::uint8_t rgba[4], const std::string& label) {
  gl::TextureDesc d;
  d.format = GL_RGBA8;
  d.width = d.height = 1;
  d.wrap = GL_REPEAT;
  gl::Texture t(d, label);
  glTextureSubImage2D(t.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  return t;
}

int mipLevels(int w, int h) { return 1 + int(std::floor(std::log2(double(std::max(w, h))))); }

} // namespace

SceneGpu::SceneGpu(const Scene& scene) : m_scene(scene) {
  for (const auto& mesh : scene.meshes) {
    MeshGpu g;
    g.vao = gl::VertexArray("mesh:" + mesh.name);
    g.vertices = gl::Buffer("vertices:" + mesh.name);
    g.indices = gl::Buffer("indices:" + mesh.name);
    const auto vbytes = GLsizeiptr(mesh.vertices.size() * sizeof(Vertex));
    const auto ibytes = GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t));
    glNamedBufferStorage(g.vertices.id(), std::max<GLsizeiptr>(vbytes, 1), mesh.vertices.empty() ? nullptr : mesh.vertices.data(), 0);
    glNamedBufferStorage(g.indices.id(), std::max<GLsizeiptr>(ibytes, 1), mesh.indices.empty() ? nullptr : mesh.indices.data(), 0);
    m_geometryBytes += std::size_t(vbytes + ibytes);
    g.indexCount = GLsizei(mesh.indices.size());
    const GLuint vao = g.vao.id();
    glVertexArrayVertexBuffer(vao, 0, g.vertices.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, g.indices.id());
    auto attrib = [&](GLuint index, GLint size, std::size_t offset) {
      glEnableVertexArrayAttrib(vao, index);
      glVertexArrayAttribFormat(vao, index, size, GL_FLOAT, GL_FALSE, GLuint(offset));
      glVertexArrayAttribBinding(vao, index, 0);
    };
    attrib(0, 3, offsetof(Vertex, position));
    attrib(1, 3, offsetof(Vertex, normal));
    attrib(2, 4, offsetof(Vertex, tangent));
    attrib(3, 2, offsetof(Vertex, uv));
    m_meshes.push_back(std::move(g));
  }
  for (const auto& img : scene.textures) {
    gl::TextureDesc d;
    d.format = img.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    d.width = std::max(img.width, 1);
    d.height = std::max(img.height, 1);
    d.levels = mipLevels(d.width, d.height);
    d.minFilter = GL_LINEAR_MIPMAP_LINEAR;
    d.magFilter = GL_LINEAR;
    d.wrap = GL_REPEAT;
    gl::Texture t(d, "texture:" + img.name);
    if (img.rgba8.size() == std::size_t(img.width) * img.height * 4 && img.width > 0) {
      glTextureSubImage2D(t.id(), 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba8.data());
      glGenerateTextureMipmap(t.id());
    }
    m_textureBytes += d.bytes();
    m_textures.push_back(std::move(t));
  }
  const std::uint8_t white[4] = {255, 255, 255, 255};
  const std::uint8_t flat[4] = {128, 128, 255, 255};
  m_white = makeSolid(white, "texture:white");
  m_flatNormal = makeSolid(flat, "texture:flat-normal");
  for (const auto& inst : scene.instances) m_hasTransparent = m_hasTransparent || inst.transparent;
}

const SceneTrianglesGpu& SceneGpu::triangles() {
  if (!m_triangles) m_triangles = std::make_unique<SceneTrianglesGpu>(m_scene);
  return *m_triangles;
}

void SceneGpu::bindMaterial(gl::Program& p, int index) const {
  static const Material kDefault{};
  const Material& m = (index >= 0 && index < int(m_scene.materials.size())) ? m_scene.materials[index] : kDefault;
  auto bindTex = [&](GLuint unit, int tex, const gl::Texture& fallback) {
    if (tex >= 0 && tex < int(m_textures.size())) m_textures[tex].bind(unit);
    else fallback.bind(unit);
  };
  bindTex(kUnitBaseColor, m.baseColorTexture, m_white);
  bindTex(kUnitMetallicRoughness, m.metallicRoughnessTexture, m_white);
  bindTex(kUnitNormal, m.normalTexture, m_flatNormal);
  bindTex(kUnitEmissive, m.emissiveTexture, m_white);
  bindTex(kUnitOcclusion, m.occlusionTexture, m_white);
  p.set("uBaseColor", m.baseColor)
      .set("uMetallic", m.metallic)
      .set("uRoughness", m.roughness)
      .set("uEmissive", m.emissive)
      .set("uNormalScale", m.normalScale)
      .set("uOcclusionStrength", m.occlusionStrength)
      .set("uHasNormalMap", m.normalTexture >= 0)
      .set("uAlphaMask", m.alphaMode == AlphaMode::Mask)
      .set("uAlphaCutoff", m.alphaCutoff)
      .set("uDoubleSided", m.doubleSided);
}

void SceneGpu::drawInstance(gl::Program& program, const Instance& inst, bool materials) const {
  const MeshGpu& g = m_meshes[std::size_t(inst.mesh)];
  if (g.indexCount == 0) return;
  program.set("uModel", inst.transform);
  program.set("uNormalMatrix", glm::mat3(glm::transpose(glm::inverse(inst.transform))));
  if (materials) bindMaterial(program, m_scene.meshes[std::size_t(inst.mesh)].material);
  glBindVertexArray(g.vao.id());
  glDrawElements(GL_TRIANGLES, g.indexCount, GL_UNSIGNED_INT, nullptr);
}

void SceneGpu::draw(gl::Program& program, Filter filter, bool materials, const glm::vec3& eye) const {
  program.use();
  if (materials) {
    program.set("uBaseColorTex", int(kUnitBaseColor))
        .set("uMetallicRoughnessTex", int(kUnitMetallicRoughness))
        .set("uNormalTex", int(kUnitNormal))
        .set("uEmissiveTex", int(kUnitEmissive))
        .set("uOcclusionTex", int(kUnitOcclusion));
  }
  std::vector<const Instance*> order;
  for (const auto& inst : m_scene.instances) {
    if (filter == Filter::Opaque && inst.transparent) continue;
    if (filter == Filter::Transparent && !inst.transparent) continue;
    order.push_back(&inst);
  }
  if (filter == Filter::Transparent) {
    auto distance = [&](const Instance* i) {
      const glm::vec3 c = glm::vec3(i->transform * glm::vec4(m_scene.meshes[std::size_t(i->mesh)].bounds.center(), 1));
      return glm::length(c - eye);
    };
    std::stable_sort(order.begin(), order.end(), [&](auto* a, auto* b) { return distance(a) > distance(b); });
  }
  for (const Instance* inst : order) drawInstance(program, *inst, materials);
  glBindVertexArray(0);
}

} // namespace rtlab
