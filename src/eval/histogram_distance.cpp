#include "texsynth/eval/histogram_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "texsynth/core/error.h"

namespace texsynth {

double wasserstein1(std::vector<float> a, std::vector<float> b) {
  if (a.empty() || b.empty()) throw ParameterError("wasserstein1", "needs two non-empty samples");
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  // Sweep the merged sorted values; between consecutive values both CDFs are constant.
  const double n = double(a.size()), m = double(b.size());
  const double infinity = std::numeric_limits<double>::infinity();
  std::size_t i = 0, j = 0;
  double at = std::min(a[0], b[0]), total = 0;
  while (i < a.size() || j < b.size()) {
    const double next = std::min(i < a.size() ? double(a[i]) : infinity, j < b.size() ? double(b[j]) : infinity);
    total += std::abs(double(i) / n - double(j) / m) * (next - at);
    at = next;
    while (i < a.size() && double(a[i]) == next) ++i;
    while (j < b.size() && double(b[j]) == next) ++j;
  }
  return total;
}

double histogramDistance(const Image& a, const Image& b) {
  if (a.empty() || b.empty()) throw ParameterError("histogramDistance", "needs two non-empty images");
  if (a.channels != b.channels)
    throw ParameterError("histogramDistance",
                         "channel counts differ: " + std::to_string(a.channels) + " and " + std::to_string(b.channels));
  auto channel = [](const Image& image, int c) {
    std::vector<float> values(image.pixelCount());
    for (std::size_t p = 0; p < values.size(); ++p) values[p] = image.pixels[p * image.channels + c];
    return values;
  };
  double sum = 0;
  for (int c = 0; c < a.channels; ++c) sum += wasserstein1(channel(a, c), channel(b, c));
  return sum / a.channels;
}

}  // namespace texsynth
