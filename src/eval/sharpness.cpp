#include "texsynth/eval/sharpness.h"

#include <cmath>
#include <vector>

#include "texsynth/core/parallel.h"

namespace texsynth {

double meanGradientMagnitude(const Image& image) {
  if (image.width < 2 || image.height < 2) return 0.0;
  const int rows = image.height - 1, columns = image.width - 1, channels = image.channels;
  std::vector<double> rowSums(static_cast<std::size_t>(rows), 0.0);
  parallelForChunks(0, rows, 16, [&](std::int64_t begin, std::int64_t end) {
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < columns; ++x) {
        const float *here = image.pixel(x, y), *right = image.pixel(x + 1, y), *below = image.pixel(x, y + 1);
        double squares = 0;
        for (int c = 0; c < channels; ++c) {
          const double dx = right[c] - here[c], dy = below[c] - here[c];
          squares += dx * dx + dy * dy;
        }
        rowSums[y] += std::sqrt(squares);
      }
  });
  double total = 0;  // in row order: independent of the thread count
  for (double s : rowSums) total += s;
  return total / (double(rows) * columns);
}

}  // namespace texsynth
