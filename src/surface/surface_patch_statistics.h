#pragma once
// Internal: the pieces of the surface quality (surface_quality.h) that look at whole patch
// distributions rather than at each vertex's nearest exemplar patch: flatness and completeness.
// Patches are RGB on 0..255, in PatchIndex's vector layout (rows, pixels, channels innermost).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/eval/patch_vector_index.h"
#include "texsynth/image/flat_patch_share.h"

namespace texsynth::surface_detail {

// The deviation (detail::patchDeviation) of a patch of `pixels` RGB pixels stored one after another.
inline double rgbPatchDeviation(const float* values, int pixels) {
  return detail::patchDeviation(pixels, 3, [&](int i) { return values + std::size_t(i) * 3; });
}

// The flatness threshold of an RGB 0..255 exemplar: the 10th-percentile deviation (the
// (n / 10)-th smallest, counting from 0) of its n patchSize x patchSize patches fully inside it,
// each resampled bilinearly at a sub-pixel offset hashed from its position (none along an axis
// where it touches the exemplar's edge), as a surface resamples its texture between vertices: so
// that a share of about 0.1 of the exemplar's own patches, resampled like a faithful surface copy
// of them, lies below it. (Unresampled patches would set the bar too high: resampling blurs, and
// a faithful surface copy of a fine texture such as GIMP's burlap would read 0.2-0.6 flat.)
double flatnessThreshold(const Image& exemplar255, int patchSize);

// Completeness: for each exemplar patch (all patches fully inside, or the first kCompletenessPatches
// of them in an order hashed from `seed`), the mean squared difference per value to its nearest
// surface patch, over all surface patches given to add() in any number of batches (exact: each
// batch is indexed in a PatchVectorIndex and searched only for patches nearer than the best so
// far); result() is the RMS over the exemplar patches.
class CompletenessSearch {
 public:
  static constexpr std::size_t kCompletenessPatches = 4096;

  CompletenessSearch(const Image& exemplar255, int patchSize, std::uint64_t seed);
  void add(std::span<const float> surfacePatches, std::size_t count);
  double result() const;

 private:
  PatchVectorIndex index_;
  std::vector<float> queries_;  // the exemplar patches, in PatchIndex's vector layout
  std::size_t count_ = 0;
  std::vector<double> best_;  // per exemplar patch: the nearest distance so far (infinity: none)
};

}  // namespace texsynth::surface_detail
