#pragma once
// Internals of lazy solid synthesis (lazy_solid.h), shared by its source files: sparse 4^3 voxel
// blocks, the dependency plan of one level, and the per-level kernels (initialization,
// upsampling, correction). Not a stable API.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/exemplar/candidate_triples.h"
#include "texsynth/solid/lazy_solid.h"

namespace texsynth::lazy {

constexpr int kB = LazySolid::kBlock;
constexpr int kBlockVoxels = kB * kB * kB;
constexpr int kMaxChannels = 8;
constexpr int kCoordinateBias = 1 << 20;  // |voxel| < 2^20 keeps block indices in 21 bits

using BlockKey = std::uint64_t;

constexpr int floorDiv(int v, int d) {
  return v >= 0 ? v / d : -((-v + d - 1) / d);
}
inline BlockKey blockKey(int bx, int by, int bz) {
  const auto part = [](int b) { return std::uint64_t(b + kCoordinateBias) & 0x1fffffu; };
  return part(bx) << 42 | part(by) << 21 | part(bz);
}
inline Vec3i blockIndex(BlockKey key) {
  return {int((key >> 42) & 0x1fffffu) - kCoordinateBias, int((key >> 21) & 0x1fffffu) - kCoordinateBias,
          int(key & 0x1fffffu) - kCoordinateBias};
}
inline BlockKey blockOfVoxel(const Vec3i& v) {
  return blockKey(floorDiv(v.x(), kB), floorDiv(v.y(), kB), floorDiv(v.z(), kB));
}
inline int voxelSlot(const Vec3i& v) {
  return ((v.z() - floorDiv(v.z(), kB) * kB) * kB + (v.y() - floorDiv(v.y(), kB) * kB)) * kB +
         (v.x() - floorDiv(v.x(), kB) * kB);
}

using TripleBlock = std::array<CoordinateTriple, kBlockVoxels>;
using BlockCache = std::unordered_map<BlockKey, TripleBlock>;

// A block while its level is being synthesized: triples, their colours at the level (mean of
// the three planes' stack images, all channels) and each voxel's local frame.
struct WorkBlock {
  Vec3i origin = Vec3i::Zero();  // voxel at slot 0
  TripleBlock triples{};
  std::array<float, kBlockVoxels * kMaxChannels> colors{};
  std::array<Mat3f, kBlockVoxels> frames;  // columns: local axes in grid space
};

// The working blocks of one level, sorted by key (fixed iteration order). Corrections update
// them in place; lastLayer[i] is the last plan layer holding block i, so step i (reading the
// state after step i - 1) may read block j only if lastLayer[j] >= i - 1 (older blocks are stale).
struct WorkSet {
  std::vector<BlockKey> keys;
  std::vector<WorkBlock> blocks;
  std::vector<std::int32_t> lastLayer;
  // Grid scheme: each block's triples and colours when the current phase began (what a
  // correction reads of voxels outside its own cell); empty otherwise.
  struct PhaseStart {
    TripleBlock triples;
    std::array<float, kBlockVoxels * kMaxChannels> colors;
  };
  std::vector<PhaseStart> phaseStart;
  std::unordered_map<BlockKey, std::int32_t> index;

  explicit WorkSet(std::vector<BlockKey> sortedKeys);
  std::int32_t indexOf(BlockKey key) const {
    auto it = index.find(key);
    return it == index.end() ? -1 : it->second;
  }
};

// One level's dependency plan under the standard pass/subpass scheme: layers[0] holds the
// blocks to upsample (or initialize), layers[i] those every later step still needs after
// correction step i, layers.back() the blocks the level must deliver. Step i corrects only the
// voxels of its class, each reading `readRadius` voxels around it, so the needed region grows by
// readRadius - 1 on a side whose outermost voxel is of another class (s = 2). Reaches add up in
// voxels per side and are rounded up to blocks once per layer; voxels of a layer's blocks outside
// the exact region may read stale or missing data: they are never read by what is delivered.
struct LazyDependencyPlan {
  std::vector<std::vector<BlockKey>> layers;
  // The dual-grid scheme (§5.3, planGridLevel) instead: layers = {all blocks, delivered
  // blocks}, and the M^3 cells each phase corrects (keys as blockKey of cell indices).
  bool gridScheme = false;
  int cellSize = 0;
  std::vector<BlockKey> primaryCells, dualCells;
};
// stepClasses: the voxel class of each correction step (-1 = all voxels, see correctStep).
LazyDependencyPlan planLevel(const std::vector<BlockKey>& deliver, const std::vector<int>& stepClasses, int readRadius);
// One level's plan under grid / dual-grid correction (§5.3): the voxels are divided into M^3
// cells (primary: [cM, cM + M), dual: shifted by M/2); during a phase a correction reads the
// current state of voxels in its own cell and the phase's starting state of all others, so
// nothing outside a cell's reach leaks in. The dual phase corrects every dual cell touching the
// delivered blocks and reads the primary phase's result up to readRadius around them; the
// primary phase corrects every primary cell touching that; both read the upsampled state up to
// readRadius around the primary cells. The dependent set grows by about 2 (M + readRadius) per
// side, whatever the number of passes and subpasses. dualPhase false: primary cells only.
LazyDependencyPlan planGridLevel(const std::vector<BlockKey>& deliver, int cellSize, int readRadius, bool dualPhase);
// Sorted, unique parent blocks (the coarser level) of `blocks`: block b reads parents in b/2.
std::vector<BlockKey> parentBlocks(const std::vector<BlockKey>& blocks);
// Everything one level's kernels need.
struct LevelContext {
  int level = 0, levels = 1;
  int spacing = 1;           // h_l
  int neighborhoodSize = 9;  // N_l
  int width = 0, height = 0, channels = 0;
  const ExemplarLevel* planes[3] = {nullptr, nullptr, nullptr};  // the level of I_xy, I_yz, I_zx
  const CandidateTriples* triples = nullptr;
  const LazySolidOptions* options = nullptr;
  const LazyOrientation* orientation = nullptr;

  // Radius (voxels) of everything a correction reads: the rotated neighbourhood and the 3x3
  // candidate sources; sqrt(2) * N/2 when a field may rotate the planes, one more where
  // neighbourhoods are integrated and read trilinearly.
  int readRadius() const;
  // True where the level's neighbourhoods are integrated along the field and read trilinearly
  // (a coarse level with an orientation).
  bool integrated() const;
  // Local frame of voxel v at this level (identity without orientation).
  Mat3f frame(int level, const Vec3i& v) const;
  // Colour (all channels) of a triple at this level into out[channels].
  void color(const CoordinateTriple& t, float* out) const;
};

// Fills `block` (origin set) at the coarsest level: tiled candidate slabs, T([q^-1 v]).
void initializeBlock(const LevelContext& ctx, WorkBlock& block);
// Fills `block` from the coarser level's finished triples (eq. 3-4) plus jitter.
void upsampleBlock(const LevelContext& ctx, const BlockCache& parents, WorkBlock& block);
// Frames and colours of a block whose triples are set.
void finishBlock(const LevelContext& ctx, WorkBlock& block);

// One phase (primary or dual) of grid correction: cells [cM - shift, cM - shift + M) per axis,
// and per block of the work set the voxels (bit per slot) this phase corrects.
struct GridPhase {
  int cellSize = 0, shift = 0;
  std::vector<std::uint64_t> correct;
};
// The phase over `cells` (sorted keys of cell indices), with `set.phaseStart` taken now.
GridPhase beginGridPhase(WorkSet& set, const std::vector<BlockKey>& cells, int cellSize, int shift);

// Correction step `step` (1-based) in place: every block with lastLayer >= step corrects its
// voxels of class `voxelClass` (x mod s, y mod s, z mod s as bits 0..2; -1 = all voxels) from
// the state before the step (all results are computed before any is written). Voxels that would
// read a stale or missing block are left alone (they lie outside the exact planned region).
// Returns the number of corrected voxels and of neighbourhood comparisons.
// With a grid phase, the phase's voxels are corrected instead, reading the phase's start state
// of voxels outside their own cell.
struct StepCounts {
  std::int64_t corrections = 0, comparisons = 0;
};
StepCounts correctStep(const LevelContext& ctx, WorkSet& set, int step, int s, int voxelClass,
                       const GridPhase* phase = nullptr);

}  // namespace texsynth::lazy
