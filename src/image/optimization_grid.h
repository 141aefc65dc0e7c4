#pragma once
// Internal to texture optimization: one level's toroidal output grid, its sparse set of
// active neighborhoods X (centres `stride` apart), and the neighborhood arithmetic both
// solvers share. Output pixel (x, y) and offset d read the exemplar stack level at spacing h,
// so an output neighborhood compares with exemplar neighborhoods gathered h apart.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "texsynth/core/wrap.h"
#include "texsynth/exemplar/analysis.h"

namespace texsynth::detail {

// How one pixel's color difference counts in |x_p - z_p|: squared (Kwatra's L2 energy), or
// its Euclidean length (a robust, L1-over-pixels energy: the discrete E-step then picks the
// candidate the most votes agree on, where L2 picks the one nearest their mean and washes
// structure out into flat, mean-colored regions).
enum class PixelNorm { Squared, Euclidean };

struct OptimizationGrid {
  const ExemplarLevel* exemplar = nullptr;  // the stack level
  int exemplarWidth = 0, exemplarHeight = 0;
  int width = 0, height = 0;  // output at this level; multiples of stride
  int size = 0, radius = 0, stride = 1;
  PixelNorm norm = PixelNorm::Squared;

  OptimizationGrid(const ExemplarAnalysis& analysis, int level, int width, int height, int neighborhoodSize,
                   PixelNorm norm = PixelNorm::Squared)
      : exemplar(&analysis.levels[level]),
        exemplarWidth(analysis.width),
        exemplarHeight(analysis.height),
        width(width),
        height(height),
        size(neighborhoodSize),
        radius(neighborhoodSize / 2),
        stride(activeStride(neighborhoodSize)),
        norm(norm) {
    const int reach = radius * spacing();
    bounded = exemplarWidth > 2 * reach && exemplarHeight > 2 * reach;
    if (bounded) minX = minY = reach, maxX = exemplarWidth - 1 - reach, maxY = exemplarHeight - 1 - reach;
  }

  // Matches are exemplar neighborhoods that do not cross the exemplar's wrap-around seam,
  // where the exemplar is big enough for the level's N and spacing. Otherwise a copy of the
  // toroidal exemplar would be a zero-energy optimum, and the optimization drifts towards
  // tiling it (seen at 4+ levels on pink_marble: periodicity 0.98).
  bool bounded = false;
  int minX = 0, maxX = 0, minY = 0, maxY = 0;
  // The nearest allowed match centre.
  std::int32_t allowedCentre(std::int32_t pixel) const {
    if (!bounded) return pixel;
    const int x = std::clamp(pixel % exemplarWidth, minX, maxX), y = std::clamp(pixel / exemplarWidth, minY, maxY);
    return std::int32_t(y) * exemplarWidth + x;
  }
  bool isAllowedCentre(std::int32_t pixel) const { return allowedCentre(pixel) == pixel; }

  // Kwatra et al.: neighborhoods of width w overlap by 3/4, centres w/4 apart.
  static int activeStride(int neighborhoodSize) { return neighborhoodSize / 4 > 1 ? neighborhoodSize / 4 : 1; }

  int spacing() const { return exemplar->spacing; }
  int channels() const { return exemplar->image.channels; }
  int dimension() const { return size * size * channels(); }
  int activeWidth() const { return width / stride; }
  int activeHeight() const { return height / stride; }
  std::int64_t activeCount() const { return std::int64_t(activeWidth()) * activeHeight(); }
  std::int64_t pixelCount() const { return std::int64_t(width) * height; }

  // Exemplar pixel `pixel` moved by offset d output pixels (h_l d exemplar pixels), wrapped.
  std::int32_t shifted(std::int32_t pixel, int dx, int dy) const {
    const int x = wrapIndex(pixel % exemplarWidth + dx * spacing(), exemplarWidth);
    const int y = wrapIndex(pixel / exemplarWidth + dy * spacing(), exemplarHeight);
    return std::int32_t(y) * exemplarWidth + x;
  }
  const float* exemplarColor(std::int32_t pixel) const {
    return exemplar->image.pixels.data() + std::size_t(pixel) * channels();
  }

  // The output neighborhood around (x, y) (wrapping) into out[dimension()], in the layout of
  // gatherNeighborhood; colorAt(x, y) gives a wrapped output pixel's colors.
  template <class ColorAt>
  void gatherOutput(int x, int y, ColorAt&& colorAt, float* out) const {
    const int c = channels();
    for (int dy = -radius; dy <= radius; ++dy) {
      const int row = wrapIndex(y + dy, height);
      for (int dx = -radius; dx <= radius; ++dx) {
        const float* color = colorAt(wrapIndex(x + dx, width), row);
        for (int i = 0; i < c; ++i) *out++ = color[i];
      }
    }
  }

  // |query - exemplar neighborhood at `pixel`| under `norm`, abandoned (returning a value >=
  // bound) once a row pushes it past `bound`. `columns` is scratch of `size` ints.
  float distance(const float* query, std::int32_t pixel, float bound, int* columns) const {
    const int h = spacing(), c = channels();
    const int ux = pixel % exemplarWidth, uy = pixel / exemplarWidth;
    for (int i = 0; i < size; ++i) columns[i] = wrapIndex(ux + (i - radius) * h, exemplarWidth) * c;
    const float* image = exemplar->image.pixels.data();
    float sum = 0;
    for (int dy = -radius; dy <= radius; ++dy) {
      const float* row = image + std::size_t(wrapIndex(uy + dy * h, exemplarHeight)) * exemplarWidth * c;
      for (int i = 0; i < size; ++i) {
        const float* color = row + columns[i];
        float pixel = 0;
        for (int k = 0; k < c; ++k) {
          const float d = *query++ - color[k];
          pixel += d * d;
        }
        sum += norm == PixelNorm::Squared ? pixel : std::sqrt(pixel);
      }
      if (sum >= bound) return sum;
    }
    return sum;
  }

  // Calls visit(activeIndex, dx, dy) for every active neighborhood covering output pixel
  // (x, y), where (dx, dy) = (x, y) - centre in [-radius, radius]^2 (unwrapped).
  template <class Visit>
  void forEachCovering(int x, int y, Visit&& visit) const {
    const int aw = activeWidth(), ah = activeHeight();
    for (int cy = floorDivide(y - radius + stride - 1, stride); cy * stride <= y + radius; ++cy) {
      const int rowIndex = wrapIndex(cy, ah);
      for (int cx = floorDivide(x - radius + stride - 1, stride); cx * stride <= x + radius; ++cx)
        visit(std::int64_t(rowIndex) * aw + wrapIndex(cx, aw), x - cx * stride, y - cy * stride);
    }
  }

  static int floorDivide(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
};

// The matches z_p of the active neighborhoods and their squared distances |x_p - z_p|^2.
struct Matches {
  std::vector<std::int32_t> pixel;  // exemplar pixel whose neighborhood matches; -1 = none yet
  std::vector<float> distance;
  explicit Matches(std::int64_t count = 0) : pixel(std::size_t(count), -1), distance(std::size_t(count), 0.0f) {}
};

// Sum of the distances in index order (independent of the thread count), over |X| N^2.
inline double normalizedEnergy(const OptimizationGrid& grid, const Matches& matches) {
  double sum = 0;
  for (float d : matches.distance) sum += d;
  return sum / (double(grid.activeCount()) * grid.size * grid.size);
}

}  // namespace texsynth::detail
