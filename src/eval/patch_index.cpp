#include "texsynth/eval/patch_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "patch_kd_tree.h"
#include "patch_vectors.h"
#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
using eval_detail::PatchBasis;
using eval_detail::PatchKdTree;

namespace {
// Patch rows per parallel work item. Fixed, so the work split (and with it every guess and
// rotation) is the same for any thread count.
constexpr int kRowsPerBlock = 4;
// Query vectors per parallel work item of nearestVectors.
constexpr std::size_t kVectorsPerBlock = 64;
}  // namespace

struct PatchIndex::Impl {
  Image image;
  int columns = 0, rows = 0;
  PatchBasis basis;
  std::optional<PatchKdTree> tree;

  // The nearest patch to `query`, starting from the match `guess` (or none, -1), among those
  // closer than `bound` (a float distance in rotated coordinates).
  PatchKdTree::Best search(const float* query, int guess, float bound = std::numeric_limits<float>::infinity()) const {
    PatchKdTree::Best best{bound, -1};
    if (guess >= 0) best = {tree->distanceTo(query, guess), guess};
    tree->nearest(query, best);
    return best;
  }
  // The patch next to `index` in direction (dx, dy), or -1 at the border: a good neighbour's
  // match shifted along is usually a good match (the coherence PatchMatch exploits).
  int shifted(int index, int dx, int dy) const {
    if (index < 0) return -1;
    int x = index % columns + dx, y = index / columns + dy;
    return x < columns && y < rows ? y * columns + x : -1;
  }
};

PatchIndex::PatchIndex(const Image& image, int patchSize) : impl_(std::make_unique<Impl>()) {
  if (patchSize < 1) throw ParameterError("patchSize", "must be positive, got " + std::to_string(patchSize));
  if (image.empty() || image.width < patchSize || image.height < patchSize)
    throw ParameterError("image", "is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                      ", smaller than a " + std::to_string(patchSize) + "x" +
                                      std::to_string(patchSize) + " patch");
  Impl& d = *impl_;
  d.image = image;
  d.columns = image.width - patchSize + 1;
  d.rows = image.height - patchSize + 1;
  d.basis = eval_detail::computePatchBasis(image, patchSize);
  const int stride = d.basis.stride;
  std::vector<float> points(std::size_t(d.columns) * d.rows * stride);
  const int blocks = (d.rows + kRowsPerBlock - 1) / kRowsPerBlock;
  parallelFor(0, blocks, [&](std::int64_t block) {
    const int first = int(block) * kRowsPerBlock, count = std::min(kRowsPerBlock, d.rows - first);
    eval_detail::rotatePatchRows(d.image, d.basis, first, count, &points[std::size_t(first) * d.columns * stride]);
  });
  d.tree.emplace(points, d.columns * d.rows, stride);
}

PatchIndex::~PatchIndex() = default;
PatchIndex::PatchIndex(PatchIndex&&) noexcept = default;
PatchIndex& PatchIndex::operator=(PatchIndex&&) noexcept = default;

int PatchIndex::patchSize() const {
  return impl_->basis.patchSize;
}
int PatchIndex::columns() const {
  return impl_->columns;
}
int PatchIndex::rows() const {
  return impl_->rows;
}
const Image& PatchIndex::image() const {
  return impl_->image;
}

double PatchIndex::meanSquaredDifference(const Image& a, int ax, int ay, const Image& b, int bx, int by,
                                         int patchSize) {
  TS_CHECK(a.channels == b.channels);
  const int rowValues = patchSize * a.channels;
  double sum = 0;
  for (int dy = 0; dy < patchSize; ++dy) {
    const float* pa = a.pixel(ax, ay + dy);
    const float* pb = b.pixel(bx, by + dy);
    for (int k = 0; k < rowValues; ++k) {
      double diff = double(pa[k]) - double(pb[k]);
      sum += diff * diff;
    }
  }
  return sum / (double(rowValues) * patchSize);
}

std::vector<PatchMatch> PatchIndex::nearest(const Image& queries) const {
  const Impl& d = *impl_;
  const int size = patchSize();
  if (queries.channels != d.image.channels)
    throw ParameterError("queries", "has " + std::to_string(queries.channels) + " channels, the index " +
                                        std::to_string(d.image.channels));
  if (queries.width < size || queries.height < size)
    throw ParameterError("queries", "is smaller than a " + std::to_string(size) + "-pixel patch");
  const int columns = queries.width - size + 1, rows = queries.height - size + 1;
  const int stride = d.basis.stride;
  std::vector<PatchMatch> matches(std::size_t(columns) * rows);
  const int blocks = (rows + kRowsPerBlock - 1) / kRowsPerBlock;
  parallelFor(0, blocks, [&](std::int64_t block) {
    const int first = int(block) * kRowsPerBlock, count = std::min(kRowsPerBlock, rows - first);
    std::vector<float> vectors(std::size_t(count) * columns * stride);
    eval_detail::rotatePatchRows(queries, d.basis, first, count, vectors.data());
    for (int r = 0; r < count; ++r)
      for (int x = 0; x < columns; ++x) {
        const std::size_t at = std::size_t(first + r) * columns + x;
        int guess = x > 0   ? d.shifted(matches[at - 1].index, 1, 0)
                    : r > 0 ? d.shifted(matches[at - columns].index, 0, 1)
                            : -1;
        PatchKdTree::Best best = d.search(&vectors[(std::size_t(r) * columns + x) * stride], guess);
        const int bx = best.index % d.columns, by = best.index / d.columns;
        matches[at] = {best.index, meanSquaredDifference(queries, x, first + r, d.image, bx, by, size)};
      }
  });
  return matches;
}

std::vector<PatchMatch> PatchIndex::nearestVectors(std::span<const float> queries, std::size_t count,
                                                   std::span<const double> limits) const {
  const Impl& d = *impl_;
  const int size = patchSize(), dims = d.basis.dimensions, stride = d.basis.stride;
  if (queries.size() != count * std::size_t(dims))
    throw ParameterError("queries", "holds " + std::to_string(queries.size()) + " values, not " +
                                        std::to_string(count) + " vectors of " + std::to_string(dims));
  for (float value : queries)
    if (!std::isfinite(value)) throw ParameterError("queries", "contains non-finite values (NaN or infinity)");
  if (!limits.empty() && limits.size() != count)
    throw ParameterError("limits",
                         "has " + std::to_string(limits.size()) + " entries for " + std::to_string(count) + " queries");
  for (double limit : limits)
    if (!(limit >= 0)) throw ParameterError("limits", "must be >= 0 (or infinity), got " + std::to_string(limit));
  const std::size_t rowValues = std::size_t(size) * d.image.channels;
  std::vector<PatchMatch> matches(count);
  const std::size_t blocks = (count + kVectorsPerBlock - 1) / kVectorsPerBlock;
  parallelFor(0, std::int64_t(blocks), [&](std::int64_t block) {
    const std::size_t first = std::size_t(block) * kVectorsPerBlock;
    const std::size_t n = std::min(kVectorsPerBlock, count - first);
    const float* values = queries.data() + first * dims;
    std::vector<float> vectors(n * stride);
    eval_detail::rotateVectors(values, n, d.basis, vectors.data());
    for (std::size_t i = 0; i < n; ++i) {
      float bound = std::numeric_limits<float>::infinity();
      if (!limits.empty() && limits[first + i] < std::numeric_limits<float>::max() / (2.0 * dims))
        bound = PatchKdTree::slackened(float(limits[first + i] * dims));
      PatchKdTree::Best best = d.search(&vectors[i * stride], -1, bound);
      if (best.index < 0) {
        matches[first + i] = {-1, std::numeric_limits<double>::infinity()};
        continue;
      }
      const int bx = best.index % d.columns, by = best.index / d.columns;
      // The distance in double, from the raw query values and the indexed pixels.
      const float* query = values + i * dims;
      double sum = 0;
      for (int dy = 0; dy < size; ++dy) {
        const float* pixels = d.image.pixel(bx, by + dy);
        for (std::size_t k = 0; k < rowValues; ++k) {
          const double diff = double(query[dy * rowValues + k]) - double(pixels[k]);
          sum += diff * diff;
        }
      }
      matches[first + i] = {best.index, sum / double(dims)};
    }
  });
  return matches;
}

std::vector<int> PatchIndex::within(const Image& image, int x, int y, double limit) const {
  const Impl& d = *impl_;
  const int size = patchSize();
  TS_CHECK(image.channels == d.image.channels && x >= 0 && y >= 0 && x + size <= image.width &&
           y + size <= image.height);
  std::vector<float> query(d.basis.stride);
  eval_detail::rotatePatch(image, d.basis, x, y, query.data());
  std::vector<int> candidates;
  d.tree->within(query.data(), float(limit * d.basis.dimensions), candidates);
  // The float search may admit borderline candidates; the double check decides.
  std::vector<int> found;
  for (int index : candidates)
    if (meanSquaredDifference(image, x, y, d.image, index % d.columns, index / d.columns, size) <= limit)
      found.push_back(index);
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace texsynth
