#include "texsynth/eval/patch_vector_index.h"

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
// Vectors rotated per parallel work item (assign), and query vectors per work item
// (nearestVectors). Fixed, so the work split (and with it every guess) is the same for any
// thread count.
constexpr std::size_t kVectorsPerBlock = 64;

void checkFinite(std::span<const float> values, const char* what) {
  for (float value : values)
    if (!std::isfinite(value)) throw ParameterError(what, "contains non-finite values (NaN or infinity)");
}
}  // namespace

struct PatchVectorIndex::Impl {
  PatchBasis basis;
  std::vector<float> values;  // the distinct vectors, in order of their lowest index
  std::vector<int> original;  // per distinct vector: its lowest index among the given ones
  std::size_t count = 0;      // vectors given
  std::optional<PatchKdTree> tree;
};

PatchVectorIndex::PatchVectorIndex(const Image& basisImage, int patchSize) : impl_(std::make_unique<Impl>()) {
  if (patchSize < 1) throw ParameterError("patchSize", "must be positive, got " + std::to_string(patchSize));
  if (basisImage.empty() || basisImage.width < patchSize || basisImage.height < patchSize)
    throw ParameterError("image", "is " + std::to_string(basisImage.width) + "x" + std::to_string(basisImage.height) +
                                      ", smaller than a " + std::to_string(patchSize) + "x" +
                                      std::to_string(patchSize) + " patch");
  impl_->basis = eval_detail::computePatchBasis(basisImage, patchSize);
}

PatchVectorIndex::~PatchVectorIndex() = default;
PatchVectorIndex::PatchVectorIndex(PatchVectorIndex&&) noexcept = default;
PatchVectorIndex& PatchVectorIndex::operator=(PatchVectorIndex&&) noexcept = default;

int PatchVectorIndex::patchSize() const {
  return impl_->basis.patchSize;
}
int PatchVectorIndex::dimensions() const {
  return impl_->basis.dimensions;
}
std::size_t PatchVectorIndex::size() const {
  return impl_->count;
}

void PatchVectorIndex::assign(std::span<const float> vectors, std::size_t count) {
  Impl& d = *impl_;
  const std::size_t dims = std::size_t(d.basis.dimensions), stride = std::size_t(d.basis.stride);
  if (count == 0) throw ParameterError("vectors", "is empty");
  if (vectors.size() != count * dims || count > std::size_t(std::numeric_limits<int>::max()))
    throw ParameterError("vectors", "holds " + std::to_string(vectors.size()) + " values, not " +
                                        std::to_string(count) + " vectors of " + std::to_string(dims));
  checkFinite(vectors, "vectors");
  // Exact duplicates once, under their lowest index (which the tie rule would pick anyway): a
  // cluster of equal vectors is no cluster any KD-tree could prune (a one-color surface).
  auto vector = [&](std::size_t i) { return vectors.subspan(i * dims, dims); };
  std::vector<int> order(count);
  for (std::size_t i = 0; i < count; ++i) order[i] = int(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const auto va = vector(std::size_t(a)), vb = vector(std::size_t(b));
    const auto [pa, pb] = std::mismatch(va.begin(), va.end(), vb.begin());
    return pa != va.end() ? *pa < *pb : a < b;
  });
  d.original.clear();
  for (std::size_t i = 0; i < count; ++i)
    if (i == 0 || !std::ranges::equal(vector(std::size_t(order[i - 1])), vector(std::size_t(order[i]))))
      d.original.push_back(order[i]);
  std::sort(d.original.begin(), d.original.end());
  const std::size_t distinct = d.original.size();
  d.tree.reset();
  d.values.resize(distinct * dims);
  for (std::size_t u = 0; u < distinct; ++u)
    std::ranges::copy(vector(std::size_t(d.original[u])), d.values.begin() + std::ptrdiff_t(u * dims));
  d.count = count;
  std::vector<float> points(distinct * stride);
  const std::size_t blocks = (distinct + kVectorsPerBlock - 1) / kVectorsPerBlock;
  parallelFor(0, std::int64_t(blocks), [&](std::int64_t block) {
    const std::size_t first = std::size_t(block) * kVectorsPerBlock, n = std::min(kVectorsPerBlock, distinct - first);
    eval_detail::rotateVectors(&d.values[first * dims], n, d.basis, &points[first * stride]);
  });
  d.tree.emplace(points, int(distinct), int(stride));
}

std::vector<PatchMatch> PatchVectorIndex::nearestVectors(std::span<const float> queries, std::size_t count,
                                                         std::span<const double> limits) const {
  const Impl& d = *impl_;
  const std::size_t dims = std::size_t(d.basis.dimensions), stride = std::size_t(d.basis.stride);
  if (!d.tree) throw ParameterError("queries", "cannot be searched in an index of no vectors");
  if (queries.size() != count * dims)
    throw ParameterError("queries", "holds " + std::to_string(queries.size()) + " values, not " +
                                        std::to_string(count) + " vectors of " + std::to_string(dims));
  checkFinite(queries, "queries");
  if (!limits.empty() && limits.size() != count)
    throw ParameterError("limits",
                         "has " + std::to_string(limits.size()) + " entries for " + std::to_string(count) + " queries");
  for (double limit : limits)
    if (!(limit >= 0)) throw ParameterError("limits", "must be >= 0 (or infinity), got " + std::to_string(limit));
  std::vector<PatchMatch> matches(count);
  const std::size_t blocks = (count + kVectorsPerBlock - 1) / kVectorsPerBlock;
  parallelFor(0, std::int64_t(blocks), [&](std::int64_t block) {
    const std::size_t first = std::size_t(block) * kVectorsPerBlock, n = std::min(kVectorsPerBlock, count - first);
    const float* values = queries.data() + first * dims;
    std::vector<float> vectors(n * stride);
    eval_detail::rotateVectors(values, n, d.basis, vectors.data());
    int guess = -1;
    for (std::size_t i = 0; i < n; ++i) {
      const float* query = &vectors[i * stride];
      float bound = std::numeric_limits<float>::infinity();
      if (!limits.empty() && limits[first + i] < std::numeric_limits<float>::max() / (2.0 * double(dims)))
        bound = PatchKdTree::slackened(float(limits[first + i] * double(dims)));
      PatchKdTree::Best best{bound, -1};
      if (guess >= 0) {
        const float distance = d.tree->distanceTo(query, guess);
        if (distance <= bound) best = {distance, guess};
      }
      d.tree->nearest(query, best);
      if (best.index < 0) {
        matches[first + i] = {-1, std::numeric_limits<double>::infinity()};
        continue;
      }
      guess = best.index;
      // The distance in double, from the raw query and indexed values.
      const float* raw = values + i * dims;
      const float* indexed = &d.values[std::size_t(best.index) * dims];
      double sum = 0;
      for (std::size_t k = 0; k < dims; ++k) {
        const double diff = double(raw[k]) - double(indexed[k]);
        sum += diff * diff;
      }
      matches[first + i] = {d.original[std::size_t(best.index)], sum / double(dims)};
    }
  });
  return matches;
}

}  // namespace texsynth
