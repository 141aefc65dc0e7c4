// The flat-patch share of a synthesized level (flat_patch_share.h).
#include "texsynth/image/flat_patch_share.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"

namespace texsynth::detail {
namespace {

constexpr int kSampleStep = 2;

}  // namespace

double flatPatchThreshold(const ExemplarLevel& level, int channels, int size) {
  const Image& image = level.image;
  const int h = level.spacing, radius = size / 2, side = 2 * radius + 1;
  std::vector<double> deviations;
  for (int y = 0; y < image.height; y += kSampleStep)
    for (int x = 0; x < image.width; x += kSampleStep)
      deviations.push_back(patchDeviation(side * side, channels, [&](int i) {
        return image.pixel(wrapIndex(x + h * (i % side - radius), image.width),
                           wrapIndex(y + h * (i / side - radius), image.height));
      }));
  const auto tenth = deviations.begin() + std::ptrdiff_t(deviations.size() / 10);
  std::nth_element(deviations.begin(), tenth, deviations.end());
  return *tenth;
}

FlatPatchShare::FlatPatchShare(const ExemplarLevel& level, int colorChannels, int size)
    : level_(level),
      channels_(std::clamp(colorChannels, 1, std::min(4, level.image.channels))),
      radius_(size / 2),
      threshold_(flatPatchThreshold(level, channels_, size)) {}

double FlatPatchShare::of(std::span<const std::int32_t> sources, int width, int height) const {
  const Image& image = level_.image;
  const int rows = (height + kSampleStep - 1) / kSampleStep, side = 2 * radius_ + 1;
  std::vector<int> flatPerRow(static_cast<std::size_t>(rows), 0);
  parallelForChunks(0, rows, 8, [&](std::int64_t begin, std::int64_t end) {
    // A patch's colors gathered once (patchDeviation reads each twice), with its wrapped rows
    // and columns computed per patch rather than per read.
    std::vector<const float*> colors(static_cast<std::size_t>(side * side));
    std::vector<std::size_t> rowStart(static_cast<std::size_t>(side)), column(static_cast<std::size_t>(side));
    for (std::int64_t row = begin; row < end; ++row) {
      const int y = int(row) * kSampleStep;
      for (int d = 0; d < side; ++d) rowStart[std::size_t(d)] = std::size_t(wrapIndex(y + d - radius_, height)) * width;
      for (int x = 0; x < width; x += kSampleStep) {
        for (int d = 0; d < side; ++d) column[std::size_t(d)] = std::size_t(wrapIndex(x + d - radius_, width));
        for (int i = 0; i < side * side; ++i) {
          const std::int32_t source = sources[rowStart[std::size_t(i / side)] + column[std::size_t(i % side)]];
          colors[std::size_t(i)] = image.pixels.data() + std::size_t(source) * std::size_t(image.channels);
        }
        const double d = patchDeviation(side * side, channels_, [&](int i) { return colors[std::size_t(i)]; });
        flatPerRow[std::size_t(row)] += d < threshold_;
      }
    }
  });
  std::int64_t flat = 0;
  for (int f : flatPerRow) flat += f;
  const std::int64_t samples = std::int64_t(rows) * ((width + kSampleStep - 1) / kSampleStep);
  return samples > 0 ? double(flat) / double(samples) : 0.0;
}

}  // namespace texsynth::detail
