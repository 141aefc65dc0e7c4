#pragma once
// Tile-deform (Chen, Johan & Mueller-Wittig, "Simple and efficient example-based texture
// synthesis using tiling and deformation"): the exemplar is tiled, a grid of cells (sx, sy) is
// laid over it, every cell corner is displaced by Perlin noise (eq. 1), and each output point
// is mapped by bilinear interpolation inside its deformed cell (eq. 2, inverse warping) to a
// point of the tiled exemplar, sampled bilinearly with wrap-around.
//
// The texture is infinite and random-access: a corner's displacement depends only on its grid
// index and the seed, so any window is bit-identical to the same region of a larger output.
// Pixel (x, y) is the point at its center (x + 0.5, y + 0.5).
#include <cstdint>

#include "texsynth/core/image.h"

namespace texsynth {

// Which displacement components are applied (paper §5: deform only selected directions to
// avoid stretching straight features).
enum class DeformDirections { Both, XOnly, YOnly };

struct TileDeformOptions {
  // Grid cell size (sx, sy) in pixels; 0 picks a quarter of the exemplar's width / height,
  // about the scale of the features in typical GIMP patterns.
  float cellWidth = 0, cellHeight = 0;
  // Noise factors λx, λy of eq. 1: displacement = noise * λ * cell size (noise in [-1, 1]).
  float lambdaX = 0.35f, lambdaY = 0.35f;
  // Clamp threshold: |displacement| <= maxDisplacement * cell size per axis, in [0, 0.5). 0.45 keeps
  // neighbouring corners from crossing, so cells never fold.
  float maxDisplacement = 0.45f;
  // Noise frequency in noise-lattice periods per grid cell (> 0): low values deform smoothly
  // over many cells, high values make each corner nearly independent.
  float noiseFrequency = 0.6f;
  DeformDirections directions = DeformDirections::Both;
  std::uint64_t seed = 1;
};

// A ready-to-sample tile-deform texture (options validated, automatic sizes resolved).
// Holds a reference to the exemplar, which must outlive it.
class TileDeformTexture {
 public:
  // Throws ParameterError naming the option (cellWidth, lambdaX, maxDisplacement, ...) or
  // "exemplar" (empty).
  TileDeformTexture(const Image& exemplar, const TileDeformOptions& options);

  float cellWidth() const { return sx_; }
  float cellHeight() const { return sy_; }
  const Image& exemplar() const { return exemplar_; }

  // Displacement (eq. 1, clamped, direction-limited) of grid corner (i, j), in pixels.
  void cornerDisplacement(std::int64_t i, std::int64_t j, float displacement[2]) const;
  // Position in the tiled exemplar that output point (x, y) maps to (eq. 2).
  void sourcePosition(double x, double y, double source[2]) const;
  // Color at output point (x, y) (exemplar channels): random access to single points.
  void sample(double x, double y, float* color) const;

  // The width x height window whose top-left pixel is (x0, y0).
  Image synthesizeWindow(std::int64_t x0, std::int64_t y0, int width, int height) const;

 private:
  const Image& exemplar_;
  TileDeformOptions options_;
  float sx_, sy_;
  float noiseOffset_[4];  // per-seed shift of the noise domain (noise is 0 on its lattice)
};

// One-off: the window (x0, y0, width, height) of the infinite tile-deform texture.
Image synthesizeTileDeform(const Image& exemplar, const TileDeformOptions& options, std::int64_t x0, std::int64_t y0,
                           int width, int height);

}  // namespace texsynth
