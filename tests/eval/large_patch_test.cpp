// Large patches on small images and volume slices: a patch that fits no slice is refused before
// any work, and few patches of many dimensions are searched in raw coordinates (a PCA of a
// 1323-dimensional covariance per slice took most of a minute) with the same exact results.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>

#include "eval_test_images.h"
#include "test_support.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/eval/patch_index.h"

namespace texsynth {
namespace {
using test::makeTestPattern;
using test::scaled;

// Counts what evaluateVolume reports.
class CountingProgress : public Progress {
 public:
  void begin(const std::string&, std::int64_t total) override { totals += total; }
  void advance(std::int64_t units) override { done += units; }
  void end() override {}
  std::int64_t totals = 0;
  std::atomic<std::int64_t> done = 0;
};

// A volume whose every z slice is `image` (nz deep).
Volume stackedAlongZ(const Image& image, int nz) {
  Volume volume(image.width, image.height, nz, image.channels);
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int c = 0; c < image.channels; ++c) volume.at(x, y, z, c) = image.at(x, y, c);
  return volume;
}

TEST(LargePatches, FewPatchesOfManyDimensionsStillMatchExactly) {
  // 10x10 patches of 15x15 RGB (675 dimensions) against 14x14 queries: raw coordinates.
  const Image reference = scaled(makeTestPattern(24, 24, 3), 255);
  const Image queries = scaled(makeTestPattern(28, 26, 7), 255);
  const int size = 15;
  PatchIndex index(reference, size);
  const std::vector<PatchMatch> found = index.nearest(queries);
  const int columns = queries.width - size + 1;
  for (std::size_t q = 0; q < found.size(); ++q) {
    const int qx = int(q % columns), qy = int(q / columns);
    double best = std::numeric_limits<double>::infinity();
    for (int y = 0; y < index.rows(); ++y)
      for (int x = 0; x < index.columns(); ++x)
        best = std::min(best, PatchIndex::meanSquaredDifference(queries, qx, qy, reference, x, y, size));
    EXPECT_NEAR(found[q].meanSquared, best, 1e-9 * (1 + best)) << "query " << q;
  }
  // A patch of the reference is found at distance 0, also by radius.
  const std::vector<PatchMatch> self = index.nearest(reference);
  for (std::size_t i = 0; i < self.size(); ++i) EXPECT_EQ(self[i].meanSquared, 0.0);
  EXPECT_EQ(index.within(reference, 3, 4, 0.0), std::vector<int>{4 * index.columns() + 3});
}

TEST(LargePatches, PatchLargerThanTheSlicesIsRefusedBeforeIndexingTheExemplar) {
  const Image exemplar = makeTestPattern(96, 96, 2);  // 33x33 patches: minutes of PCA before
  const Volume volume(32, 32, 40, 3, 0.5f);
  CountingProgress progress;
  try {
    evaluateVolume(exemplar, volume, {.patchSize = 33}, progress);
    ADD_FAILURE() << "a 33-voxel patch was accepted on 32x32 slices";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.parameter(), "patchSize");
    EXPECT_NE(e.problem().find("32x40 slices normal to x of the 32x32x40 volume"), std::string::npos) << e.problem();
    EXPECT_NE(e.problem().find("at most 31"), std::string::npos) << e.problem();
  }
  EXPECT_EQ(progress.totals, 0) << "work began before the check";
}

// (Before raw coordinates this took over a minute, a PCA per slice; now half a second.)
TEST(LargePatches, VolumeWithLargePatchesOnSmallSlicesIsEvaluated) {
  // 21x21 patches on 32x32 slices: 144 patches of 1323 dimensions per slice.
  const Image exemplar = makeTestPattern(48, 48, 4);
  const Volume volume = stackedAlongZ(makeTestPattern(32, 32, 5), 32);
  const VolumeQuality q = evaluateVolume(exemplar, volume, {.patchSize = 21, .slicesPerAxis = 2});
  EXPECT_GT(q.mean.coherence, 0.0);
  EXPECT_TRUE(std::isfinite(q.mean.completeness));
}

TEST(LargePatches, VolumeEvaluationReportsEverySlice) {
  CountingProgress progress;
  evaluateVolume(makeTestPattern(20, 20), Volume(12, 12, 12, 3, 0.5f), {.patchSize = 5, .slicesPerAxis = 3}, progress);
  EXPECT_EQ(progress.totals, 1 + 3 * 3);  // indexing the exemplar, then nine slices
  EXPECT_EQ(progress.done, progress.totals);
}

TEST(LargePatches, NonFiniteVoxelIsAnErrorAboutTheVolume) {
  Volume volume(12, 12, 12, 3, 0.5f);
  volume.at(2, 3, 4, 1) = std::nanf("");
  test::expectParameterError([&] { evaluateVolume(makeTestPattern(20, 20), volume); }, "volume");
}

}  // namespace
}  // namespace texsynth
