#pragma once
// Gaussian stack (Lefebvre & Hoppe 2005): every level keeps the exemplar's full resolution;
// level l is filtered so that its samples at spacing h_l = 2^(L-1-l) correspond to level l of
// a Gaussian pyramid. Level 0 is the coarsest, level L-1 the unfiltered exemplar (h = 1).
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth {

struct GaussianStackOptions {
  // Number of levels L; 0 picks floor(log2(min(width, height))), the number of pyramid
  // levels of the exemplar (L&H 2005). Must not exceed that value (coarser levels would
  // sample at a spacing larger than half the exemplar).
  int levelCount = 0;
};

struct GaussianStack {
  std::vector<Image> levels;  // [0] coarsest ... [L-1] = exemplar itself

  int levelCount() const { return int(levels.size()); }
  // h_l = 2^(L-1-l): the exemplar spacing that neighborhoods use at level l.
  int spacing(int level) const { return 1 << (levelCount() - 1 - level); }
};

// The default level count for an exemplar of this size (at least 1).
int defaultStackLevelCount(int width, int height);

// Builds the stack by separable toroidal filtering with the 5-tap binomial kernel
// [1 4 6 4 1]/16 dilated to the spacing of the finer level ("a trous"), which is exactly
// the pyramid's reduce filter without the subsampling. The cumulative kernel at spacing h
// is a near-Gaussian with variance (h^2 - 1)/3. Filtering preserves each channel's mean.
// Throws ParameterError for an empty image or a bad level count.
GaussianStack buildGaussianStack(const Image& exemplar, const GaussianStackOptions& options = {});

// One separable toroidal pass of the dilated binomial kernel (taps at 0, +-spacing, +-2 spacing).
Image filterBinomialToroidal(const Image& image, int spacing);

}  // namespace texsynth
