#include "texsynth/image/make_tileable.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "texsynth/core/error.h"

namespace texsynth {

namespace {

Image transposed(const Image& in) {
  Image out(in.height, in.width, in.channels);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) std::copy_n(in.pixel(x, y), in.channels, out.pixel(y, x));
  return out;
}

// Cut column (within the overlap) for each row: the minimum-cost 8-connected vertical path
// through the squared difference of the two overlapping strips, kept `margin` away from the
// strip edges so the feather stays inside the overlap.
std::vector<int> minimumErrorCut(const Image& image, int overlap, int margin) {
  const int w = image.width, h = image.height;
  auto error = [&](int y, int k) {
    double e = 0;
    for (int c = 0; c < image.channels; ++c) {
      double d = image.at(k, y, c) - image.at(w - overlap + k, y, c);
      e += d * d;
    }
    return e;
  };
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> cost(std::size_t(h) * overlap, inf);
  for (int y = 0; y < h; ++y)
    for (int k = margin; k < overlap - margin; ++k) {
      double best = 0;
      if (y > 0) {
        best = cost[std::size_t(y - 1) * overlap + k];
        if (k > margin) best = std::min(best, cost[std::size_t(y - 1) * overlap + k - 1]);
        if (k + 1 < overlap - margin) best = std::min(best, cost[std::size_t(y - 1) * overlap + k + 1]);
      }
      cost[std::size_t(y) * overlap + k] = error(y, k) + best;
    }
  std::vector<int> cut(h);
  const double* last = &cost[std::size_t(h - 1) * overlap];
  cut[h - 1] = int(std::min_element(last + margin, last + overlap - margin) - last);
  for (int y = h - 2; y >= 0; --y) {
    int best = cut[y + 1];
    for (int k = std::max(margin, cut[y + 1] - 1); k <= std::min(overlap - margin - 1, cut[y + 1] + 1); ++k)
      if (cost[std::size_t(y) * overlap + k] < cost[std::size_t(y) * overlap + best]) best = k;
    cut[y] = best;
  }
  return cut;
}

// Makes the image tileable horizontally; the result is `overlap` columns narrower.
Image tileableHorizontally(const Image& image, int overlap, int feather) {
  const std::vector<int> cut = minimumErrorCut(image, overlap, feather + 1);
  Image out(image.width - overlap, image.height, image.channels);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const float* near = image.pixel(x, y);
      if (x >= overlap) {
        std::copy_n(near, image.channels, out.pixel(x, y));
        continue;
      }
      const float* far = image.pixel(image.width - overlap + x, y);
      // Weight of the near (original position) pixel: 0 left of the cut, 1 right of it.
      float t = feather > 0 ? std::clamp((float(x - cut[y]) + 0.5f) / float(2 * feather + 1) + 0.5f, 0.0f, 1.0f)
                            : (x >= cut[y] ? 1.0f : 0.0f);
      for (int c = 0; c < image.channels; ++c) out.at(x, y, c) = far[c] + (near[c] - far[c]) * t;
    }
  }
  return out;
}

}  // namespace

Image makeTileable(const Image& exemplar, const MakeTileableOptions& options) {
  if (!std::isfinite(options.overlapFraction) || !(options.overlapFraction > 0.0f) || options.overlapFraction > 0.5f)
    throw ParameterError("overlapFraction", "must be in (0, 0.5], got " + std::to_string(options.overlapFraction));
  if (options.featherRadius < 0)
    throw ParameterError("featherRadius", "must be >= 0, got " + std::to_string(options.featherRadius));
  const int minOverlap = 2 * options.featherRadius + 3;
  const int overlapX = int(std::lround(options.overlapFraction * exemplar.width));
  const int overlapY = int(std::lround(options.overlapFraction * exemplar.height));
  if (exemplar.empty() || overlapX < minOverlap || overlapY < minOverlap)
    throw ParameterError("exemplar", std::to_string(exemplar.width) + "x" + std::to_string(exemplar.height) +
                                         " is too small for an overlap of at least " + std::to_string(minOverlap) +
                                         " pixels per side");
  Image horizontal = tileableHorizontally(exemplar, overlapX, options.featherRadius);
  return transposed(tileableHorizontally(transposed(horizontal), overlapY, options.featherRadius));
}

SeamStrength measureSeams(const Image& image) {
  if (image.width < 2 || image.height < 2) throw ParameterError("image", "needs at least 2x2 pixels to measure seams");
  double wrapSum = 0, interiorSum = 0;
  std::size_t wrapCount = 0, interiorCount = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < image.channels; ++c) {
        const float v = image.at(x, y, c);
        const float right = image.wrapped(x + 1, y, c), below = image.wrapped(x, y + 1, c);
        double& horizontalSum = (x + 1 == image.width) ? wrapSum : interiorSum;
        std::size_t& horizontalCount = (x + 1 == image.width) ? wrapCount : interiorCount;
        horizontalSum += std::abs(right - v), ++horizontalCount;
        double& verticalSum = (y + 1 == image.height) ? wrapSum : interiorSum;
        std::size_t& verticalCount = (y + 1 == image.height) ? wrapCount : interiorCount;
        verticalSum += std::abs(below - v), ++verticalCount;
      }
  return {wrapSum / double(wrapCount), interiorSum / double(interiorCount)};
}

}  // namespace texsynth
