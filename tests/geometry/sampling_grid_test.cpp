// The shared sampling grid: the longest side gets `resolution` voxels, bad boxes and resolutions throw.
#include "texsynth/geometry/sampling_grid.h"

#include <gtest/gtest.h>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

TEST(SamplingGrid, FollowsTheLongestSide) {
  Box3f box;
  box.extend(Vec3f(-1.0f, 0.0f, 2.0f));
  box.extend(Vec3f(1.0f, 1.5f, 3.0f));
  EXPECT_EQ(samplingGridSize(box, 40), Vec3i(40, 30, 20));
  EXPECT_THROW(samplingGridSize(box, 0), ParameterError);
  EXPECT_THROW(samplingGridSize(Box3f{}, 8), ParameterError);
}

}  // namespace
}  // namespace texsynth
