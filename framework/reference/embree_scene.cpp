#include "reference/embree_scene.h"

#include "reference/terminator.h"
#include "reference/texture_sample.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace rtlab::reference {

struct EmbreeScene::Geometry {
  std::vector<glm::vec3> positions; // world
  std::vector<glm::vec3> normals;   // world, unit (normal matrix as in shaders/shading/surface.vert)
  std::vector<glm::vec2> uvs;
  std::vector<std::uint32_t> indices;
  const Material* material = nullptr;
  const Scene* scene = nullptr;
  bool alphaMask = false;
};

namespace {

// Embree reports errors through a callback; keep the first one to turn it into an Error.
void onDeviceError(void* user, RTCError code, const char* message) {
  auto* first = static_cast<std::string*>(user);
  if (first->empty()) first->assign("Embree error " + std::to_string(int(code)) + ": " + (message ? message : ""));
}

void checkDevice(RTCDevice device, std::string& firstError, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE || !firstError.empty()) {
    const std::string msg = firstError.empty() ? "Embree error " + std::to_string(int(e)) : firstError;
    throw Error(ExitCode::Internal, std::string(what) + ": " + msg);
  }
}

// The G-buffer's alpha test (shaders/shading/gbuffer.frag): a masked material's fragments with
// alpha below the cutoff do not exist, for camera rays and shadow rays alike.
void alphaFilter(const RTCFilterFunctionNArguments* args) {
  const auto* g = static_cast<const EmbreeScene::Geometry*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
    const std::uint32_t* tri = &g->indices[std::size_t(prim) * 3];
    const glm::vec2 uv = (1.0f - u - v) * g->uvs[tri[0]] + u * g->uvs[tri[1]] + v * g->uvs[tri[2]];
    if (surfaceInputs(*g->scene, g->material, uv).baseColor.w < g->material->alphaCutoff) args->valid[i] = 0;
  }
}

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
  const float l2 = glm::dot(v, v);
  return l2 > 0.0f && std::isfinite(l2) ? v / std::sqrt(l2) : fallback;
}

} // namespace

EmbreeScene::EmbreeScene(const Scene& scene) {
  m_device.reset(rtcNewDevice(nullptr));
  if (!m_device) throw Error(ExitCode::Internal, "Embree: could not create a device (error " +
                                                     std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  RTCDevice device = m_device.get();
  rtcSetDeviceErrorFunction(device, onDeviceError, &m_error);
  m_rtcScene.reset(rtcNewScene(device));
  RTCScene rtcScene = m_rtcScene.get();
  // Robust mode: Embree's guard against rays slipping through the shared edges of neighbouring
  // triangles (a ground truth must not leak); high-quality build for a BVH traced by millions of
  // rays.
  rtcSetSceneFlags(rtcScene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(rtcScene, RTC_BUILD_QUALITY_HIGH);
  for (const Instance& inst : scene.instances) {
    if (inst.transparent || inst.mesh < 0 || inst.mesh >= int(scene.meshes.size())) continue;
    const Mesh& mesh = scene.meshes[std::size_t(inst.mesh)];
    if (mesh.indices.size() < 3 || mesh.vertices.empty()) continue;
    auto g = std::make_unique<Geometry>();
    g->scene = &scene;
    if (mesh.material >= 0 && mesh.material < int(scene.materials.size()))
      g->material = &scene.materials[std::size_t(mesh.material)];
    g->alphaMask = g->material && g->material->alphaMode == AlphaMode::Mask;
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(inst.transform)));
    g->positions.reserve(mesh.vertices.size());
    for (const Vertex& v : mesh.vertices) {
      g->positions.push_back(glm::vec3(inst.transform * glm::vec4(v.position, 1.0f)));
      g->normals.push_back(safeNormalize(normalMatrix * v.normal, glm::vec3(0, 1, 0)));
      g->uvs.push_back(v.uv);
    }
    const std::size_t triangles = mesh.indices.size() / 3;
    g->indices.assign(mesh.indices.begin(), mesh.indices.begin() + std::ptrdiff_t(triangles * 3));
    for (std::uint32_t& i : g->indices)
      if (i >= mesh.vertices.size()) i = 0; // the loader validates indices; stay safe regardless

    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           sizeof(float) * 3, g->positions.size()));
    auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                              sizeof(unsigned) * 3, triangles));
    if (!vb || !ib) {
      rtcReleaseGeometry(geom);
      checkDevice(device, m_error, "Embree: geometry buffers");
      throw Error(ExitCode::Internal, "Embree: could not allocate geometry buffers");
    }
    for (std::size_t i = 0; i < g->positions.size(); ++i) {
      vb[i * 3] = g->positions[i].x;
      vb[i * 3 + 1] = g->positions[i].y;
      vb[i * 3 + 2] = g->positions[i].z;
    }
    std::copy(g->indices.begin(), g->indices.end(), ib);
    rtcSetGeometryUserData(geom, g.get());
    if (g->alphaMask) {
      rtcSetGeometryIntersectFilterFunction(geom, alphaFilter);
      rtcSetGeometryOccludedFilterFunction(geom, alphaFilter);
    }
    rtcCommitGeometry(geom);
    const unsigned id = rtcAttachGeometry(rtcScene, geom);
    rtcReleaseGeometry(geom);
    if (id != m_geometries.size()) throw Error(ExitCode::Internal, "Embree: unexpected geometry id");
    m_triangles += triangles;
    m_geometries.push_back(std::move(g));
  }
  rtcCommitScene(rtcScene);
  checkDevice(device, m_error, "Embree: building the scene");
}

EmbreeScene::~EmbreeScene() = default;

bool EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.dir_x = dir.x;
  ray.dir_y = dir.y;
  ray.dir_z = dir.z;
  ray.tnear = tnear;
  ray.tfar = tfar;
  ray.mask = 0xffffffffu;
  ray.flags = 0;
  rtcOccluded1(m_rtcScene.get(), &context, &ray);
  return ray.tfar < 0.0f; // set to -inf when occluded
}

unsigned EmbreeScene::occluded(const Packet& packet) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  alignas(32) RTCRay8 rays;
  alignas(32) int valid[8];
  for (int i = 0; i < 8; ++i) {
    const int k = i < packet.count ? i : 0; // inactive lanes repeat a valid ray, masked out
    valid[i] = i < packet.count ? -1 : 0;
    rays.org_x[i] = packet.origin[k].x;
    rays.org_y[i] = packet.origin[k].y;
    rays.org_z[i] = packet.origin[k].z;
    rays.dir_x[i] = packet.direction[k].x;
    rays.dir_y[i] = packet.direction[k].y;
    rays.dir_z[i] = packet.direction[k].z;
    rays.tnear[i] = packet.tnear[k];
    rays.tfar[i] = packet.tfar[k];
    rays.time[i] = 0.0f;
    rays.mask[i] = 0xffffffffu;
    rays.id[i] = unsigned(i);
    rays.flags[i] = 0;
  }
  rtcOccluded8(valid, m_rtcScene.get(), &context, &rays);
  unsigned mask = 0;
  for (int i = 0; i < packet.count; ++i)
    if (rays.tfar[i] < 0.0f) mask |= 1u << i;
  return mask;
}

bool EmbreeScene::intersect(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar,
                            RayHit& hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = origin.x;
  rh.ray.org_y = origin.y;
  rh.ray.org_z = origin.z;
  rh.ray.dir_x = dir.x;
  rh.ray.dir_y = dir.y;
  rh.ray.dir_z = dir.z;
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xffffffffu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(m_rtcScene.get(), &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || rh.hit.geomID >= m_geometries.size()) return false;

  describeHit(rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v, rh.ray.tfar, dir, hit);
  return true;
}

unsigned EmbreeScene::intersect(const Packet& packet, RayHit hits[8]) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  alignas(32) RTCRayHit8 rh;
  alignas(32) int valid[8];
  for (int i = 0; i < 8; ++i) {
    const int k = i < packet.count ? i : 0;
    valid[i] = i < packet.count ? -1 : 0;
    rh.ray.org_x[i] = packet.origin[k].x;
    rh.ray.org_y[i] = packet.origin[k].y;
    rh.ray.org_z[i] = packet.origin[k].z;
    rh.ray.dir_x[i] = packet.direction[k].x;
    rh.ray.dir_y[i] = packet.direction[k].y;
    rh.ray.dir_z[i] = packet.direction[k].z;
    rh.ray.tnear[i] = packet.tnear[k];
    rh.ray.tfar[i] = packet.tfar[k];
    rh.ray.time[i] = 0.0f;
    rh.ray.mask[i] = 0xffffffffu;
    rh.ray.id[i] = unsigned(i);
    rh.ray.flags[i] = 0;
    rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect8(valid, m_rtcScene.get(), &context, &rh);
  unsigned mask = 0;
  for (int i = 0; i < packet.count; ++i) {
    if (rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID || rh.hit.geomID[i] >= m_geometries.size()) continue;
    describeHit(rh.hit.geomID[i], rh.hit.primID[i], rh.hit.u[i], rh.hit.v[i], rh.ray.tfar[i], packet.direction[i],
                hits[i]);
    mask |= 1u << i;
  }
  return mask;
}

void EmbreeScene::describeHit(unsigned geomID, unsigned primID, float u, float v, float t, const glm::vec3& dir,
                              RayHit& hit) const {
  const Geometry& g = *m_geometries[geomID];
  const std::uint32_t* tri = &g.indices[std::size_t(primID) * 3];
  const float w = 1.0f - u - v;
  const glm::vec3 &p0 = g.positions[tri[0]], &p1 = g.positions[tri[1]], &p2 = g.positions[tri[2]];
  hit.t = t;
  hit.position = w * p0 + u * p1 + v * p2;
  // Front face as GL decides it: counter-clockwise seen from the viewer, i.e. the world-space
  // winding normal facing the ray's origin (independent of the instance matrix's handedness).
  const glm::vec3 winding = glm::cross(p1 - p0, p2 - p0);
  const bool frontFacing = glm::dot(winding, dir) < 0.0f;
  const glm::vec3 ng = safeNormalize(frontFacing ? winding : -winding, -safeNormalize(dir, glm::vec3(0, 0, 1)));
  hit.geometricNormal = ng;
  // As the G-buffer does (gbuffer.frag): flip for back faces, keep in the geometric hemisphere.
  glm::vec3 ns = safeNormalize(w * g.normals[tri[0]] + u * g.normals[tri[1]] + v * g.normals[tri[2]], ng);
  if (!frontFacing) ns = -ns;
  if (glm::dot(ns, ng) < 0.0f) ns = safeNormalize(ns - 1.01f * glm::dot(ns, ng) * ng, ng);
  hit.shadingNormal = ns;
  // The vertex normals on the side the hit is seen from, as the G-buffer does (gbuffer.frag).
  const glm::vec3 corners[3] = {p0, p1, p2};
  const float side = frontFacing ? 1.0f : -1.0f;
  const glm::vec3 normals[3] = {side * g.normals[tri[0]], side * g.normals[tri[1]], side * g.normals[tri[2]]};
  hit.shadingPoint = terminatorPoint(hit.position, glm::vec3(w, u, v), corners, normals);
  hit.uv = w * g.uvs[tri[0]] + u * g.uvs[tri[1]] + v * g.uvs[tri[2]];
  hit.material = g.material;
}

RayStart rayStart(const glm::vec3& p, const glm::vec3& n, const glm::vec3& back) {
  // 2^-13 is about 1000 float ulps of the largest coordinate: well above the rasterizer's
  // interpolation error of a G-buffer position, well below any feature the techniques resolve.
  // Near the world origin a floor of 2^-5 scene units keeps it from vanishing.
  constexpr float kRelative = 1.0f / 8192.0f, kFloor = 1.0f / 32.0f;
  const float eps = kRelative * std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), kFloor});
  return {p + eps * (n + back), 0.0f};
}

} // namespace rtlab::reference
