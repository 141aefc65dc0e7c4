#include "texsynth/geometry/sampling_grid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "texsynth/core/error.h"

namespace texsynth {

Vec3i samplingGridSize(const Box3f& box, int resolution) {
  if (!box.valid() || !box.min.allFinite() || !box.max.allFinite())
    throw ParameterError("box", "must be a finite, non-empty box");
  const float longest = box.size().maxCoeff();
  if (!(longest > 0.0f)) throw ParameterError("box", "has zero extent");
  if (resolution < 1 || resolution > 4096)
    throw ParameterError("resolution", "must be in [1, 4096], got " + std::to_string(resolution));
  Vec3i size;
  for (int a = 0; a < 3; ++a) size[a] = std::max(1, int(std::lround(resolution * box.size()[a] / longest)));
  return size;
}

}  // namespace texsynth
