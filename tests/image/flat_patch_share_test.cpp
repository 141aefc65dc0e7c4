// The flat-patch share: about a tenth for the exemplar itself, everything for one color.
#include "texsynth/image/flat_patch_share.h"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "image_test_support.h"
#include "test_support.h"

namespace texsynth {
namespace {

TEST(FlatPatchShare, ReadsATenthForTheExemplarAndAllForOneColor) {
  auto path = gimpPattern("Stone/cracked.pat");
  const Image exemplar = path ? test::loadPatternRgb(*path, 1024) : test::makeTestPattern(64, 64);
  AnalysisOptions options;
  options.levelCount = 2;
  const ExemplarAnalysis analysis = analyzeExemplar(exemplar, options);
  const detail::FlatPatchShare flatness(analysis.levels.back(), analysis.colorChannels);
  EXPECT_GT(flatness.threshold(), 0.0);
  // The exemplar copied onto a torus of its own size: its patches, sampled every other pixel.
  std::vector<std::int32_t> copy(std::size_t(exemplar.width) * exemplar.height);
  std::iota(copy.begin(), copy.end(), 0);
  const double copied = flatness.of(copy, exemplar.width, exemplar.height);
  EXPECT_GT(copied, 0.05);
  EXPECT_LT(copied, 0.2);
  const std::vector<std::int32_t> oneColor(copy.size(), 17);
  EXPECT_EQ(flatness.of(oneColor, exemplar.width, exemplar.height), 1.0);
}

}  // namespace
}  // namespace texsynth
