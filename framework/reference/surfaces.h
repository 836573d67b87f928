// The camera-visible surface points of one frame, read back from the G-buffer, so that the
// reference starts from exactly the points the GPU shaded (docs/measuring.md "Where the rays start"):
// primary visibility is identical and only the approximation differs.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace rtlab {

struct SurfaceData {
  int width = 0, height = 0; // rows top to bottom, like Image
  std::vector<glm::vec3> position;        // world
  std::vector<glm::vec3> geometricNormal; // world, unit, facing the camera
  std::vector<glm::vec3> shadingNormal;   // world, unit, in the geometric normal's hemisphere
  // The shadow terminator rule (docs/measuring.md, "The shading point"): where the reference's rays
  // start (the point lifted onto the smooth surface the vertex normals describe) and the normal
  // whose tangent plane is the horizon there (the interpolated vertex normal, in the geometric
  // normal's hemisphere). Both empty, or one per pixel; empty: the position and the geometric
  // normal (a flat surface).
  std::vector<glm::vec3> shadingPoint;
  std::vector<glm::vec3> smoothNormal;
  // The material the G-buffer holds at each pixel (textures applied): base colour, metallic and
  // perceptual roughness as the lighting pass reads them (gbuffer.albedo, gbuffer.material), so a
  // reference that shades (arealight) uses the GPU's own material values. Empty, or one per pixel.
  std::vector<glm::vec3> baseColor;
  std::vector<float> metallic;
  std::vector<float> roughness;
  std::vector<std::uint8_t> valid;        // 1 on surface pixels, 0 on background
  std::size_t pixelCount() const { return std::size_t(width) * height; }
};

} // namespace rtlab
