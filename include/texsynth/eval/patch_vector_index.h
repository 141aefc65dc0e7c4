#pragma once
// Exact nearest-neighbour search among given patch vectors: patches that do not come from one
// image (resampled on a surface, say), searched with PatchIndex's machinery. The vectors are
// rotated into the PCA basis of the patches of a basis image (any orthonormal basis keeps every
// distance; one fitted to patches like the indexed ones prunes best, such as the exemplar for
// patches of a texture synthesized from it) and put in the same exact KD-tree. Search in float
// picks the neighbour, ties (within float rounding) go to the lowest vector index, and the
// reported distance is recomputed in double, so results never depend on the order of queries
// or the thread count.
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/eval/patch_index.h"

namespace texsynth {

class PatchVectorIndex {
 public:
  // An index of no vectors yet, for patchSize x patchSize patches with basisImage.channels
  // channels, rotated by the PCA of the patches of `basisImage` (fitted once, kept by assign).
  // Throws ParameterError("patchSize" / "image", ...) if patchSize is not positive or the image
  // is smaller than a patch.
  PatchVectorIndex(const Image& basisImage, int patchSize);
  ~PatchVectorIndex();
  PatchVectorIndex(PatchVectorIndex&&) noexcept;
  PatchVectorIndex& operator=(PatchVectorIndex&&) noexcept;

  int patchSize() const;
  int dimensions() const;    // values per vector: patchSize * patchSize * channels
  std::size_t size() const;  // vectors given to assign (duplicates included)

  // Indexes `count` vectors (count * dimensions() floats, each in PatchIndex's vector layout:
  // rows top to bottom, pixels left to right, channels innermost) in place of the previous ones.
  // Exact duplicates are indexed once, under their lowest index (where ties go anyway), so a
  // cluster of equal vectors (patches of a one-color surface) costs one comparison, not a scan.
  // Throws ParameterError("vectors", ...) when the sizes do not fit, count is 0, or a value is
  // not finite.
  void assign(std::span<const float> vectors, std::size_t count);

  // As PatchIndex::nearestVectors, with PatchMatch::index the indexed vector's number: the
  // nearest indexed vector of each of `count` query vectors, optionally only within the
  // per-query `limits` (index -1 and infinity when none is). Each block of queries starts its
  // search from its previous query's match (neighbouring patches of an image, listed in order,
  // tend to share near matches); that only tightens pruning, never changes a result. Throws
  // ParameterError("queries" / "limits", ...) for bad sizes or values, or an empty index.
  std::vector<PatchMatch> nearestVectors(std::span<const float> queries, std::size_t count,
                                         std::span<const double> limits = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace texsynth
