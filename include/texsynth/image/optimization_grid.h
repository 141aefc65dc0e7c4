#pragma once
// One level's toroidal output grid and its sparse set of active neighborhoods X (centres
// `stride` apart), as a domain of the discrete steps (texsynth/image/discrete_steps.h): texture
// optimization's levels, the least-squares solver and flow animation's frames read it. Output
// sample y * width + x is pixel (x, y).
#include <cstdint>

#include "texsynth/core/wrap.h"
#include "texsynth/image/discrete_steps.h"
#include "texsynth/image/exemplar_window.h"

namespace texsynth::detail {

struct OptimizationGrid {
  ExemplarWindow window;
  int width = 0, height = 0;  // output at this level; multiples of stride
  int radius = 0, stride = 1;
  int offsetX = 0, offsetY = 0;  // of the centres' lattice, in [0, stride): animation moves it frame to frame

  // Centres `stride` apart (0: activeStride(N), Kwatra's N/4); width and height must be multiples of it.
  OptimizationGrid(const ExemplarAnalysis& analysis, int level, int width, int height, int neighborhoodSize,
                   PixelNorm norm = PixelNorm::Squared, int stride = 0)
      : window(analysis, level, neighborhoodSize, norm),
        width(width),
        height(height),
        radius(neighborhoodSize / 2),
        stride(stride > 0 ? stride : activeStride(neighborhoodSize)) {}

  int size() const { return window.size; }
  int activeWidth() const { return width / stride; }
  int activeHeight() const { return height / stride; }
  std::int64_t activeCount() const { return std::int64_t(activeWidth()) * activeHeight(); }
  std::int64_t sampleCount() const { return std::int64_t(width) * height; }
  std::int64_t activeChunk() const { return 2 * std::int64_t(activeWidth()); }  // two rows of centres
  std::int64_t sampleChunk() const { return 8 * std::int64_t(width); }          // eight rows of pixels
  std::int64_t sample(int x, int y) const { return std::int64_t(y) * width + x; }
  bool masksCells() const { return false; }  // a torus has every neighborhood whole

  // The output neighborhood of active neighborhood a (wrapping) into out[window.dimension()];
  // colorOf(sample) gives a pixel's colors.
  template <class ColorOf>
  void gather(std::int64_t a, ColorOf&& colorOf, float* out) const {
    const int c = window.channels();
    const int x = int(a % activeWidth()) * stride + offsetX, y = int(a / activeWidth()) * stride + offsetY;
    for (int dy = -radius; dy <= radius; ++dy) {
      const std::int64_t row = std::int64_t(wrap(y + dy, height)) * width;
      for (int dx = -radius; dx <= radius; ++dx) {
        const float* color = colorOf(row + wrap(x + dx, width));
        for (int i = 0; i < c; ++i) *out++ = color[i];
      }
    }
  }

  // visit(sample, dx, dy) for every pixel of active neighborhood a, row by row.
  template <class Visit>
  void forEachMember(std::int64_t a, Visit&& visit) const {
    const int x = int(a % activeWidth()) * stride + offsetX, y = int(a / activeWidth()) * stride + offsetY;
    for (int dy = -radius; dy <= radius; ++dy) {
      const std::int64_t row = std::int64_t(wrap(y + dy, height)) * width;
      for (int dx = -radius; dx <= radius; ++dx) visit(row + wrap(x + dx, width), dx, dy);
    }
  }

  // visit(a, dx, dy) for every active neighborhood covering pixel `sample` = (x, y), where
  // (dx, dy) = (x, y) - centre in [-radius, radius]^2 (unwrapped).
  template <class Visit>
  void forEachCovering(std::int64_t sample, Visit&& visit) const {
    const int x = int(sample % width) - offsetX, y = int(sample / width) - offsetY;
    const int aw = activeWidth(), ah = activeHeight();
    for (int cy = floorDivide(y - radius + stride - 1, stride); cy * stride <= y + radius; ++cy) {
      const int rowIndex = wrapIndex(cy, ah);
      for (int cx = floorDivide(x - radius + stride - 1, stride); cx * stride <= x + radius; ++cx)
        visit(std::int64_t(rowIndex) * aw + wrapIndex(cx, aw), x - cx * stride, y - cy * stride);
    }
  }

  // Moves the centres' lattice to the offset in [0, stride)^2 hashed from `key` and carries each
  // match along (a neighborhood moved by (dx, dy) keeps the exemplar neighborhood moved by the
  // same), so that the patch borders the E-step's votes leave do not line up iteration after
  // iteration into straight seams.
  void moveLattice(std::uint64_t key, Matches& matches) {
    const int x = int(uniformBelow(key, std::uint32_t(stride))),
              y = int(uniformBelow(mix64(key), std::uint32_t(stride)));
    const int dx = x - offsetX, dy = y - offsetY;
    if (dx == 0 && dy == 0) return;
    for (std::int32_t& match : matches.pixel)
      if (match >= 0) match = window.allowedCentre(window.shifted(match, dx, dy));
    offsetX = x, offsetY = y;
  }

  static int floorDivide(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
  // A centre plus an offset of at most the radius (plus the lattice offset) around a side:
  // one compare where the side is wider than that, a division otherwise (tiny outputs).
  int wrap(int v, int n) const { return radius + stride < n ? wrapOnce(v, n) : wrapIndex(v, n); }
};

}  // namespace texsynth::detail
