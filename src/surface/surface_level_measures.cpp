// Flatness and histogram distance of one level's coordinates (surface_level_measures.h).
#include "texsynth/surface/surface_level_measures.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "surface_patch_statistics.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"
#include "texsynth/eval/histogram_distance.h"
#include "texsynth/surface/surface_parallel.h"

namespace texsynth {

SurfaceLevelMeasures measureSurfaceLevel(const SurfaceStencil& stencil, const ExemplarLevel& level,
                                         std::span<const Vec2f> coordinates) {
  const Image& image = level.image;
  const int channels = image.channels, h = level.spacing, radius = stencil.size / 2;
  std::vector<float> colors(coordinates.size() * std::size_t(channels));
  const std::vector<std::int32_t> pixels = pixelsOfCoordinates(coordinates, image.width, image.height);
  for (std::size_t v = 0; v < pixels.size(); ++v)
    std::copy_n(image.pixels.data() + std::size_t(pixels[v]) * channels, channels, colors.data() + v * channels);

  // The exemplar's neighbourhoods of the stencil's size, h apart, at every other pixel.
  std::vector<double> exemplarSpread;
  std::vector<float> patch;
  for (int y = 0; y < image.height; y += 2)
    for (int x = 0; x < image.width; x += 2) {
      patch.clear();
      for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
          const float* p = image.pixel(wrapIndex(x + dx * h, image.width), wrapIndex(y + dy * h, image.height));
          patch.insert(patch.end(), p, p + channels);
        }
      exemplarSpread.push_back(surface_detail::patchDeviation(patch.data(), int(patch.size()) / channels, channels));
    }
  const std::size_t tenth = exemplarSpread.size() / 10;
  std::nth_element(exemplarSpread.begin(), exemplarSpread.begin() + std::ptrdiff_t(tenth), exemplarSpread.end());
  const double threshold = exemplarSpread[tenth];

  std::vector<std::uint8_t> flat(coordinates.size(), 0);
  parallelForChunks(0, std::int64_t(coordinates.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
    std::vector<float> members;
    for (std::int64_t v = begin; v < end; ++v) {
      members.clear();
      for (const NeighborhoodMember& m : stencil.of(std::size_t(v))) {
        const float* color = colors.data() + std::size_t(m.vertex) * channels;
        members.insert(members.end(), color, color + channels);
      }
      flat[std::size_t(v)] =
          surface_detail::patchDeviation(members.data(), int(members.size()) / channels, channels) < threshold;
    }
  });
  SurfaceLevelMeasures measures;
  std::size_t flatCount = 0;
  for (std::uint8_t f : flat) flatCount += f;
  measures.flatness = coordinates.empty() ? 0.0 : double(flatCount) / double(coordinates.size()) - 0.10;

  // Distinctive colors: farther from the per-channel median than the exemplar's 80th percentile.
  const std::size_t pixelCount = std::size_t(image.width) * image.height;
  std::vector<float> median(static_cast<std::size_t>(channels)), values(pixelCount);
  for (int c = 0; c < channels; ++c) {
    for (std::size_t p = 0; p < pixelCount; ++p) values[p] = image.pixels[p * channels + std::size_t(c)];
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(pixelCount / 2), values.end());
    median[std::size_t(c)] = values[pixelCount / 2];
  }
  auto fromMedian = [&](const float* color) {
    float sum = 0;
    for (int c = 0; c < channels; ++c) sum += (color[c] - median[std::size_t(c)]) * (color[c] - median[std::size_t(c)]);
    return sum;
  };
  for (std::size_t p = 0; p < pixelCount; ++p) values[p] = fromMedian(image.pixels.data() + p * channels);
  const std::size_t fifth = pixelCount * 4 / 5;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(fifth), values.end());
  const float far = values[fifth];
  std::size_t distinctive = 0;
  for (std::size_t v = 0; v < coordinates.size(); ++v) distinctive += fromMedian(colors.data() + v * channels) > far;
  measures.distinctive = coordinates.empty() ? 0.0 : double(distinctive) / double(coordinates.size());

  // Wasserstein-1 per channel between the vertices' values and the level's pixels.
  if (coordinates.empty()) return measures;
  std::vector<float> ours(coordinates.size()), theirs(pixelCount);
  double total = 0;
  for (int c = 0; c < channels; ++c) {
    for (std::size_t v = 0; v < ours.size(); ++v) ours[v] = colors[v * channels + std::size_t(c)];
    for (std::size_t p = 0; p < pixelCount; ++p) theirs[p] = image.pixels[p * channels + std::size_t(c)];
    total += wasserstein1(ours, theirs);
  }
  measures.histogram = total / channels;
  return measures;
}

}  // namespace texsynth
