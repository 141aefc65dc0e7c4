#pragma once
// Crossbar vectors of an exemplar and nearest-crossbar search. A pixel's u-row and v-column are the
// N samples `spacing` apart through it along each image axis: where two orthogonal slices of a solid
// meet, one slice's row or column must equal the other's (a crossbar). The vectors are projected on
// a PCA basis shared by every image indexed together, so rows of one image compare with columns of
// another, and searched with KD-trees (nanoflann): rows, columns, and both at once (the joint index:
// the leading dimensions of the row, then of the column).
// Used by the candidate triples of lazy solids and by gradient-solid synthesis's crossbar matching.
#include <cstdint>
#include <memory>
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth {

class CrossbarIndex {
 public:
  // Gathers every pixel's row and column (toroidal); index() must follow before any search.
  CrossbarIndex(const Image& image, int spacing, int size);
  ~CrossbarIndex();
  CrossbarIndex(const CrossbarIndex&) = delete;
  CrossbarIndex& operator=(const CrossbarIndex&) = delete;

  // Fits one PCA basis (at most `dimensions` axes) to the rows and columns of all `indices`, in order,
  // single-threaded in double (independent of the thread count), projects them and builds the trees.
  // `jointHalf`: leading dimensions of each crossbar in the joint index.
  static void indexTogether(const std::vector<CrossbarIndex*>& indices, int dimensions, int jointHalf);

  int dimension() const { return dimension_; }  // N * channels
  int reduced() const { return reduced_; }      // PCA dimensions
  int jointHalf() const { return jointHalf_; }
  const float* row(std::int32_t p) const { return &rows_[std::size_t(p) * dimension_]; }
  const float* column(std::int32_t p) const { return &columns_[std::size_t(p) * dimension_]; }
  const float* rowReduced(std::int32_t p) const { return &rowsReduced_[std::size_t(p) * reduced_]; }
  const float* columnReduced(std::int32_t p) const { return &columnsReduced_[std::size_t(p) * reduced_]; }
  // A raw row or column vector (N * channels floats) projected like the stored ones.
  void project(const float* vector, float* reduced) const;

  enum class Tree { Rows, Columns, Joint };
  // The (at most) k pixels nearest to `query` (reduced, or 2 * jointHalf for Joint) by L2, nearest first;
  // approximate with epsilon > 0 (nanoflann prunes within 1 + epsilon). Thread-safe.
  void nearest(Tree tree, const float* query, int k, float epsilon, std::vector<std::uint32_t>& out) const;

 private:
  struct Trees;
  int dimension_ = 0, reduced_ = 0, jointHalf_ = 0;
  std::vector<float> rows_, columns_, rowsReduced_, columnsReduced_, joint_;
  std::vector<float> mean_, basis_;  // dimension_; dimension_ x reduced_ (column-major)
  std::unique_ptr<Trees> trees_;
};

// The u-row and v-column through (x, y): N = `size` samples `spacing` apart, centred, toroidal.
void gatherCrossbars(const Image& image, int x, int y, int spacing, int size, float* row, float* column);

// L1 distance of two vectors in 8 interleaved partial sums added in a fixed tree: vectorizes, and gives
// the same float wherever it is used.
float crossbarL1(const float* a, const float* b, int dimension);

}  // namespace texsynth
