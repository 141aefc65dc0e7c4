#include "texsynth/exemplar/gaussian_stack.h"

#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"

namespace texsynth {
namespace {

constexpr float kCenterWeight = 6.0f / 16.0f;
constexpr float kNearWeight = 4.0f / 16.0f;
constexpr float kFarWeight = 1.0f / 16.0f;

// Filters `count` samples spaced `stride` floats apart (a row or a column of one channel).
// `line` is a private copy of the input samples, so in-place output is safe.
void filterLine(const float* line, int count, int spacing, float* out, std::size_t outStride) {
  for (int i = 0; i < count; ++i) {
    float nearSum = line[wrapIndex(i - spacing, count)] + line[wrapIndex(i + spacing, count)];
    float farSum = line[wrapIndex(i - 2LL * spacing, count)] + line[wrapIndex(i + 2LL * spacing, count)];
    out[i * outStride] = kFarWeight * farSum + kNearWeight * nearSum + kCenterWeight * line[i];
  }
}

}  // namespace

int defaultStackLevelCount(int width, int height) {
  int smaller = width < height ? width : height;
  int levels = 0;
  while ((2LL << levels) <= smaller) ++levels;  // floor(log2(smaller))
  return levels < 1 ? 1 : levels;
}

Image filterBinomialToroidal(const Image& image, int spacing) {
  TS_CHECK(spacing >= 1 && !image.empty());
  const int width = image.width, height = image.height, channels = image.channels;
  Image horizontal(width, height, channels);
  parallelForChunks(0, std::int64_t(height) * channels, 16, [&](std::int64_t begin, std::int64_t end) {
    std::vector<float> line(width);
    for (std::int64_t job = begin; job < end; ++job) {
      int y = int(job / channels), c = int(job % channels);
      for (int x = 0; x < width; ++x) line[x] = image.at(x, y, c);
      filterLine(line.data(), width, spacing, horizontal.pixel(0, y) + c, channels);
    }
  });
  Image result(width, height, channels);
  const std::size_t rowStride = std::size_t(width) * channels;
  parallelForChunks(0, std::int64_t(width) * channels, 16, [&](std::int64_t begin, std::int64_t end) {
    std::vector<float> line(height);
    for (std::int64_t job = begin; job < end; ++job) {
      int x = int(job / channels), c = int(job % channels);
      for (int y = 0; y < height; ++y) line[y] = horizontal.at(x, y, c);
      filterLine(line.data(), height, spacing, result.pixel(x, 0) + c, rowStride);
    }
  });
  return result;
}

GaussianStack buildGaussianStack(const Image& exemplar, const GaussianStackOptions& options) {
  if (exemplar.empty()) throw ParameterError("exemplar", "image is empty");
  const int maxLevels = defaultStackLevelCount(exemplar.width, exemplar.height);
  if (options.levelCount < 0 || options.levelCount > maxLevels)
    throw ParameterError("levelCount", "must be 0 (automatic) or 1.." + std::to_string(maxLevels) + " for a " +
                                           std::to_string(exemplar.width) + "x" + std::to_string(exemplar.height) +
                                           " exemplar, got " + std::to_string(options.levelCount));
  const int levelCount = options.levelCount == 0 ? maxLevels : options.levelCount;
  GaussianStack stack;
  stack.levels.resize(levelCount);
  stack.levels[levelCount - 1] = exemplar;
  // Each coarser level filters the next finer one at that finer level's spacing, as a
  // pyramid's reduce step would before subsampling.
  for (int level = levelCount - 2; level >= 0; --level)
    stack.levels[level] = filterBinomialToroidal(stack.levels[level + 1], stack.spacing(level + 1));
  return stack;
}

}  // namespace texsynth
