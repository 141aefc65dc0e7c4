// A level's correction schedule as history windows (§5.2-5.3), and the read tables the
// corrector uses: per voxel type, which version of each neighbour it reads.
#include <algorithm>
#include <numeric>

#include "texsynth/core/error.h"
#include "texsynth/core/wrap.h"
#include "texsynth/solid/lazy_blocks.h"

namespace texsynth::lazy {
namespace {

// The s^3 voxel classes (bits x | y << 1 | z << 2) in an order that alternates far-apart
// classes, as L&H's 2D order alternates diagonals; s = 1: one step over all voxels.
std::vector<int> subpassOrder(int s) {
  if (s == 1) return {-1};
  return {0, 7, 1, 6, 2, 5, 4, 3};
}

}  // namespace

LevelSchedule levelSchedule(const LazySolidOptions& options, int level, bool grid) {
  LevelSchedule schedule;
  schedule.s = options.subpassGrid;
  schedule.classOrder = subpassOrder(schedule.s);
  const int passes = level == 0 ? options.coarsestPasses : options.passes;
  const int primaryPasses = (passes + 1) / 2;
  for (int pass = 1; pass <= passes; ++pass)
    for (std::size_t j = 0; j < schedule.classOrder.size(); ++j) {
      CorrectionStep step;
      step.pass = pass;
      step.subpass = int(j);
      step.voxelClass = schedule.classOrder[j];
      if (grid) {
        const bool dual = pass > primaryPasses;
        step.gridPhase = dual ? 1 : 0;
        step.cellSize = options.gridCellSize;
        step.shift = dual ? options.gridCellSize / 2 : 0;
        step.startVersion = dual ? primaryPasses : 0;  // the dual phase starts from the primary's result
      }
      schedule.steps.push_back(step);
    }
  return schedule;
}

HistoryWindow LevelSchedule::latest(std::size_t k, const Vec3i& voxel, int radius) const {
  const CorrectionStep& step = steps[k];
  if (s == 1) return passWindow(radius, step.pass);
  return subpassWindow(radius, step.pass, step.subpass, classOrder, s, voxel);
}

HistoryWindow LevelSchedule::window(std::size_t k, const Vec3i& voxel, int radius) const {
  const CorrectionStep& step = steps[k];
  HistoryWindow window = latest(k, voxel, radius);
  if (step.gridPhase >= 0) window.intersect(gridWindow(radius, step.cellSize, step.shift, step.startVersion, voxel));
  return window;
}

int LevelSchedule::period(std::size_t k) const {
  const CorrectionStep& step = steps[k];
  return step.gridPhase >= 0 ? std::lcm(s, step.cellSize) : s;
}

const std::int8_t* StepReads::sourcesFor(const Vec3i& voxel) const {
  const int type =
      (wrapIndex(voxel.z(), period) * period + wrapIndex(voxel.y(), period)) * period + wrapIndex(voxel.x(), period);
  return sources[std::size_t(type)].data();
}

StepReads stepReads(const LevelSchedule& schedule, std::size_t k, int radius) {
  StepReads reads;
  reads.radius = radius;
  reads.period = schedule.period(k);
  reads.s = schedule.s;
  reads.voxelClass = schedule.steps[k].voxelClass;
  const int period = reads.period;
  reads.sources.resize(std::size_t(period * period * period));
  for (int z = 0; z < period; ++z)
    for (int y = 0; y < period; ++y)
      for (int x = 0; x < period; ++x) {
        const Vec3i voxel(x, y, z);
        if (reads.voxelClass >= 0 && subpassClassOf(voxel, reads.s) != reads.voxelClass) continue;
        const HistoryWindow window = schedule.window(k, voxel, radius);
        const HistoryWindow latest = schedule.latest(k, voxel, radius);
        std::vector<std::int8_t>& table = reads.sources[std::size_t((z * period + y) * period + x)];
        table.resize(window.versions().size());
        for (std::size_t i = 0; i < table.size(); ++i) {
          const std::int8_t version = window.versions()[i];
          TS_CHECK(version <= latest.versions()[i]);  // a window never reads a version not yet made
          table[i] = version == latest.versions()[i] ? std::int8_t(-1) : version;
          if (table[i] >= 0 &&
              !std::binary_search(reads.snapshotVersions.begin(), reads.snapshotVersions.end(), version))
            reads.snapshotVersions.insert(
                std::upper_bound(reads.snapshotVersions.begin(), reads.snapshotVersions.end(), int(version)), version);
        }
      }
  return reads;
}

std::vector<std::vector<Vec3i>> windowDependencies(const LevelSchedule& schedule, const std::vector<Vec3i>& deliver,
                                                   int radius) {
  const std::size_t steps = schedule.steps.size(), perPass = schedule.classOrder.size();
  // Voxels packed as block keys of their coordinates (|v| < 2^20).
  std::vector<std::vector<BlockKey>> needed(steps + 1);
  for (const Vec3i& v : deliver) needed[steps].push_back(blockKey(v.x(), v.y(), v.z()));
  const auto sortUnique = [](std::vector<BlockKey>& keys) {
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  };
  for (std::size_t k = steps; k >= 1; --k) {
    sortUnique(needed[k]);
    const std::size_t step = k - 1;
    const int voxelClass = schedule.steps[step].voxelClass;
    for (BlockKey key : needed[k]) {
      const Vec3i v = blockIndex(key);
      if (voxelClass >= 0 && subpassClassOf(v, schedule.s) != voxelClass) {
        needed[k - 1].push_back(key);
        continue;
      }
      const HistoryWindow window = schedule.window(step, v, radius), latest = schedule.latest(step, v, radius);
      for (int z = -radius; z <= radius; ++z)
        for (int y = -radius; y <= radius; ++y)
          for (int x = -radius; x <= radius; ++x) {
            const Vec3i offset(x, y, z), q = v + offset;
            const int version = window.at(offset);
            const std::size_t state = version == latest.at(offset) ? k - 1 : std::size_t(version) * perPass;
            needed[state].push_back(blockKey(q.x(), q.y(), q.z()));
          }
    }
  }
  sortUnique(needed[0]);
  std::vector<std::vector<Vec3i>> voxels(steps + 1);
  for (std::size_t k = 0; k <= steps; ++k)
    for (BlockKey key : needed[k]) voxels[k].push_back(blockIndex(key));
  return voxels;
}

}  // namespace texsynth::lazy
