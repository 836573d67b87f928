// The LTC tables of the GGX specular lobe (Heitz, Dupuy, Hill & Neubelt 2016, "Real-Time
// Polygonal-Light Shading with Linearly Transformed Cosines"), as tools/ltc_fit writes them and the
// arealight techniques read them: assets/ltc/ggx.json. The format, cell by cell, is in
// assets/ltc/README.md; in short, one JSON object whose arrays are flat and row-major with the view
// index j outer and the roughness index i inner (cell k = j*N + i):
//   cell (i, j): perceptual roughness r = i/(N-1), sqrt(1 - cos(theta_v)) = j/(N-1) (the last row,
//   cos(theta_v) = 0, is fit at brdf.glsl's n.v clamp 1e-4);
//   "m_inv" (a, b, c, d) per cell: M^-1 = [[a, 0, b], [0, 1, 0], [c, 0, d]] in the frame where the
//   view vector lies in the xz-plane (x toward its tangential part, z the normal);
//   "magnitude": the integral of D V cos; "fresnel": of D V cos (1 - v.h)^5;
//   "diffuse_fresnel" (one per row j): (1/pi) times the integral of cos (1 - v.h)^5;
//   "sphere": the horizon-clipped form factor of a spherical cap divided by its unclipped length
//   |F|, cell (u index inner) u = z*0.5 + 0.5 (z the elevation cosine of F), v = |F|;
//   "error": the fit's L1 error per cell.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rtlab {

struct LtcTable {
  static constexpr int kSchema = 1;
  static constexpr const char* kBrdf = "ggx-height-correlated-smith";

  int size = 0;              // N: the table is N x N
  std::uint64_t seed = 0;    // the fit's seed
  int samples = 0;           // the per-cell sample count of the fit
  double fitSeconds = 0.0;   // wall time of the fit (informative)
  int threads = 0;           // worker threads of the fit (informative: the table does not depend on it)
  std::vector<float> mInv;           // 4 N^2: (a, b, c, d) per cell
  std::vector<float> magnitude;      // N^2
  std::vector<float> fresnel;        // N^2
  std::vector<float> diffuseFresnel; // N
  std::vector<float> sphere;         // N^2
  std::vector<float> error;          // N^2

  // An empty table of size n (every array sized, zero-filled).
  static LtcTable withSize(int n);

  // Reads and validates a table. Error(Input) with one line naming the path when the file is
  // missing, unreadable, not JSON, or does not hold exactly the format above (schema, brdf, size >= 2,
  // every array present with its length, every value finite).
  static LtcTable load(const std::string& path);
  // Writes the table atomically (a temporary beside path, renamed into place): Error(Output) when
  // it cannot be written, Error(Internal) when the table itself is inconsistent (array lengths).
  // Values are written as the shortest decimals that read back as the same floats.
  void save(const std::string& path) const;

  // The grid's coordinates (cell centres of the lookup texture).
  static double roughnessAt(int i, int n) { return double(i) / double(n - 1); }
  // cos(theta_v) of row j: 1 - (j/(N-1))^2, the last row at 1e-4 (brdf.glsl's n.v clamp).
  static double cosThetaAt(int j, int n);
  // The sphere table's grid: z = 2u - 1 and |F| of cell (u index, v index).
  static double sphereZAt(int iu, int n) { return 2.0 * double(iu) / double(n - 1) - 1.0; }
  static double sphereLengthAt(int iv, int n) { return double(iv) / double(n - 1); }

  int cell(int i, int j) const { return j * size + i; }
  std::array<float, 4> mInvAt(int i, int j) const;
  float magnitudeAt(int i, int j) const { return magnitude[std::size_t(cell(i, j))]; }
  float fresnelAt(int i, int j) const { return fresnel[std::size_t(cell(i, j))]; }
  float errorAt(int i, int j) const { return error[std::size_t(cell(i, j))]; }
  float sphereAt(int iu, int iv) const { return sphere[std::size_t(cell(iu, iv))]; }
};

} // namespace rtlab
