#include "patch_kd_tree.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>

#include "patch_vectors.h"
#include "texsynth/core/error.h"

namespace texsynth::eval_detail {
namespace {
// Float lower bounds and float distances each carry rounding of ~1e-5 relative; prune only
// when the bound is clearly past the limit so no true candidate is ever skipped.
constexpr float kPruneSlack = 1e-4f;
constexpr float kPruneFloor = 1e-3f;
}  // namespace

float PatchKdTree::slackened(float limit) {
  return limit * (1 + kPruneSlack) + kPruneFloor;
}

struct PatchKdTree::Search {
  const float* query;
  float limit;  // best distance so far (nearest) or the radius (within)
  int bestIndex;
  std::vector<int>* found;
  float offset[kSplitCoordinates] = {};  // per split coordinate: query minus the cell's side
};

PatchKdTree::PatchKdTree(const std::vector<float>& points, int count, int stride) : stride_(stride) {
  TS_CHECK(count > 0 && points.size() == std::size_t(count) * stride);
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  nodes_.reserve(4 * std::size_t(count) / kLeafSize + 2);
  slotOf_.resize(count);
  build(order, 0, count, points);
}

int PatchKdTree::build(std::vector<int>& order, int begin, int end, const std::vector<float>& points) {
  const int self = int(nodes_.size());
  nodes_.push_back({});
  if (end - begin <= kLeafSize) {
    const int leaf = int(slotIndex_.size() / kLeafSize);
    nodes_[self].leaf = leaf;
    slotIndex_.resize(slotIndex_.size() + kLeafSize, -1);
    leafValues_.resize(leafValues_.size() + std::size_t(stride_) * kLeafSize, 0.0f);
    float* values = &leafValues_[std::size_t(leaf) * stride_ * kLeafSize];
    for (int slot = 0; slot < kLeafSize; ++slot) {
      // Padding slots repeat the last point; their index -1 keeps them out of every result.
      const int index = order[std::min(begin + slot, end - 1)];
      if (begin + slot < end)
        slotIndex_[std::size_t(leaf) * kLeafSize + slot] = index, slotOf_[index] = leaf * kLeafSize + slot;
      for (int c = 0; c < stride_; ++c) values[c * kLeafSize + slot] = points[std::size_t(index) * stride_ + c];
    }
    return self;
  }
  // Split the widest of the leading coordinates at its median; (value, index) is a total
  // order, so the tree is the same on every run.
  const int splitCount = std::min(kSplitCoordinates, stride_);
  int widest = 0;
  float widestSpread = -1;
  for (int c = 0; c < splitCount; ++c) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    for (int i = begin; i < end; ++i) {
      float v = points[std::size_t(order[i]) * stride_ + c];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    if (hi - lo > widestSpread) widestSpread = hi - lo, widest = c;
  }
  const int middle = begin + (end - begin) / 2;
  auto value = [&](int index) { return points[std::size_t(index) * stride_ + widest]; };
  std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                   [&](int a, int b) { return value(a) < value(b) || (value(a) == value(b) && a < b); });
  const float split = value(order[middle]);  // before the children reorder their ranges
  const int left = build(order, begin, middle, points);
  const int right = build(order, middle, end, points);
  Node& node = nodes_[self];
  node.coordinate = widest;
  node.split = split;
  node.left = left;
  node.right = right;
  return self;
}

float PatchKdTree::distanceTo(const float* query, int index) const {
  const int slot = slotOf_[index];
  const float* values = &leafValues_[std::size_t(slot / kLeafSize) * stride_ * kLeafSize + slot % kLeafSize];
  float sum = 0;  // same order of summation as leafDistances
  for (int c = 0; c < stride_; ++c) {
    const float d = query[c] - values[std::size_t(c) * kLeafSize];
    sum += d * d;
  }
  return sum;
}

// All kLeafSize slots at once as one GCC/Clang vector: the compiler maps it onto whatever SIMD
// width the target has, with no horizontal sums in the hot loop.
using LeafLanes = float __attribute__((vector_size(PatchKdTree::kLeafSize * sizeof(float))));

bool PatchKdTree::leafDistances(int leaf, const float* query, float limit, float* distances) const {
  const float* values = &leafValues_[std::size_t(leaf) * stride_ * kLeafSize];
  LeafLanes sum = {};
  for (int start = 0; start < stride_; start += kLaneWidth) {
    for (int c = start; c < start + kLaneWidth; ++c) {
      LeafLanes row;
      std::memcpy(&row, values + std::size_t(c) * kLeafSize, sizeof row);
      const LeafLanes d = query[c] - row;
      sum += d * d;
    }
    // Partial sums never decrease: once all are past the limit, so are the full distances.
    float lowest = sum[0];
    for (int slot = 1; slot < kLeafSize; ++slot) lowest = std::min(lowest, sum[slot]);
    if (lowest > limit) return false;
  }
  std::memcpy(distances, &sum, sizeof sum);
  return true;
}

void PatchKdTree::nearest(const float* query, Best& best) const {
  Search search{query, best.distance, best.index, nullptr};
  searchNearest(0, search, 0.0f);
  best = {search.limit, search.bestIndex};
}

void PatchKdTree::within(const float* query, float radius, std::vector<int>& out) const {
  Search search{query, radius, -1, &out};
  searchWithin(0, search, 0.0f);
}

// Arya & Mount's incremental bound: the squared distance from the query to a cell, summed
// over the split coordinates, updated in O(1) when crossing one split.
void PatchKdTree::searchNearest(int nodeIndex, Search& s, float lowerBound) const {
  const Node& node = nodes_[nodeIndex];
  if (node.coordinate < 0) {
    float distances[kLeafSize];
    if (!leafDistances(node.leaf, s.query, s.limit, distances)) return;
    for (int slot = 0; slot < kLeafSize; ++slot) {
      const int index = slotIndex_[std::size_t(node.leaf) * kLeafSize + slot];
      const float d = distances[slot];
      if (index >= 0 && (d < s.limit || (d == s.limit && index < s.bestIndex))) s.limit = d, s.bestIndex = index;
    }
    return;
  }
  const float diff = s.query[node.coordinate] - node.split;
  searchNearest(diff < 0 ? node.left : node.right, s, lowerBound);
  const float previous = s.offset[node.coordinate];
  const float farBound = lowerBound - previous * previous + diff * diff;
  if (farBound > slackened(s.limit)) return;
  s.offset[node.coordinate] = diff;
  searchNearest(diff < 0 ? node.right : node.left, s, farBound);
  s.offset[node.coordinate] = previous;
}

void PatchKdTree::searchWithin(int nodeIndex, Search& s, float lowerBound) const {
  const Node& node = nodes_[nodeIndex];
  const float limit = slackened(s.limit);
  if (node.coordinate < 0) {
    float distances[kLeafSize];
    if (!leafDistances(node.leaf, s.query, limit, distances)) return;
    for (int slot = 0; slot < kLeafSize; ++slot) {
      const int index = slotIndex_[std::size_t(node.leaf) * kLeafSize + slot];
      if (index >= 0 && distances[slot] <= limit) s.found->push_back(index);
    }
    return;
  }
  const float diff = s.query[node.coordinate] - node.split;
  searchWithin(diff < 0 ? node.left : node.right, s, lowerBound);
  const float previous = s.offset[node.coordinate];
  const float farBound = lowerBound - previous * previous + diff * diff;
  if (farBound > limit) return;
  s.offset[node.coordinate] = diff;
  searchWithin(diff < 0 ? node.right : node.left, s, farBound);
  s.offset[node.coordinate] = previous;
}

}  // namespace texsynth::eval_detail
