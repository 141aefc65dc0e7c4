#pragma once
// Exact nearest-neighbour search among all square patches of an image.
//
// Every patch fully inside the image becomes a vector of patchSize*patchSize*channels values.
// The vectors are rotated into the PCA basis of the indexed patches: an orthonormal rotation
// keeps every distance, but puts most of the variance into the first coordinates, so an exact
// KD-tree split on those coordinates prunes well and partial distances (summed in PCA order)
// can stop early against the best match so far. With few patches of many values (large patches
// on a small image) the PCA would cost more than searching every patch, so the raw values are
// used instead: as exact, pruned less. Queries start from a guess propagated from
// their left (or upper) neighbour's match, which makes that bound tight from the start.
// Search in float picks the neighbour; the reported distance is recomputed in double from
// the pixels. Ties (within float rounding) go to the lowest patch index, so results never
// depend on the order of queries, the guesses, or the thread count.
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth {

struct PatchMatch {
  int index = -1;          // patch index in the indexed image: y * columns + x (top-left corner)
  double meanSquared = 0;  // squared distance divided by the patch's value count
};

class PatchIndex {
 public:
  // Indexes every patchSize×patchSize patch of `image`. Throws ParameterError if patchSize is
  // not positive or the image is smaller than a patch.
  PatchIndex(const Image& image, int patchSize);
  ~PatchIndex();
  PatchIndex(PatchIndex&&) noexcept;
  PatchIndex& operator=(PatchIndex&&) noexcept;

  int patchSize() const;
  int columns() const;  // patch positions per row: width - patchSize + 1
  int rows() const;     // height - patchSize + 1
  std::size_t size() const { return std::size_t(columns()) * rows(); }
  const Image& image() const;

  // The nearest indexed patch of every patch fully inside `queries` (same channel count),
  // in row-major order of the query patch positions. Runs in parallel over fixed blocks.
  std::vector<PatchMatch> nearest(const Image& queries) const;

  // The nearest indexed patch of each of `count` query vectors given as raw values: `queries`
  // holds count * patchSize * patchSize * channels floats, each vector in the layout of an
  // indexed patch (rows top to bottom, pixels left to right, channels innermost) and in the same
  // units as the indexed image. For patches that come from elsewhere (resampled on a surface,
  // transformed). The same exact search as nearest(), without guesses; the distance is recomputed
  // in double. `limits` is empty or has one mean squared difference per query: then only a patch
  // within the limit is looked for, and a query with none gets index -1 and meanSquared infinity
  // (one a hair past the limit may still be reported). A tight limit (the best distance so far
  // over several variants of a patch) prunes most of the search. Runs in parallel over fixed
  // blocks; ties go to the lowest patch index. Throws ParameterError("queries" / "limits", ...)
  // when the sizes do not fit or a value is not finite (limits may be +infinity, not negative).
  std::vector<PatchMatch> nearestVectors(std::span<const float> queries, std::size_t count,
                                         std::span<const double> limits = {}) const;

  // Indices (ascending) of all indexed patches whose mean squared difference to the patch of
  // `image` at top-left (x, y) is at most `limit`.
  std::vector<int> within(const Image& image, int x, int y, double limit) const;

  // Mean squared difference per value between two patches given by their top-left corners.
  static double meanSquaredDifference(const Image& a, int ax, int ay, const Image& b, int bx, int by, int patchSize);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace texsynth
