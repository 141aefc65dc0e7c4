#pragma once
// Internals of lazy solid synthesis (lazy_solid.h), shared by its source files: sparse 4^3 voxel
// blocks, the dependency plan of one level, and the per-level kernels (initialization,
// upsampling, correction). Not a stable API.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/exemplar/candidate_triples.h"
#include "texsynth/solid/history_window.h"
#include "texsynth/solid/lazy_solid.h"

namespace texsynth::lazy {

constexpr int kB = LazySolid::kBlock;
constexpr int kBlockVoxels = kB * kB * kB;
constexpr int kMaxChannels = 8;
// A voxel's colours: each plane's exemplar colour at its triple, so a plane's neighbourhood is
// matched against that plane's exemplar in its own colours. A block stores them plane by plane,
// densely in the level's channel count (colorIndex): a correction gathers one plane's colours of
// neighbouring voxels, which then share cache lines (with kMaxChannels a voxel, the gather's loads
// stalled 12% of a cut's profile).
constexpr int kVoxelColors = 3 * kMaxChannels;  // room per voxel in a block
inline std::size_t colorIndex(int plane, int slot, int channels) {
  return (std::size_t(plane) * kBlockVoxels + std::size_t(slot)) * std::size_t(channels);
}
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

// Inclusive index ranges along x, y, z (of blocks, cells or voxels).
struct IndexBox {
  Vec3i lo, hi;
};
// Appends the key (blockKey packing) of every index in `box`.
void appendBox(std::vector<BlockKey>& keys, const IndexBox& box);

using TripleBlock = std::array<CoordinateTriple, kBlockVoxels>;
// A finished block of a level's cache: its triples and which of them are final (bit per slot).
// Coarser levels finish whole blocks; the finest finishes only the voxels requested.
struct CachedBlock {
  TripleBlock triples{};
  std::uint64_t done = ~std::uint64_t(0);
};
using BlockCache = std::unordered_map<BlockKey, CachedBlock>;
// Requested voxels by block: sorted, unique keys, each with its bit per slot.
struct BlockMask {
  BlockKey key = 0;
  std::uint64_t voxels = 0;
};

// A block while its level is being synthesized: triples, their colours at the level (each
// plane's stack image at its coordinate, all channels) and each voxel's local frame.
// Colours and frames are left unset until upsampling or initialization fills a voxel (unset
// voxels are never read): zeroing them, 8.5 KB a block on one thread, was 10% of a cut's profile.
struct WorkBlock {
  WorkBlock() {}                 // user-provided: `= default` would zero the arrays in std::vector(n)
  Vec3i origin = Vec3i::Zero();  // voxel at slot 0
  TripleBlock triples{};
  std::array<float, kBlockVoxels * kVoxelColors> colors;
  std::array<Mat3f, kBlockVoxels> frames;  // columns: local axes in grid space
};

// The working blocks of one level, sorted by key (fixed iteration order). Corrections update
// them in place; lastLayer[i] is the last plan layer holding block i, so step i (reading the
// state after step i - 1) may read block j only if lastLayer[j] >= i - 1 (older blocks are stale).
struct WorkSet {
  std::vector<BlockKey> keys;
  std::vector<WorkBlock> blocks;
  std::vector<std::int32_t> lastLayer;
  // Earlier versions that history windows still read below the latest (the grid scheme: the
  // state its phase began from): each block's triples and colours after pass `version`.
  struct Snapshot {
    TripleBlock triples;
    std::array<float, kBlockVoxels * kVoxelColors> colors;
  };
  struct Version {
    int version = 0;
    std::vector<Snapshot> blocks;
  };
  std::vector<Version> snapshots;
  std::unordered_map<BlockKey, std::int32_t> index;

  explicit WorkSet(std::vector<BlockKey> sortedKeys);
  std::int32_t indexOf(BlockKey key) const {
    auto it = index.find(key);
    return it == index.end() ? -1 : it->second;
  }
  // Keeps the current state as `version` (taken when the pass after it begins).
  void takeSnapshot(int version);
  // Frees the snapshots of versions no step reads any more.
  void dropSnapshotsExcept(const std::vector<int>& versions);
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
  // planExactLevel instead: the exact voxels needed before each step (voxels[0]: what upsampling
  // makes) and after the last (the delivered ones); layers hold their blocks.
  std::vector<std::vector<BlockMask>> voxels;
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
// Sorted by key, one entry per block, the bits of each block's masks or-ed together.
std::vector<BlockMask> mergeMasks(std::vector<BlockMask> masks);
// The parent voxels (the coarser level) of every voxel of `blocks`, by parent block: block b's
// voxels read the 2^3 voxels at the corner 2 (b mod 2) of parent block floor(b / 2).
std::vector<BlockMask> parentMasks(const std::vector<BlockKey>& blocks);
// The parent voxels of exactly these voxels (the block form: of every voxel of the blocks).
std::vector<BlockMask> parentMasks(const std::vector<BlockMask>& voxels);
// The sorted keys of the coarsest level's torus blocks (torusMin, torusSize: multiples of kB).
std::vector<BlockKey> torusBlocks(const Vec3i& torusMin, const Vec3i& torusSize);
// Every voxel within `radius` (a cube) of a masked one.
std::vector<BlockMask> dilateMasks(const std::vector<BlockMask>& masks, int radius);
// One level's plan voxel by voxel, for the standard scheme with s = 1 (each of `steps` steps
// corrects every voxel from the state before it, reading `readRadius` around it): the voxels
// needed before a step are those within readRadius of the ones needed after it.
LazyDependencyPlan planExactLevel(const std::vector<BlockMask>& deliver, int steps, int readRadius);
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
  // The coarsest level's torus (coarsest voxels, multiples of kB): its voxel v is stored at
  // wrapCoarsest(v), and its corrections read across the torus' sides.
  Vec3i torusMin = Vec3i::Zero(), torusSize = Vec3i::Zero();

  // Radius (voxels) of everything a correction reads: the rotated neighbourhood and the 3x3
  // candidate sources; sqrt(2) * N/2 when a field may rotate the planes, one more where
  // neighbourhoods are integrated and read trilinearly.
  int readRadius() const;
  // True where the level's neighbourhoods are integrated along the field and read trilinearly
  // (a coarse level with an orientation).
  bool integrated() const;
  // Local frame of voxel v at this level (identity without orientation).
  Mat3f frame(int level, const Vec3i& v) const;
  // Colours (all channels) of a triple at this level into a block's colours at `slot` (colorIndex).
  void color(const CoordinateTriple& t, float* blockColors, int slot) const;
  // A coarsest-level voxel's place on the torus.
  Vec3i wrapCoarsest(const Vec3i& voxel) const;
  // Where this level stores block `block` (wrapped onto the torus at the coarsest level).
  Vec3i storedBlock(const Vec3i& block) const;
};

// Fills `block` (origin set) at the coarsest level: tiled candidate slabs, T([q^-1 v]).
void initializeBlock(const LevelContext& ctx, WorkBlock& block);
// Fills `block` from the coarser level's finished triples (eq. 3-4) plus jitter.
// Only the voxels of `voxels` (bit per slot); the others stay unset and are never read.
void upsampleBlock(const LevelContext& ctx, const BlockCache& parents, WorkBlock& block,
                   std::uint64_t voxels = ~std::uint64_t(0));
// Frames and colours of a block whose triples are set.
void finishBlock(const LevelContext& ctx, WorkBlock& block, std::uint64_t voxels = ~std::uint64_t(0));

// A level's correction schedule: its steps in order, each a pass (or one subpass of it) with
// the history windows its voxels read through (§5.2): the standard scheme (pass or subpass
// windows) or, above the coarsest level with dual grid, ceil(P/2) primary then floor(P/2) dual
// grid passes, each subpass reading H_g ∩ H_s.
struct CorrectionStep {
  int pass = 1;         // 1-based: the version the step produces
  int subpass = 0;      // index into LevelSchedule::classOrder
  int voxelClass = -1;  // voxels corrected: class x mod s | y mod s << 1 | z mod s << 2; -1 all
  int gridPhase = -1;   // -1: none; 0 primary cells, 1 dual cells (shifted by M / 2)
  int cellSize = 0, shift = 0, startVersion = 0;
};
struct LevelSchedule {
  int s = 1;
  std::vector<int> classOrder;  // s^3 classes ({-1} for s = 1)
  std::vector<CorrectionStep> steps;
  // H(p) of step k (0-based) for voxel p: the (sub)pass window, intersected with the grid window.
  HistoryWindow window(std::size_t k, const Vec3i& voxel, int radius) const;
  // The versions p's neighbours hold when step k runs (the subpass or pass window): a version
  // read below it comes from a snapshot.
  HistoryWindow latest(std::size_t k, const Vec3i& voxel, int radius) const;
  // Window types repeat with this period per axis (s, or lcm(s, M) under grid correction).
  int period(std::size_t k) const;
};
// The schedule of `level` for these options; `grid` selects dual-grid correction.
LevelSchedule levelSchedule(const LazySolidOptions& options, int level, bool grid);
// How step k reads: per voxel type (position mod the period) a table over the window's D^3
// offsets of the version read from a snapshot, or -1 where the neighbour's current state is
// read. Built from the step's windows; types of other classes stay empty.
struct StepReads {
  int radius = 0, period = 1, s = 1, voxelClass = -1;
  std::vector<std::vector<std::int8_t>> sources;  // per type
  std::vector<int> snapshotVersions;              // sorted versions some table reads
  const std::int8_t* sourcesFor(const Vec3i& voxel) const;
};
StepReads stepReads(const LevelSchedule& schedule, std::size_t k, int radius);
// The exact voxels a level must hold after each step for `deliver` to come out right, from the
// schedule's history windows: needed[K] = deliver (K steps); a voxel needed after step k that
// step k corrects (its class) needs every neighbour in its window at the version the window
// gives (the state after that pass's last step; the latest: after step k - 1), a voxel step k
// leaves alone needs itself after step k - 1. needed[0]: what upsampling must make. Sorted.
// Voxel by voxel (D^3 per corrected voxel), so for checking the block planners on small requests.
std::vector<std::vector<Vec3i>> windowDependencies(const LevelSchedule& schedule, const std::vector<Vec3i>& deliver,
                                                   int radius);

// The disk cache of a coarsest level (one torus): "<dir>/coarsest-<key>.tsxc", its blocks'
// triples in key order; loading checks the envelope, the torus and every index (< pixelCount).
inline constexpr std::uint32_t kCoarsestCacheFormatVersion = 1;
std::string coarsestCachePath(const std::string& cacheDirectory, std::uint64_t key);
std::string serializeCoarsestLevel(const BlockCache& cache, std::uint64_t key);
std::optional<BlockCache> loadCoarsestLevel(const std::string& path, std::uint64_t key, const Vec3i& torusMin,
                                            const Vec3i& torusSize, std::int32_t pixelCount);

// One phase (primary or dual) of grid correction: per block of the work set the voxels (bit per
// slot) lying in the phase's planned cells (sorted keys of cell indices), the only ones it corrects.
struct GridPhase {
  std::vector<std::uint64_t> correct;
};
GridPhase gridPhase(const WorkSet& set, const std::vector<BlockKey>& cells, int cellSize, int shift);

// Correction step `step` (1-based) in place: every block with lastLayer >= step corrects its
// voxels of the step's class (all voxels for -1) from the state before the step (all results are
// computed before any is written), reading each neighbour at the version its history window
// gives (`reads`). Voxels that would read a stale or missing block are left alone (they lie
// outside the exact planned region). With a grid phase only the phase's voxels are corrected.
// Returns the number of corrected voxels and of neighbourhood comparisons.
struct StepCounts {
  std::int64_t corrections = 0, comparisons = 0;
};
StepCounts correctStep(const LevelContext& ctx, WorkSet& set, int step, const StepReads& reads,
                       const GridPhase* phase = nullptr);

}  // namespace texsynth::lazy
