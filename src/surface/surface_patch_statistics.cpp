// Flatness and completeness of a surface texture (surface_patch_statistics.h).
#include "surface_patch_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"

namespace texsynth::surface_detail {
namespace {

constexpr std::uint64_t kCompletenessStream = 0x636f6d706c657465;  // "complete": the sample's own hash
constexpr std::uint64_t kFlatnessOffsets = 0x666c61746e657373;     // "flatness": fixed, a property of the exemplar

void copyPatch(const Image& image, int patchSize, int x, int y, float* out) {
  const std::size_t rowValues = std::size_t(patchSize) * image.channels;
  for (int dy = 0; dy < patchSize; ++dy) std::copy_n(image.pixel(x, y + dy), rowValues, out + dy * rowValues);
}

}  // namespace

double flatnessThreshold(const Image& exemplar255, int patchSize) {
  const int columns = exemplar255.width - patchSize + 1, rows = exemplar255.height - patchSize + 1;
  const int pixels = patchSize * patchSize;
  std::vector<double> deviations(std::size_t(columns) * rows);
  parallelFor(0, rows, [&](std::int64_t row) {
    const int y = int(row);
    std::vector<float> patch(std::size_t(pixels) * 3);
    for (int x = 0; x < columns; ++x) {
      // The sub-pixel offset: none along an axis where the patch touches the exemplar's edge.
      const std::uint64_t key = hashKey(kFlatnessOffsets, std::uint64_t(y) * std::uint64_t(columns) + std::uint64_t(x));
      const float fx = x + 1 < columns ? uniform01(key) : 0.0f;
      const float fy = y + 1 < rows ? uniform01(hashKey(key, 1)) : 0.0f;
      for (int dy = 0; dy < patchSize; ++dy)
        for (int dx = 0; dx < patchSize; ++dx) {
          const int x1 = std::min(x + dx + 1, exemplar255.width - 1), y1 = std::min(y + dy + 1, exemplar255.height - 1);
          const float *p00 = exemplar255.pixel(x + dx, y + dy), *p10 = exemplar255.pixel(x1, y + dy);
          const float *p01 = exemplar255.pixel(x + dx, y1), *p11 = exemplar255.pixel(x1, y1);
          float* out = &patch[std::size_t(dy * patchSize + dx) * 3];
          for (int c = 0; c < 3; ++c)
            out[c] = (1 - fy) * ((1 - fx) * p00[c] + fx * p10[c]) + fy * ((1 - fx) * p01[c] + fx * p11[c]);
        }
      deviations[std::size_t(y) * columns + x] = rgbPatchDeviation(patch.data(), pixels);
    }
  });
  const auto tenth = deviations.begin() + std::ptrdiff_t(deviations.size() / 10);
  std::nth_element(deviations.begin(), tenth, deviations.end());
  return *tenth;
}

CompletenessSearch::CompletenessSearch(const Image& exemplar255, int patchSize, std::uint64_t seed)
    : index_(exemplar255, patchSize) {
  const int columns = exemplar255.width - patchSize + 1, rows = exemplar255.height - patchSize + 1;
  std::vector<int> patches(std::size_t(columns) * rows);
  for (std::size_t i = 0; i < patches.size(); ++i) patches[i] = int(i);
  if (patches.size() > kCompletenessPatches) {
    auto key = [&](int i) { return std::pair{hashKey(seed, std::uint64_t(i), kCompletenessStream), i}; };
    std::nth_element(patches.begin(), patches.begin() + std::ptrdiff_t(kCompletenessPatches), patches.end(),
                     [&](int a, int b) { return key(a) < key(b); });
    patches.resize(kCompletenessPatches);
    std::sort(patches.begin(), patches.end());  // row order: neighbours' matches make good guesses
  }
  count_ = patches.size();
  const std::size_t dims = std::size_t(index_.dimensions());
  queries_.resize(count_ * dims);
  for (std::size_t i = 0; i < count_; ++i)
    copyPatch(exemplar255, patchSize, patches[i] % columns, patches[i] / columns, &queries_[i * dims]);
  best_.assign(count_, std::numeric_limits<double>::infinity());
}

void CompletenessSearch::add(std::span<const float> surfacePatches, std::size_t count) {
  index_.assign(surfacePatches, count);
  const std::vector<PatchMatch> matches = index_.nearestVectors(queries_, count_, best_);
  for (std::size_t i = 0; i < count_; ++i) best_[i] = std::min(best_[i], matches[i].meanSquared);
}

double CompletenessSearch::result() const {
  double sum = 0;
  for (double d : best_) sum += d;
  return std::sqrt(sum / double(count_));
}

}  // namespace texsynth::surface_detail
