#include "texsynth/exemplar/neighborhood.h"

#include "texsynth/core/error.h"
#include "texsynth/core/wrap.h"

namespace texsynth {
namespace {

// Toroidal sample positions center + h*d for d in [-r, r], into positions[size].
void windowPositions(int center, int extent, const NeighborhoodShape& shape, int* positions) {
  int step = shape.spacing % extent;
  int p = wrapIndex(center - (long long)shape.radius() * shape.spacing, extent);
  for (int i = 0; i < shape.size; ++i) {
    positions[i] = p;
    p += step;
    if (p >= extent) p -= extent;
  }
}

void gatherWithColumns(const Image& image, int y, const int* columns, const NeighborhoodShape& shape, float* out) {
  const int channels = image.channels;
  int rows[kMaxNeighborhoodSize];
  windowPositions(y, image.height, shape, rows);
  for (int j = 0; j < shape.size; ++j) {
    const float* row = image.pixel(0, rows[j]);
    for (int i = 0; i < shape.size; ++i) {
      const float* src = row + std::size_t(columns[i]) * channels;
      for (int c = 0; c < channels; ++c) *out++ = src[c];
    }
  }
}

void checkShape(const Image& image, const NeighborhoodShape& shape) {
  TS_CHECK(shape.size >= 1 && shape.size <= kMaxNeighborhoodSize && shape.size % 2 == 1);
  TS_CHECK(shape.spacing >= 1 && shape.channels == image.channels && !image.empty());
}

}  // namespace

void gatherNeighborhood(const Image& image, int x, int y, const NeighborhoodShape& shape, float* out) {
  checkShape(image, shape);
  int columns[kMaxNeighborhoodSize];
  windowPositions(x, image.width, shape, columns);
  gatherWithColumns(image, y, columns, shape, out);
}

void gatherNeighborhoods(const Image& image, std::int64_t first, std::int64_t count, const NeighborhoodShape& shape,
                         float* out) {
  checkShape(image, shape);
  const int width = image.width;
  const std::size_t dimension = shape.dimension();
  int columns[kMaxNeighborhoodSize];
  for (std::int64_t k = 0; k < count; ++k) {
    std::int64_t pixel = first + k;
    int x = int(pixel % width), y = int(pixel / width);
    // Consecutive pixels of one row shift every column by one: update instead of recomputing.
    if (k == 0 || x == 0) {
      windowPositions(x, width, shape, columns);
    } else {
      for (int i = 0; i < shape.size; ++i)
        if (++columns[i] == width) columns[i] = 0;
    }
    gatherWithColumns(image, y, columns, shape, out + k * dimension);
  }
}

}  // namespace texsynth
