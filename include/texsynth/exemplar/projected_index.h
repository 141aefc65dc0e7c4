#pragma once
// Nearest exemplar neighborhood to an arbitrary query in a level's PCA space: a KD-tree
// (nanoflann) over the projected neighborhoods the analysis stored. The tree-search M-step of
// least-squares texture optimization (Kwatra et al. 2005 search a KD-tree the same way);
// k-coherence solvers need no tree.
#include <cstdint>
#include <memory>
#include <vector>

#include "texsynth/exemplar/similarity_sets.h"

namespace texsynth {

class ProjectedNeighborhoodIndex {
 public:
  // `vectors` must outlive the index. `pixels`: the pixels to index (empty = all of them).
  // epsilon: nanoflann's approximation factor (0 = exact).
  explicit ProjectedNeighborhoodIndex(const PixelVectors& vectors, std::vector<std::int32_t> pixels = {},
                                      float epsilon = 0.0f);
  ~ProjectedNeighborhoodIndex();
  ProjectedNeighborhoodIndex(const ProjectedNeighborhoodIndex&) = delete;
  ProjectedNeighborhoodIndex& operator=(const ProjectedNeighborhoodIndex&) = delete;

  // The pixel whose vector is nearest to query[dimension] (ties: the lower index). Thread-safe.
  std::int32_t nearest(const float* query) const;
  // The (at most) k nearest pixels, nearest first (approximate as the index's epsilon). Thread-safe.
  void nearest(const float* query, int k, std::vector<std::int32_t>& out) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
  float epsilon_;
};

}  // namespace texsynth
