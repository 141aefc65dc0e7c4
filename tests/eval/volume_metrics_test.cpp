// evaluateVolume: slices along each axis.
#include <gtest/gtest.h>

#include "eval_test_images.h"
#include "test_support.h"
#include "texsynth/eval/metrics.h"

namespace texsynth {
namespace {

// A volume whose slices normal to `axis` all equal `image` (u, v as documented in metrics.h).
Volume stacked(const Image& image, int axis, int depth) {
  const int nx = axis == 0 ? depth : image.width;
  const int ny = axis == 0 ? image.width : axis == 1 ? depth : image.height;
  const int nz = axis == 2 ? depth : image.height;
  Volume volume(nx, ny, nz, image.channels);
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const int u = axis == 0 ? y : x, v = axis == 2 ? y : z;
        for (int c = 0; c < image.channels; ++c) volume.at(x, y, z, c) = image.at(u, v, c);
      }
  return volume;
}

void expectSame(const QualityMetrics& a, const QualityMetrics& b) {
  EXPECT_DOUBLE_EQ(a.coherence, b.coherence);
  EXPECT_DOUBLE_EQ(a.completeness, b.completeness);
  EXPECT_DOUBLE_EQ(a.histogram, b.histogram);
  EXPECT_DOUBLE_EQ(a.periodicity, b.periodicity);
  EXPECT_DOUBLE_EQ(a.lattice, b.lattice);
}

TEST(EvaluateVolume, StackedImageMatchesImageMetricsAlongTheStackingAxis) {
  Image big = test::makeTestPattern(80, 80, 3);
  Image exemplar = big.crop(0, 0, 40, 40);
  Image output = big.crop(6, 4, 40, 36);  // mostly overlaps the exemplar
  const QualityMetrics image = evaluateImage(exemplar, output);
  for (int axis = 0; axis < 3; ++axis) {
    SCOPED_TRACE(axis);
    VolumeQuality q = evaluateVolume(exemplar, stacked(output, axis, 24), {.slicesPerAxis = 3});
    expectSame(q.axis[axis], image);
    // Across the stacking axis slices are streaks: much less like the exemplar.
    EXPECT_GT(q.axis[(axis + 1) % 3].coherence, 2 * image.coherence);
    EXPECT_NEAR(q.mean.coherence, (q.axis[0].coherence + q.axis[1].coherence + q.axis[2].coherence) / 3, 1e-9);
    EXPECT_GE(q.mean.seconds, q.axis[axis].seconds);
  }
}

TEST(EvaluateVolume, RejectsBadInput) {
  Image exemplar = test::makeTestPattern(20, 20);
  Volume volume(20, 20, 3, 3);
  EXPECT_THROW(evaluateVolume(exemplar, volume, {.slicesPerAxis = 4}), ParameterError);  // only 3 along z
  EXPECT_THROW(evaluateVolume(exemplar, Volume()), ParameterError);
  EXPECT_THROW(evaluateVolume(exemplar, Volume(20, 5, 20, 3)), ParameterError);  // slices smaller than a patch
  EXPECT_THROW(evaluateVolume(Image(5, 5, 3), Volume(20, 20, 20, 3)), ParameterError);
  EXPECT_THROW(evaluateVolume(exemplar, Volume(20, 20, 20, 3), {.patchSize = 4}), ParameterError);
}

}  // namespace
}  // namespace texsynth
