// Flatness, histogram distance, distinctive share and coherence distance of one level's
// coordinates, and the rule that keeps a refinement by them (surface_level_measures.h).
#include "texsynth/surface/surface_level_measures.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "texsynth/core/parallel.h"
#include "texsynth/eval/histogram_distance.h"
#include "texsynth/exemplar/distinctive_colors.h"
#include "texsynth/image/flat_patch_share.h"
#include "texsynth/surface/surface_parallel.h"

namespace texsynth {

namespace {
constexpr double kFlatnessTolerance = 0.025, kHistogramTolerance = 1.5, kHistogramFloor = 0.003,
                 kDistinctiveShare = 0.9;
// A refinement that joins the start (keepsTheTexture): coherence distance at most this share of
// the state's, and its allowances.
constexpr double kJoiningCoherence = 0.5, kJoiningHistogramTolerance = 3.0, kJoiningDistinctiveShare = 0.8;

bool keepsFeatures(const SurfaceLevelMeasures& before, const SurfaceLevelMeasures& after, double distinctiveShare) {
  return after.flatness <= std::max(before.flatness, 0.0) + kFlatnessTolerance &&
         after.distinctive >= distinctiveShare * before.distinctive;
}
}  // namespace

bool keepsTheFeatures(const SurfaceLevelMeasures& before, const SurfaceLevelMeasures& after) {
  return keepsFeatures(before, after, kDistinctiveShare);
}

bool keepsTheTexture(const SurfaceLevelMeasures& before, const SurfaceLevelMeasures& after) {
  const bool joins = before.coherence > 0 && after.coherence <= kJoiningCoherence * before.coherence;
  return keepsFeatures(before, after, joins ? kJoiningDistinctiveShare : kDistinctiveShare) &&
         after.histogram <=
             std::max((joins ? kJoiningHistogramTolerance : kHistogramTolerance) * before.histogram, kHistogramFloor);
}

SurfaceLevelMeasures measureSurfaceLevel(const SurfaceStencil& stencil, const ExemplarLevel& level,
                                         std::span<const Vec2f> coordinates) {
  const Image& image = level.image;
  const int channels = image.channels;
  std::vector<float> colors(coordinates.size() * std::size_t(channels));
  const std::vector<std::int32_t> pixels = pixelsOfCoordinates(coordinates, image.width, image.height);
  for (std::size_t v = 0; v < pixels.size(); ++v)
    std::copy_n(image.pixels.data() + std::size_t(pixels[v]) * channels, channels, colors.data() + v * channels);

  // Flat: below the exemplar level's 10th-percentile neighbourhood of the stencil's size.
  const double threshold = detail::flatPatchThreshold(level, channels, stencil.size);

  std::vector<std::uint8_t> flat(coordinates.size(), 0);
  parallelForChunks(0, std::int64_t(coordinates.size()), 4096, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v) {
      const auto members = stencil.of(std::size_t(v));
      flat[std::size_t(v)] = detail::patchDeviation(int(members.size()), channels, [&](int i) {
                               return colors.data() + std::size_t(members[std::size_t(i)].vertex) * channels;
                             }) < threshold;
    }
  });
  SurfaceLevelMeasures measures;
  std::size_t flatCount = 0;
  for (std::uint8_t f : flat) flatCount += f;
  measures.flatness = coordinates.empty() ? 0.0 : double(flatCount) / double(coordinates.size()) - 0.10;

  // Distinctive colors: farther from the per-channel median than the exemplar's 80th percentile.
  const std::size_t pixelCount = std::size_t(image.width) * image.height;
  const DistinctiveColors isDistinctive(image, channels, kDistinctivePercent);
  std::size_t distinctive = 0;
  for (std::size_t v = 0; v < coordinates.size(); ++v) distinctive += isDistinctive(colors.data() + v * channels);
  measures.distinctive = coordinates.empty() ? 0.0 : double(distinctive) / double(coordinates.size());
  double coherence = 0;  // summed in vertex order: the same for any thread count
  for (float d : stencilDistances(stencil, level, coordinates)) coherence += d;
  measures.coherence = coordinates.empty() ? 0.0 : coherence / double(coordinates.size());

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
