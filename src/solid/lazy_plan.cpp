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

// Grows a block set by lo[a] blocks towards -a and hi[a] towards +a along each axis a in turn
// (separable, so the cost is sum (lo + hi + 1) inserts per block rather than the product).
std::vector<BlockKey> dilate(const std::vector<BlockKey>& keys, const int lo[3], const int hi[3]) {
  std::vector<BlockKey> current = keys;
  for (int axis = 0; axis < 3; ++axis) {
    if (lo[axis] == 0 && hi[axis] == 0) continue;
    std::vector<BlockKey> next;
    next.reserve(current.size() * std::size_t(lo[axis] + hi[axis] + 1));
    for (BlockKey key : current) {
      const Vec3i b = blockIndex(key);
      for (int d = -lo[axis]; d <= hi[axis]; ++d) {
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

WorkSet::WorkSet(std::vector<BlockKey> sortedKeys)
    : keys(std::move(sortedKeys)), blocks(keys.size()), lastLayer(keys.size(), 0) {
  index.reserve(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    index.emplace(keys[i], std::int32_t(i));
    blocks[i].origin = blockIndex(keys[i]) * kB;
  }
}

LazyDependencyPlan planLevel(const std::vector<BlockKey>& deliver, const std::vector<int>& stepClasses,
                             int readRadius) {
  TS_CHECK(readRadius >= 1);
  const int steps = int(stepClasses.size());
  LazyDependencyPlan plan;
  plan.layers.resize(std::size_t(steps) + 1);
  std::vector<BlockKey> base = deliver;
  sortUnique(base);
  // Exact reach in voxels beyond each delivered block [4b, 4b + 3] per axis and side. Step i's
  // outermost voxel of its class on the low side is at 4b - lo (parity lo mod 2), on the high
  // side at 4b + 3 + hi (parity (hi + 1) mod 2), or one voxel further in.
  int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int i = steps; i > 0; --i) {
    const int voxelClass = stepClasses[std::size_t(i) - 1];
    for (int axis = 0; axis < 3; ++axis) {
      const int parity = voxelClass < 0 ? -1 : (voxelClass >> axis) & 1;
      lo[axis] += parity < 0 || lo[axis] % 2 == parity ? readRadius : readRadius - 1;
      hi[axis] += parity < 0 || (hi[axis] + 1) % 2 == parity ? readRadius : readRadius - 1;
    }
    int loBlocks[3], hiBlocks[3];
    for (int axis = 0; axis < 3; ++axis) {
      loBlocks[axis] = (lo[axis] + kB - 1) / kB;
      hiBlocks[axis] = (hi[axis] + kB - 1) / kB;
    }
    plan.layers[std::size_t(i) - 1] = dilate(base, loBlocks, hiBlocks);
  }
  plan.layers[std::size_t(steps)] = std::move(base);
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
