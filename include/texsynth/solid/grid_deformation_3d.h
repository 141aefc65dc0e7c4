#pragma once
// The 3D grid deformation of tile-deform solids (Chen et al., §4, the 3D form of eqs. 1-2):
// a regular grid of cells of size s over exemplar space; every cell corner c is displaced by
// clamp(n(c) * λ) * s, with n a 3D Perlin noise per component; a point inside a cell maps to
// the trilinear interpolation of its cell's displaced corners (inverse warping).
#include <climits>
#include <cstdint>

#include "texsynth/core/math.h"

namespace texsynth {

struct GridDeformationOptions {
  // Cell size (s_x, s_y, s_z) in exemplar pixels; each finite and > 0. Set it near the size
  // of the exemplar's features (paper §3.1).
  Vec3f cellSize{32.0f, 32.0f, 32.0f};
  // Noise factors (λ_x, λ_y, λ_z): displacement per axis as a fraction of the cell size
  // times the noise; each finite and >= 0. 0 disables deformation along that axis (§5).
  Vec3f lambda{0.4f, 0.4f, 0.4f};
  // Threshold on |displacement| as a fraction of the cell size, in [0, 0.5): below one half,
  // neighbouring corners can never cross, so cells never fold.
  float clamp = 0.45f;
  // Grid cells per noise lattice spacing (> 0, finite): larger values give smoother, larger
  // scale deformation. Non-integer by default so noise zeros (at its lattice) avoid corners.
  float noiseScale = 2.5f;
  std::uint64_t seed = 1;
};

// Throws ParameterError("deformation.cellSize" | ".lambda" | ".clamp" | ".noiseScale", ...).
void validateGridDeformation(const GridDeformationOptions& options);

class GridDeformation3d {
 public:
  explicit GridDeformation3d(const GridDeformationOptions& options);  // validates

  // The 8 corner displacements of the last cell visited: neighbouring points (mesh vertices,
  // slice rows) mostly share cells, and noise dominates the cost. One per thread/batch.
  struct CellCache {
    std::int64_t cell[3] = {INT64_MIN, 0, 0};
    Vec3f corner[8];
  };

  // The point of the tiled exemplar that exemplar-space point p maps to. With λ = 0 it is
  // exactly p. The cache only saves work; the result never depends on it.
  Vec3f map(const Vec3f& p, CellCache& cache) const;
  // Displacement of grid corner (i, j, k), in exemplar pixels.
  Vec3f cornerDisplacement(std::int64_t i, std::int64_t j, std::int64_t k) const;

 private:
  GridDeformationOptions options_;
  Vec3f maxDisplacement_;     // clamp * cellSize
  Vec3f componentOffset_[3];  // decorrelate the three noise components
  std::uint64_t componentSeed_[3];
};

}  // namespace texsynth
