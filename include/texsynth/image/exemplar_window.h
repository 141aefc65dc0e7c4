#pragma once
// The exemplar side of texture optimization at one stack level and neighborhood size: which
// exemplar neighborhoods may match, how an exemplar pixel moves by an output offset, and the
// distance between an output neighborhood and an exemplar one. Shared by every output domain
// (image grids and mesh vertices): an output offset d (in output pixels) reads the stack level
// h d exemplar pixels away, so output neighborhoods compare with exemplar neighborhoods
// gathered h apart.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "texsynth/core/wrap.h"
#include "texsynth/exemplar/analysis.h"

namespace texsynth::detail {

// How one pixel's color difference counts in |x_p - z_p|: squared (Kwatra's L2 energy), or
// its Euclidean length (a robust, L1-over-pixels energy: the discrete E-step then picks the
// candidate the most votes agree on, where L2 picks the one nearest their mean and washes
// structure out into flat, mean-colored regions).
enum class PixelNorm { Squared, Euclidean };

struct ExemplarWindow {
  const ExemplarLevel* exemplar = nullptr;  // the stack level
  int exemplarWidth = 0, exemplarHeight = 0;
  int size = 0, radius = 0;
  PixelNorm norm = PixelNorm::Squared;

  ExemplarWindow(const ExemplarAnalysis& analysis, int level, int neighborhoodSize, PixelNorm norm = PixelNorm::Squared)
      : exemplar(&analysis.levels[level]),
        exemplarWidth(analysis.width),
        exemplarHeight(analysis.height),
        size(neighborhoodSize),
        radius(neighborhoodSize / 2),
        norm(norm) {
    const int reach = radius * spacing();
    bounded = exemplarWidth > 2 * reach && exemplarHeight > 2 * reach;
    if (bounded) minX = minY = reach, maxX = exemplarWidth - 1 - reach, maxY = exemplarHeight - 1 - reach;
    // Offsets up to a neighborhood's reach (plus a pixel of rounding) wrap by one conditional step.
    wrapsOnce = (radius + 1) * spacing() < std::min(exemplarWidth, exemplarHeight);
    fastRows = std::int64_t(exemplarWidth) * exemplarHeight < FixedDivisor::kLimit;
    rowOf = FixedDivisor(exemplarWidth);
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

  int spacing() const { return exemplar->spacing; }
  int channels() const { return exemplar->image.channels; }
  int dimension() const { return size * size * channels(); }
  std::int32_t pixelCount() const { return std::int32_t(exemplarWidth) * exemplarHeight; }

  // Exemplar pixel `pixel` moved by an output offset (dx, dy): h d exemplar pixels, wrapped.
  // Integer offsets (image grids) move exactly; fractional ones (mesh vertices at their
  // flattened positions) move to the nearest exemplar pixel.
  std::int32_t shifted(std::int32_t pixel, int dx, int dy) const {
    return moved(pixel, dx * spacing(), dy * spacing());
  }
  std::int32_t shifted(std::int32_t pixel, float dx, float dy) const {
    const float h = float(spacing());
    return moved(pixel, int(std::lround(dx * h)), int(std::lround(dy * h)));
  }
  const float* exemplarColor(std::int32_t pixel) const {
    return exemplar->image.pixels.data() + std::size_t(pixel) * channels();
  }

  // |query - exemplar neighborhood at `pixel`| under `norm`, abandoned (returning a value >=
  // bound) once a row pushes it past `bound`. `columns` is scratch of `size` ints. The query's
  // layout is gatherNeighborhood's: rows dy = -r..r, in each dx = -r..r, channels innermost.
  // With a `mask` (one byte per cell, 0 = left out), only the cells it keeps count, and the sum
  // is multiplied by `scale` (cells / kept cells, so that partial neighborhoods compare with
  // whole ones).
  float distance(const float* query, std::int32_t pixel, float bound, int* columns, const std::uint8_t* mask = nullptr,
                 float scale = 1.0f) const {
    return mask ? distanceOver<true>(query, pixel, bound, columns, mask, scale)
                : distanceOver<false>(query, pixel, bound, columns, nullptr, 1.0f);
  }

 private:
  bool wrapsOnce = false;
  template <bool kMasked>
  float distanceOver(const float* query, std::int32_t pixel, float bound, int* columns, const std::uint8_t* mask,
                     float scale) const {
    const int h = spacing(), c = channels();
    const int ux = pixel % exemplarWidth, uy = pixel / exemplarWidth;
    for (int i = 0; i < size; ++i) columns[i] = wrapIndex(ux + (i - radius) * h, exemplarWidth) * c;
    const float* image = exemplar->image.pixels.data();
    float sum = 0;
    for (int dy = -radius; dy <= radius; ++dy) {
      const float* row = image + std::size_t(wrapIndex(uy + dy * h, exemplarHeight)) * exemplarWidth * c;
      for (int i = 0; i < size; ++i, query += c) {
        if constexpr (kMasked)
          if (!*mask++) continue;
        const float* color = row + columns[i];
        float pixelSum = 0;
        for (int k = 0; k < c; ++k) {
          const float d = query[k] - color[k];
          pixelSum += d * d;
        }
        sum += norm == PixelNorm::Squared ? pixelSum : std::sqrt(pixelSum);
      }
      if (sum * scale >= bound) return sum * scale;
    }
    return sum * scale;
  }

  // v mod n, by one conditional step where offsets stay within one exemplar side.
  int wrap(int v, int n) const { return wrapsOnce ? wrapOnce(v, n) : wrapIndex(v, n); }
  std::int32_t moved(std::int32_t pixel, int ox, int oy) const {
    const int row = fastRows ? rowOf.divide(pixel) : pixel / exemplarWidth;
    const int x = wrap(pixel - row * exemplarWidth + ox, exemplarWidth);
    const int y = wrap(row + oy, exemplarHeight);
    return std::int32_t(y) * exemplarWidth + x;
  }
  bool fastRows = false;  // pixel indices below FixedDivisor's limit
  FixedDivisor rowOf;
};

}  // namespace texsynth::detail
