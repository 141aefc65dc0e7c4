// Dependency planning of lazy solid synthesis: which 4^3 blocks each correction step of a level
// must produce so that the delivered blocks are exact (the standard pass/subpass scheme and grid
// correction), and the grid phases' voxels and history snapshots of a level's work set.
#include <algorithm>
#include <unordered_map>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
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

namespace {

// A mask's 4 bits along `axis` at in-block coordinates (u, v) of the other two axes (in order).
int slotOf(int axis, int along, int u, int v) {
  Vec3i local;
  local[axis] = along;
  local[(axis + 1) % 3] = u;
  local[(axis + 2) % 3] = v;
  return (local.z() * kB + local.y()) * kB + local.x();
}

// Every voxel within `radius` of a masked one along `axis` (rows of 4 bits, shifted in 64-bit
// words, so the cost is per block and row, not per voxel and offset).
std::vector<BlockMask> dilateAlong(const std::vector<BlockMask>& masks, int axis, int radius) {
  TS_CHECK(radius >= 0 && radius <= 24);
  constexpr int kOrigin = 28;  // the block's row sits at bits 28..31; rows up to 24 voxels away fit
  std::unordered_map<BlockKey, std::uint64_t> grown;
  grown.reserve(masks.size() * 3);
  const int reach = (radius + kB - 1) / kB;
  for (const BlockMask& mask : masks) {
    const Vec3i block = blockIndex(mask.key);
    std::uint64_t out[16] = {};  // per target block offset -reach..reach (<= 7 each side)
    for (int u = 0; u < kB; ++u)
      for (int v = 0; v < kB; ++v) {
        std::uint64_t row = 0;
        for (int i = 0; i < kB; ++i) row |= ((mask.voxels >> slotOf(axis, i, u, v)) & 1) << i;
        if (!row) continue;
        std::uint64_t spread = 0;
        for (int d = -radius; d <= radius; ++d) spread |= d >= 0 ? (row << kOrigin) << d : (row << kOrigin) >> -d;
        for (int k = -reach; k <= reach; ++k) {
          const std::uint64_t bits = (spread >> (kOrigin + kB * k)) & 0xf;
          for (int i = 0; i < kB; ++i)
            if (bits >> i & 1) out[k + reach] |= std::uint64_t(1) << slotOf(axis, i, u, v);
        }
      }
    for (int k = -reach; k <= reach; ++k) {
      if (!out[k + reach]) continue;
      Vec3i target = block;
      target[axis] += k;
      grown[blockKey(target.x(), target.y(), target.z())] |= out[k + reach];
    }
  }
  std::vector<BlockMask> result;
  result.reserve(grown.size());
  for (const auto& [key, voxels] : grown) result.push_back({key, voxels});
  std::sort(result.begin(), result.end(), [](const BlockMask& a, const BlockMask& b) { return a.key < b.key; });
  return result;
}

// The voxels [lo, hi] of an index box of `size`-voxel units whose origin is shifted by -shift.
IndexBox voxelsOf(const Vec3i& index, int size, int shift) {
  const Vec3i lo = index * size - Vec3i::Constant(shift);
  return {lo, lo + Vec3i::Constant(size - 1)};
}

// The indices of the `size`-voxel units (shifted by -shift) touching voxels [lo - grow, hi + grow].
IndexBox unitsTouching(const IndexBox& voxels, int grow, int size, int shift) {
  IndexBox out;
  for (int a = 0; a < 3; ++a) {
    out.lo[a] = floorDiv(voxels.lo[a] - grow + shift, size);
    out.hi[a] = floorDiv(voxels.hi[a] + grow + shift, size);
  }
  return out;
}

}  // namespace

void appendBox(std::vector<BlockKey>& keys, const IndexBox& box) {
  for (int z = box.lo.z(); z <= box.hi.z(); ++z)
    for (int y = box.lo.y(); y <= box.hi.y(); ++y)
      for (int x = box.lo.x(); x <= box.hi.x(); ++x) keys.push_back(blockKey(x, y, z));
}

LazyDependencyPlan planGridLevel(const std::vector<BlockKey>& deliver, int cellSize, int readRadius, bool dualPhase) {
  TS_CHECK(cellSize >= 2 && readRadius >= 1);
  LazyDependencyPlan plan;
  plan.gridScheme = true;
  plan.cellSize = cellSize;
  std::vector<BlockKey> base = deliver;
  sortUnique(base);
  const int half = cellSize / 2;
  // Voxels whose primary-phase result is read: the delivered blocks, or the dual cells around them.
  std::vector<IndexBox> needed;
  for (BlockKey key : base) {
    const IndexBox block = voxelsOf(blockIndex(key), kB, 0);
    if (dualPhase)
      appendBox(plan.dualCells, unitsTouching(block, 0, cellSize, half));
    else
      needed.push_back(block);
  }
  sortUnique(plan.dualCells);
  for (BlockKey key : plan.dualCells) needed.push_back(voxelsOf(blockIndex(key), cellSize, half));
  const int grow = dualPhase ? readRadius : 0;
  for (const IndexBox& voxels : needed) appendBox(plan.primaryCells, unitsTouching(voxels, grow, cellSize, 0));
  sortUnique(plan.primaryCells);
  std::vector<BlockKey> all;
  for (BlockKey key : plan.primaryCells)
    appendBox(all, unitsTouching(voxelsOf(blockIndex(key), cellSize, 0), readRadius, kB, 0));
  sortUnique(all);
  plan.layers = {std::move(all), std::move(base)};
  return plan;
}

GridPhase gridPhase(const WorkSet& set, const std::vector<BlockKey>& cells, int cellSize, int shift) {
  GridPhase phase;
  phase.correct.assign(set.blocks.size(), 0);
  parallelForChunks(0, std::int64_t(set.blocks.size()), 64, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i) {
      const WorkBlock& block = set.blocks[std::size_t(i)];
      BlockKey lastCell = 0;
      bool lastIn = false, any = false;
      for (int slot = 0; slot < kBlockVoxels; ++slot) {
        const Vec3i v = block.origin + Vec3i(slot % kB, slot / kB % kB, slot / (kB * kB));
        const BlockKey cell = blockKey(floorDiv(v.x() + shift, cellSize), floorDiv(v.y() + shift, cellSize),
                                       floorDiv(v.z() + shift, cellSize));
        if (!any || cell != lastCell)  // a block spans at most 8 cells: look each up once in a row
          lastIn = std::binary_search(cells.begin(), cells.end(), cell), lastCell = cell, any = true;
        if (lastIn) phase.correct[std::size_t(i)] |= std::uint64_t(1) << slot;
      }
    }
  });
  return phase;
}

void WorkSet::takeSnapshot(int version) {
  Version& taken = snapshots.emplace_back();
  taken.version = version;
  taken.blocks.resize(blocks.size());
  parallelForChunks(0, std::int64_t(blocks.size()), 64, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i) {
      taken.blocks[std::size_t(i)].triples = blocks[std::size_t(i)].triples;
      taken.blocks[std::size_t(i)].colors = blocks[std::size_t(i)].colors;
    }
  });
}

void WorkSet::dropSnapshotsExcept(const std::vector<int>& versions) {
  std::erase_if(snapshots, [&](const Version& s) {
    return std::find(versions.begin(), versions.end(), s.version) == versions.end();
  });
}

std::vector<BlockMask> mergeMasks(std::vector<BlockMask> masks) {
  std::sort(masks.begin(), masks.end(), [](const BlockMask& a, const BlockMask& b) { return a.key < b.key; });
  std::vector<BlockMask> merged;
  for (const BlockMask& m : masks) {
    if (!merged.empty() && merged.back().key == m.key)
      merged.back().voxels |= m.voxels;
    else
      merged.push_back(m);
  }
  return merged;
}

std::vector<BlockMask> dilateMasks(const std::vector<BlockMask>& masks, int radius) {
  std::vector<BlockMask> current = masks;
  for (int axis = 0; axis < 3; ++axis) current = dilateAlong(current, axis, radius);
  return current;
}

LazyDependencyPlan planExactLevel(const std::vector<BlockMask>& deliver, int steps, int readRadius) {
  LazyDependencyPlan plan;
  plan.voxels.resize(std::size_t(steps) + 1);
  plan.voxels[std::size_t(steps)] = deliver;
  for (int i = steps; i > 0; --i)
    plan.voxels[std::size_t(i) - 1] = dilateMasks(plan.voxels[std::size_t(i)], readRadius);
  for (const std::vector<BlockMask>& layer : plan.voxels) {
    plan.layers.emplace_back();
    for (const BlockMask& mask : layer) plan.layers.back().push_back(mask.key);
  }
  return plan;
}

std::vector<BlockMask> parentMasks(const std::vector<BlockMask>& voxels) {
  // Voxel v's parent is floor(v / 2): a block's 2^3 corners map onto 2^3 corner voxels' parents.
  std::vector<BlockMask> parents;
  parents.reserve(voxels.size());
  for (const BlockMask& mask : voxels) {
    const Vec3i b = blockIndex(mask.key);
    const Vec3i parent(floorDiv(b.x(), 2), floorDiv(b.y(), 2), floorDiv(b.z(), 2));
    const Vec3i corner = 2 * (b - 2 * parent);
    std::uint64_t bits = 0;
    for (int slot = 0; slot < kBlockVoxels; ++slot) {
      if (!(mask.voxels >> slot & 1)) continue;
      const Vec3i local(slot % kB / 2, slot / kB % kB / 2, slot / (kB * kB) / 2);
      const Vec3i at = corner + local;
      bits |= std::uint64_t(1) << ((at.z() * kB + at.y()) * kB + at.x());
    }
    parents.push_back({blockKey(parent.x(), parent.y(), parent.z()), bits});
  }
  return mergeMasks(std::move(parents));
}

std::vector<BlockMask> parentMasks(const std::vector<BlockKey>& blocks) {
  std::vector<BlockMask> whole;
  whole.reserve(blocks.size());
  for (BlockKey key : blocks) whole.push_back({key, ~std::uint64_t(0)});
  return parentMasks(whole);
}

std::vector<BlockKey> torusBlocks(const Vec3i& torusMin, const Vec3i& torusSize) {
  std::vector<BlockKey> keys;
  appendBox(keys, {(torusMin.array() / kB).matrix(), ((torusMin + torusSize).array() / kB - 1).matrix()});
  std::sort(keys.begin(), keys.end());
  return keys;
}

}  // namespace texsynth::lazy
