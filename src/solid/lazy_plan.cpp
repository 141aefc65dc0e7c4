// Dependency planning of lazy solid synthesis: which 4^3 blocks each correction step of a level
// must produce so that the delivered blocks are exact (the standard pass/subpass scheme).
#include <algorithm>

#include "texsynth/core/error.h"
#include "texsynth/solid/lazy_blocks.h"

namespace texsynth::lazy {
namespace {

void sortUnique(std::vector<BlockKey>& keys) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}

// Grows a block set by `radius` blocks along each axis in turn (separable, so the cost is
// 3 * (2 radius + 1) inserts per block rather than (2 radius + 1)^3).
std::vector<BlockKey> dilate(const std::vector<BlockKey>& keys, int radius) {
  std::vector<BlockKey> current = keys;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<BlockKey> next;
    next.reserve(current.size() * std::size_t(2 * radius + 1));
    for (BlockKey key : current) {
      const Vec3i b = blockIndex(key);
      for (int d = -radius; d <= radius; ++d) {
        Vec3i n = b;
        n[axis] += d;
        next.push_back(blockKey(n.x(), n.y(), n.z()));
      }
    }
    sortUnique(next);
    current = std::move(next);
  }
  return current;
}

}  // namespace

WorkSet::WorkSet(std::vector<BlockKey> sortedKeys) : keys(std::move(sortedKeys)), blocks(keys.size()) {
  index.reserve(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    index.emplace(keys[i], std::int32_t(i));
    blocks[i].origin = blockIndex(keys[i]) * kB;
  }
}

LazyDependencyPlan planLevel(const std::vector<BlockKey>& deliver, int steps, int readRadius) {
  TS_CHECK(steps >= 0 && readRadius >= 0);
  const int grow = (readRadius + kB - 1) / kB;
  LazyDependencyPlan plan;
  plan.layers.resize(std::size_t(steps) + 1);
  plan.layers[std::size_t(steps)] = deliver;
  sortUnique(plan.layers[std::size_t(steps)]);
  for (int i = steps; i > 0; --i) plan.layers[std::size_t(i) - 1] = dilate(plan.layers[std::size_t(i)], grow);
  return plan;
}

std::vector<BlockKey> parentBlocks(const std::vector<BlockKey>& blocks) {
  // Voxels 4b..4b+3 have parents 2b..2b+1, all inside parent block floor(b / 2).
  std::vector<BlockKey> parents;
  parents.reserve(blocks.size());
  for (BlockKey key : blocks) {
    const Vec3i b = blockIndex(key);
    parents.push_back(blockKey(floorDiv(b.x(), 2), floorDiv(b.y(), 2), floorDiv(b.z(), 2)));
  }
  sortUnique(parents);
  return parents;
}

}  // namespace texsynth::lazy
