// History windows (§5.2-5.3): the standard, subpass and grid schemes as windows, their
// intersection, and the read tables a level's schedule gives its corrector.
#include "texsynth/solid/history_window.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "texsynth/solid/lazy_blocks.h"

namespace texsynth {
namespace {

constexpr int kOrder[8] = {0, 7, 1, 6, 2, 5, 4, 3};

template <typename F>
void forEachOffset(int radius, F&& f) {
  for (int z = -radius; z <= radius; ++z)
    for (int y = -radius; y <= radius; ++y)
      for (int x = -radius; x <= radius; ++x) f(Vec3i(x, y, z));
}

TEST(HistoryWindow, SideIsThePapersD) {
  // D = ceil(N sqrt 2): 13 for N = 9 (radius ceil(4 sqrt 2) = 6).
  EXPECT_EQ(HistoryWindow(6, 0).side(), 13);
  EXPECT_EQ(HistoryWindow(6, 0).versions().size(), 13u * 13u * 13u);
}

TEST(HistoryWindow, PlainPassReadsThePreviousVersionEverywhere) {
  const HistoryWindow w = passWindow(3, 2);
  EXPECT_TRUE(std::all_of(w.versions().begin(), w.versions().end(), [](std::int8_t v) { return v == 1; }));
}

TEST(HistoryWindow, SubpassReadsTheClassesAlreadyCorrectedInThisPass) {
  const Vec3i voxel(5, -2, 3);
  for (int subpass = 0; subpass < 8; ++subpass) {
    const HistoryWindow w = subpassWindow(2, 2, subpass, kOrder, 2, voxel);
    forEachOffset(2, [&](const Vec3i& o) {
      const int c = subpassClassOf(voxel + o, 2);
      const bool earlier = std::find(kOrder, kOrder + subpass, c) != kOrder + subpass;
      ASSERT_EQ(w.at(o), earlier ? 2 : 1) << "subpass " << subpass;
    });
  }
  // The first subpass is a plain pass; the voxel's own class is always read at pass - 1.
  EXPECT_EQ(subpassWindow(2, 1, 0, kOrder, 2, voxel), passWindow(2, 1));
  EXPECT_EQ(subpassWindow(2, 1, 5, kOrder, 2, voxel).at(Vec3i(2, 0, -2)), 0);  // class 5 = the voxel's
}

TEST(HistoryWindow, GridReadsTheLatestOnlyInsideTheOwnCell) {
  // M = 6, shift 3: cells [-3, 2], [3, 8], ... per axis. Voxel (4, 2, -3): x cell [3, 8],
  // y cell [-3, 2], z cell [-3, 2].
  const Vec3i voxel(4, 2, -3);
  const HistoryWindow w = gridWindow(3, 6, 3, 1, voxel);
  forEachOffset(3, [&](const Vec3i& o) {
    const Vec3i q = voxel + o;
    const bool inside = q.x() >= 3 && q.x() <= 8 && q.y() >= -3 && q.y() <= 2 && q.z() >= -3 && q.z() <= 2;
    ASSERT_EQ(w.at(o), inside ? HistoryWindow::kLatest : 1);
  });
}

TEST(HistoryWindow, IntersectionIsTheElementwiseMinimum) {
  const Vec3i voxel(1, 1, 0);
  const HistoryWindow s = subpassWindow(2, 2, 5, kOrder, 2, voxel), g = gridWindow(2, 4, 0, 0, voxel);
  const HistoryWindow both = s & g;
  forEachOffset(2, [&](const Vec3i& o) { ASSERT_EQ(both.at(o), std::min(s.at(o), g.at(o))); });
  EXPECT_EQ(both, g & s);
  // Intersecting with "latest everywhere" changes nothing: H_g ∩ H_s keeps the subpass order in the cell.
  EXPECT_EQ(s & HistoryWindow(2, HistoryWindow::kLatest), s);
}

LazySolidOptions scheduleOptions() {
  LazySolidOptions o;
  o.passes = 3;
  o.coarsestPasses = 2;
  o.subpassGrid = 2;
  o.gridCellSize = 6;
  return o;
}

TEST(LevelSchedule, StandardSchemeReadsOnlyCurrentState) {
  const lazy::LevelSchedule schedule = lazy::levelSchedule(scheduleOptions(), 0, false);
  ASSERT_EQ(schedule.steps.size(), 16u);  // the coarsest level's 2 passes x 8 subpasses
  for (std::size_t k = 0; k < schedule.steps.size(); ++k) {
    EXPECT_EQ(schedule.steps[k].pass, int(k) / 8 + 1);
    EXPECT_EQ(schedule.steps[k].voxelClass, kOrder[k % 8]);
    const lazy::StepReads reads = lazy::stepReads(schedule, k, 3);
    EXPECT_TRUE(reads.snapshotVersions.empty());
    const std::int8_t* table = reads.sourcesFor(Vec3i(kOrder[k % 8] & 1, kOrder[k % 8] >> 1 & 1, kOrder[k % 8] >> 2));
    EXPECT_TRUE(std::all_of(table, table + 7 * 7 * 7, [](std::int8_t v) { return v == -1; }));
  }
}

TEST(LevelSchedule, DualGridReadsThePhaseStartOutsideTheCell) {
  const lazy::LevelSchedule schedule = lazy::levelSchedule(scheduleOptions(), 1, true);
  ASSERT_EQ(schedule.steps.size(), 24u);  // 2 primary passes, then 1 dual, 8 subpasses each
  for (std::size_t k = 0; k < schedule.steps.size(); ++k) {
    const lazy::CorrectionStep& step = schedule.steps[k];
    const bool dual = k >= 16;
    EXPECT_EQ(step.gridPhase, dual ? 1 : 0);
    EXPECT_EQ(step.shift, dual ? 3 : 0);
    const lazy::StepReads reads = lazy::stepReads(schedule, k, 3);
    EXPECT_EQ(reads.period, 6);
    // Outside the cell a step reads the phase's start (the upsampled or the primary result); it
    // needs a snapshot only where that is older than what the neighbour holds by then: not in
    // a phase's first step, when nothing has moved yet.
    const bool phaseBegins = k == 0 || k == 16;
    EXPECT_EQ(reads.snapshotVersions, phaseBegins ? std::vector<int>{} : std::vector<int>{step.startVersion});
    EXPECT_EQ(step.startVersion, dual ? 2 : 0);
    // A voxel of the step's class near the high border of its cell (primary [0, 5], dual [3, 8]).
    Vec3i voxel(step.voxelClass & 1, step.voxelClass >> 1 & 1, step.voxelClass >> 2 & 1);
    voxel += Vec3i::Constant(dual ? 6 : 4);
    const HistoryWindow window = schedule.window(k, voxel, 3), latest = schedule.latest(k, voxel, 3);
    const std::int8_t* table = reads.sourcesFor(voxel);
    forEachOffset(3, [&](const Vec3i& o) {
      const std::int8_t expected = window.at(o) == latest.at(o) ? -1 : window.at(o);
      ASSERT_EQ(table[window.indexOf(o)], expected);
    });
    EXPECT_EQ(window.at(Vec3i(3, 3, 3)), step.startVersion);  // across the border
    EXPECT_EQ(window.at(Vec3i(0, 0, 0)), step.pass - 1);      // itself, inside: the latest
  }
}

}  // namespace
}  // namespace texsynth
