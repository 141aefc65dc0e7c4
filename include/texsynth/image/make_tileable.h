#pragma once
// Automatic tileable conversion for exemplars whose opposite borders do not match (the paper
// does this by hand: offset by half and hide the seams with a clone stamp).
//
// Per axis, the last `overlap` columns (rows) are laid over the first ones and joined along the
// minimum-error boundary cut (dynamic programming through the overlap, as in image quilting),
// lightly feathered. Left of the cut the pixels come from the image's far end, so the new wrap
// edge joins pixels that were neighbours in the original: the wrap becomes seamless and the
// only seam left is the cut, which follows where the two strips already agree. The result is
// smaller by the overlap along each axis. Nothing is ghosted except within the feather.
#include "texsynth/core/image.h"

namespace texsynth {

struct MakeTileableOptions {
  float overlapFraction = 0.15f;  // overlap as a fraction of each side (0 < f <= 0.5)
  int featherRadius = 1;          // pixels cross-faded on each side of the cut (>= 0)
};

// Throws ParameterError("exemplar", ...) if too small for the overlap (each overlap must be at
// least 2 * featherRadius + 3 pixels), ("overlapFraction" / "featherRadius", ...) for bad options.
Image makeTileable(const Image& exemplar, const MakeTileableOptions& options = {});

// How visible the wrap-around seams are.
struct SeamStrength {
  double wrap = 0;      // mean |difference| across the wrap edges (last vs first column and row)
  double interior = 0;  // mean |difference| between adjacent pixels inside the image
  // wrap / interior: about 1 for a tileable image, well above 1 where tiling shows seams.
  double ratio() const { return interior > 0 ? wrap / interior : 0.0; }
};
SeamStrength measureSeams(const Image& image);

}  // namespace texsynth
