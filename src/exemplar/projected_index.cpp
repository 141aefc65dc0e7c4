// KD-tree over projected exemplar neighborhoods (see projected_index.h).
#include "texsynth/exemplar/projected_index.h"

#include <algorithm>
#include <limits>
#include <nanoflann.hpp>
#include <numeric>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

// The indexed pixels' vectors; tree point i is pixel pixels[i].
struct ProjectedDataset {
  PixelVectors vectors;
  const std::vector<std::int32_t>* pixels;
  std::size_t kdtree_get_point_count() const { return pixels->size(); }
  float kdtree_get_pt(std::uint32_t i, std::size_t component) const { return vectors.at((*pixels)[i])[component]; }
  template <class BoundingBox>
  bool kdtree_get_bbox(BoundingBox&) const {
    return false;
  }
};

using Metric = nanoflann::L2_Adaptor<float, ProjectedDataset, float, std::uint32_t>;
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<Metric, ProjectedDataset, -1, std::uint32_t>;

// Keeps the single nearest point; equal distances resolve to the lower index, so the answer
// does not depend on the order the tree visits leaves in.
class NearestResult {
 public:
  using DistanceType = float;
  using IndexType = std::uint32_t;
  std::size_t size() const { return found_ ? 1 : 0; }
  bool full() const { return found_; }
  float worstDist() const { return distance_; }
  bool addPoint(float distance, IndexType index) {
    if (distance < distance_ || (distance == distance_ && index < index_)) distance_ = distance, index_ = index;
    found_ = true;
    return true;
  }
  IndexType index() const { return index_; }

 private:
  float distance_ = std::numeric_limits<float>::max();
  IndexType index_ = 0;
  bool found_ = false;
};

}  // namespace

struct ProjectedNeighborhoodIndex::Tree {
  std::vector<std::int32_t> pixels;
  ProjectedDataset dataset;
  KdTree tree;  // builds on construction
  Tree(const PixelVectors& vectors, std::vector<std::int32_t> indexed)
      : pixels(std::move(indexed)),
        dataset{vectors, &pixels},
        tree(vectors.dimension, dataset, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
};

ProjectedNeighborhoodIndex::ProjectedNeighborhoodIndex(const PixelVectors& vectors, std::vector<std::int32_t> pixels,
                                                       float epsilon)
    : epsilon_(epsilon) {
  if (vectors.pixelCount() <= 0 || vectors.dimension <= 0 || vectors.data == nullptr)
    throw ParameterError("vectors", "the index needs at least one vector of dimension >= 1");
  if (!(epsilon >= 0.0f)) throw ParameterError("epsilon", "must be >= 0");
  if (pixels.empty()) {
    pixels.resize(std::size_t(vectors.pixelCount()));
    std::iota(pixels.begin(), pixels.end(), 0);
  }
  for (std::int32_t pixel : pixels)
    if (pixel < 0 || pixel >= vectors.pixelCount()) throw ParameterError("pixels", "holds a pixel outside the vectors");
  tree_ = std::make_unique<Tree>(vectors, std::move(pixels));
}

ProjectedNeighborhoodIndex::~ProjectedNeighborhoodIndex() = default;

std::int32_t ProjectedNeighborhoodIndex::nearest(const float* query) const {
  NearestResult result;
  tree_->tree.findNeighbors(result, query, nanoflann::SearchParams(32, epsilon_));
  return tree_->pixels[result.index()];
}

void ProjectedNeighborhoodIndex::nearest(const float* query, int k, std::vector<std::int32_t>& out) const {
  std::vector<std::uint32_t> indices(std::size_t(std::max(k, 1)));
  std::vector<float> distances(indices.size());
  nanoflann::KNNResultSet<float, std::uint32_t> result{indices.size()};
  result.init(indices.data(), distances.data());
  tree_->tree.findNeighbors(result, query, nanoflann::SearchParams(32, epsilon_));
  out.clear();
  for (std::size_t i = 0; i < result.size(); ++i) out.push_back(tree_->pixels[indices[i]]);
}

}  // namespace texsynth
