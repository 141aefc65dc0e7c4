// Dependency planning against the history windows: the block plans a level synthesizes hold
// every voxel (at every step) that the windows say the delivered voxels depend on, and under
// grid correction the dependent set stops growing with the number of passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "texsynth/solid/lazy_blocks.h"

namespace texsynth {
namespace {

using lazy::BlockKey;

const std::vector<BlockKey> kDeliver = {lazy::blockKey(0, 0, 0), lazy::blockKey(3, -1, 2)};

std::vector<Vec3i> voxelsOf(const std::vector<BlockKey>& blocks) {
  std::vector<Vec3i> voxels;
  for (BlockKey key : blocks)
    for (int slot = 0; slot < lazy::kBlockVoxels; ++slot)
      voxels.push_back(lazy::blockIndex(key) * lazy::kB +
                       Vec3i(slot % lazy::kB, slot / lazy::kB % lazy::kB, slot / (lazy::kB * lazy::kB)));
  return voxels;
}

bool holds(const std::vector<BlockKey>& sortedBlocks, const Vec3i& voxel) {
  return std::binary_search(sortedBlocks.begin(), sortedBlocks.end(), lazy::blockOfVoxel(voxel));
}

LazySolidOptions options(int passes) {
  LazySolidOptions o;
  o.passes = passes;
  o.subpassGrid = 2;
  o.gridCellSize = 6;
  return o;
}

TEST(LazyDependencies, StandardPlanHoldsWhatTheWindowsNeedAfterEveryStep) {
  const int radius = 2;
  const lazy::LevelSchedule schedule = lazy::levelSchedule(options(2), 1, false);
  std::vector<int> classes;
  for (const lazy::CorrectionStep& step : schedule.steps) classes.push_back(step.voxelClass);
  const lazy::LazyDependencyPlan plan = lazy::planLevel(kDeliver, classes, radius);
  const auto needed = lazy::windowDependencies(schedule, voxelsOf(kDeliver), radius);
  ASSERT_EQ(needed.size(), plan.layers.size());
  for (std::size_t k = 0; k < needed.size(); ++k)
    for (const Vec3i& v : needed[k])
      ASSERT_TRUE(holds(plan.layers[k], v)) << "step " << k << " voxel " << v.transpose();
  // The plan rounds the exact region up to blocks, no further: it is at most one block per
  // side (and step layer) larger.
  std::set<BlockKey> exactBlocks;
  for (const Vec3i& v : needed[0]) exactBlocks.insert(lazy::blockOfVoxel(v));
  EXPECT_LE(plan.layers[0].size(), exactBlocks.size() * 2);
}

TEST(LazyDependencies, GridPlanHoldsWhatTheWindowsNeedAndEachPhaseCorrectsOnlyPlannedCells) {
  const int radius = 2, m = 6;
  const lazy::LevelSchedule schedule = lazy::levelSchedule(options(3), 1, true);  // 2 primary passes, 1 dual
  const lazy::LazyDependencyPlan plan = lazy::planGridLevel(kDeliver, m, radius, true);
  const auto needed = lazy::windowDependencies(schedule, voxelsOf(kDeliver), radius);
  for (const auto& state : needed)
    for (const Vec3i& v : state) ASSERT_TRUE(holds(plan.layers.front(), v)) << v.transpose();
  // The voxels step k corrects (needed after it, of its class) lie in the phase's planned cells.
  for (std::size_t k = 0; k < schedule.steps.size(); ++k) {
    const lazy::CorrectionStep& step = schedule.steps[k];
    const std::vector<BlockKey>& cells = step.gridPhase == 0 ? plan.primaryCells : plan.dualCells;
    for (const Vec3i& v : needed[k + 1]) {
      if (subpassClassOf(v, 2) != step.voxelClass) continue;
      const BlockKey cell = lazy::blockKey(lazy::floorDiv(v.x() + step.shift, m), lazy::floorDiv(v.y() + step.shift, m),
                                           lazy::floorDiv(v.z() + step.shift, m));
      ASSERT_TRUE(std::binary_search(cells.begin(), cells.end(), cell)) << "step " << k << " voxel " << v.transpose();
    }
  }
}

TEST(LazyDependencies, GridDependentSetDoesNotGrowWithPasses) {
  const int radius = 2;
  const auto upsampled = [&](int passes, bool grid) {
    return lazy::windowDependencies(lazy::levelSchedule(options(passes), 1, grid), {Vec3i(1, 2, 3)}, radius)
        .front()
        .size();
  };
  // Grid: two more primary passes and one more dual pass add nothing (the cells bound it).
  EXPECT_EQ(upsampled(3, true), upsampled(6, true));
  // The standard scheme grows with every pass.
  EXPECT_GT(upsampled(3, false), upsampled(2, false));
  EXPECT_LT(upsampled(3, true), upsampled(3, false));
}

}  // namespace
}  // namespace texsynth
