#include "texsynth/image/tile_deform.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "texsynth/core/gradient_noise.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/image/window_support.h"

namespace texsynth {

namespace {

void validate(const Image& exemplar, const TileDeformOptions& o) {
  if (exemplar.empty()) throw ParameterError("exemplar", "image is empty");
  requireFiniteAtLeast("cellWidth", o.cellWidth, 0.0f);
  requireFiniteAtLeast("cellHeight", o.cellHeight, 0.0f);
  requireFiniteAtLeast("lambdaX", o.lambdaX, 0.0f);
  requireFiniteAtLeast("lambdaY", o.lambdaY, 0.0f);
  requireDeformationClamp("maxDisplacement", o.maxDisplacement);
  requireFinitePositive("noiseFrequency", o.noiseFrequency);
}

// Position along one axis inside its cell: cell index and fraction in [0, 1).
struct CellCoordinate {
  std::int64_t cell;
  double fraction;
};
inline CellCoordinate cellCoordinate(double position, float cellSize) {
  double scaled = position / double(cellSize);
  double cell = std::floor(scaled);
  return {std::int64_t(cell), scaled - cell};
}

// Eq. 2 written as point + bilinear interpolation of the corner displacements (the undeformed
// corners interpolate to the point itself), so λ = 0 reproduces plain tiling exactly.
inline double warpedCoordinate(double position, double u, double v, float d00, float d10, float d01, float d11) {
  double top = (1.0 - u) * d00 + u * d10;
  double bottom = (1.0 - u) * d01 + u * d11;
  return position + ((1.0 - v) * top + v * bottom);
}

}  // namespace

TileDeformTexture::TileDeformTexture(const Image& exemplar, const TileDeformOptions& options)
    : exemplar_(exemplar), options_(options) {
  validate(exemplar, options);
  sx_ = options.cellWidth > 0 ? options.cellWidth : float(exemplar.width) / 4.0f;
  sy_ = options.cellHeight > 0 ? options.cellHeight : float(exemplar.height) / 4.0f;
  for (int k = 0; k < 4; ++k) noiseOffset_[k] = 1000.0f * uniform01(hashKey(options.seed, std::uint64_t(k), 0, 0xd3f0));
}

void TileDeformTexture::cornerDisplacement(std::int64_t i, std::int64_t j, float displacement[2]) const {
  const double f = options_.noiseFrequency;
  const float nx = float(i * f + noiseOffset_[0]), ny = float(j * f + noiseOffset_[1]);
  const float mx = float(i * f + noiseOffset_[2]), my = float(j * f + noiseOffset_[3]);
  const bool deformX = options_.directions != DeformDirections::YOnly;
  const bool deformY = options_.directions != DeformDirections::XOnly;
  const float limitX = options_.maxDisplacement * sx_, limitY = options_.maxDisplacement * sy_;
  float dx = deformX ? gradientNoise2(nx, ny, hashKey(options_.seed, 0, 0, 0xd3f1)) * options_.lambdaX * sx_ : 0.0f;
  float dy = deformY ? gradientNoise2(mx, my, hashKey(options_.seed, 1, 0, 0xd3f1)) * options_.lambdaY * sy_ : 0.0f;
  displacement[0] = std::clamp(dx, -limitX, limitX);
  displacement[1] = std::clamp(dy, -limitY, limitY);
}

void TileDeformTexture::sourcePosition(double x, double y, double source[2]) const {
  CellCoordinate cx = cellCoordinate(x, sx_), cy = cellCoordinate(y, sy_);
  float d00[2], d10[2], d01[2], d11[2];
  cornerDisplacement(cx.cell, cy.cell, d00);
  cornerDisplacement(cx.cell + 1, cy.cell, d10);
  cornerDisplacement(cx.cell, cy.cell + 1, d01);
  cornerDisplacement(cx.cell + 1, cy.cell + 1, d11);
  source[0] = warpedCoordinate(x, cx.fraction, cy.fraction, d00[0], d10[0], d01[0], d11[0]);
  source[1] = warpedCoordinate(y, cx.fraction, cy.fraction, d00[1], d10[1], d01[1], d11[1]);
}

void TileDeformTexture::sample(double x, double y, float* color) const {
  double source[2];
  sourcePosition(x, y, source);
  exemplar_.sampleBilinearWrapped(source[0], source[1], color);
}

Image TileDeformTexture::synthesizeWindow(std::int64_t x0, std::int64_t y0, int width, int height) const {
  requireWindow(x0, y0, width, height);
  Image out(width, height, exemplar_.channels);
  // Per-column and per-row cell coordinates, and the corner displacements of every cell the
  // window touches: the same values sourcePosition computes, computed once.
  std::vector<CellCoordinate> columns(width), rows(height);
  for (int x = 0; x < width; ++x) columns[x] = cellCoordinate(double(x0 + x) + 0.5, sx_);
  for (int y = 0; y < height; ++y) rows[y] = cellCoordinate(double(y0 + y) + 0.5, sy_);
  const std::int64_t firstI = columns.front().cell, firstJ = rows.front().cell;
  const std::int64_t cornerCols = columns.back().cell - firstI + 2, cornerRows = rows.back().cell - firstJ + 2;
  std::vector<float> corners(std::size_t(cornerCols * cornerRows) * 2);
  parallelFor(0, cornerRows, [&](std::int64_t r) {
    for (std::int64_t c = 0; c < cornerCols; ++c)
      cornerDisplacement(firstI + c, firstJ + r, &corners[std::size_t(r * cornerCols + c) * 2]);
  });
  auto corner = [&](std::int64_t i, std::int64_t j) {
    return &corners[std::size_t((j - firstJ) * cornerCols + (i - firstI)) * 2];
  };

  parallelForChunks(0, height, kRowChunk, [&](std::int64_t rowBegin, std::int64_t rowEnd) {
    for (std::int64_t y = rowBegin; y < rowEnd; ++y) {
      const CellCoordinate cy = rows[y];
      const double py = double(y0 + y) + 0.5;
      float* dst = out.pixel(0, int(y));
      for (int x = 0; x < width; ++x) {
        const CellCoordinate cx = columns[x];
        const float *d00 = corner(cx.cell, cy.cell), *d10 = corner(cx.cell + 1, cy.cell);
        const float *d01 = corner(cx.cell, cy.cell + 1), *d11 = corner(cx.cell + 1, cy.cell + 1);
        double sourceX =
            warpedCoordinate(double(x0 + x) + 0.5, cx.fraction, cy.fraction, d00[0], d10[0], d01[0], d11[0]);
        double sourceY = warpedCoordinate(py, cx.fraction, cy.fraction, d00[1], d10[1], d01[1], d11[1]);
        exemplar_.sampleBilinearWrapped(sourceX, sourceY, dst + std::size_t(x) * out.channels);
      }
    }
  });
  return out;
}

Image synthesizeTileDeform(const Image& exemplar, const TileDeformOptions& options, std::int64_t x0, std::int64_t y0,
                           int width, int height) {
  return TileDeformTexture(exemplar, options).synthesizeWindow(x0, y0, width, height);
}

}  // namespace texsynth
