// Distinctive colors of an image (distinctive_colors.h).
#include "texsynth/exemplar/distinctive_colors.h"

#include <algorithm>
#include <cstddef>
#include <string>

#include "texsynth/core/error.h"

namespace texsynth {

DistinctiveColors::DistinctiveColors(const Image& image, int channels, int percent)
    : median_(static_cast<std::size_t>(std::max(channels, 0))), channels_(channels) {
  if (image.empty()) throw ParameterError("distinctive colors", "need a non-empty image");
  if (channels < 1 || channels > image.channels)
    throw ParameterError("distinctive colors",
                         "channels " + std::to_string(channels) + " outside 1.." + std::to_string(image.channels));
  if (percent < 0 || percent > 100)
    throw ParameterError("distinctive colors", "percent " + std::to_string(percent) + " outside 0..100");
  const std::size_t count = image.pixelCount(), stride = std::size_t(image.channels);
  std::vector<float> values(count);
  for (int c = 0; c < channels; ++c) {
    for (std::size_t p = 0; p < count; ++p) values[p] = image.pixels[p * stride + std::size_t(c)];
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(count / 2), values.end());
    median_[std::size_t(c)] = values[count / 2];
  }
  for (std::size_t p = 0; p < count; ++p) values[p] = squaredDistanceFromMedian(image.pixels.data() + p * stride);
  const std::size_t at = std::min(count - 1, count * std::size_t(100 - percent) / 100);
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(at), values.end());
  threshold_ = values[at];
}

float DistinctiveColors::squaredDistanceFromMedian(const float* color) const {
  float sum = 0;
  for (int c = 0; c < channels_; ++c)
    sum += (color[c] - median_[std::size_t(c)]) * (color[c] - median_[std::size_t(c)]);
  return sum;
}

Image distinctiveFeatureMask(const Image& exemplar, int percent) {
  const DistinctiveColors distinctive(exemplar, exemplar.channels, percent);
  Image mask(exemplar.width, exemplar.height, 1);
  std::size_t features = 0;
  for (std::size_t p = 0; p < exemplar.pixelCount(); ++p) {
    const bool is = distinctive(exemplar.pixels.data() + p * std::size_t(exemplar.channels));
    mask.pixels[p] = is ? 1.0f : 0.0f;
    features += is;
  }
  return features == 0 || features == exemplar.pixelCount() ? Image() : mask;
}

}  // namespace texsynth
