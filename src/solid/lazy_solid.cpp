// Lazy solid synthesis driver: exemplar analyses and candidate triples per level, then for each
// request a plan from the finest level down (which blocks each level must deliver, grown by
// its correction reach) and synthesis from the coarsest level up, caching finished blocks.
#include "texsynth/solid/lazy_solid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <string>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/exemplar/analysis_cache.h"
#include "texsynth/exemplar/gaussian_stack.h"
#include "texsynth/solid/lazy_blocks.h"

namespace texsynth {

using namespace lazy;

struct LazySolid::Impl {
  std::vector<BlockCache> caches;  // per level: finished (exact) blocks
};

namespace {

LazyLevelStats& operator+=(LazyLevelStats& stats, const StepCounts& counts) {
  stats.corrections += counts.corrections;
  stats.comparisons += counts.comparisons;
  return stats;
}

constexpr int kMaxVoxelCoordinate = 1 << 19;
constexpr std::int64_t kInitChunk = 16;

void require(bool ok, const char* parameter, const std::string& problem) {
  if (!ok) throw ParameterError(parameter, problem);
}

int neighborhoodSizeOf(const LazySolidOptions& options, int level) {
  return options.neighborhoodSizes[std::min<std::size_t>(std::size_t(level), options.neighborhoodSizes.size() - 1)];
}

// Memory accounting for --stats: a cached block is a hash-map node (key, triples, links); a
// working block adds its key, index entry, colours and frames, its history snapshot if one is
// taken, and room for one step's results.
constexpr std::int64_t cachedBlockBytes = sizeof(BlockKey) + sizeof(TripleBlock) + 2 * sizeof(void*);
std::int64_t workingBytes(const WorkSet& set) {
  const std::int64_t perBlock = sizeof(WorkBlock) + sizeof(BlockKey) + sizeof(std::int32_t) + cachedBlockBytes +
                                kBlockVoxels * sizeof(CoordinateTriple);
  return std::int64_t(set.blocks.size()) * perBlock +
         std::int64_t(set.snapshots.size() * set.blocks.size()) * std::int64_t(sizeof(WorkSet::Snapshot));
}

// The finest-level blocks holding the voxel box [min, min + size); ParameterError("voxels", ...)
// for an empty box or one beyond 2^19.
IndexBox blocksOfBox(const Vec3i& min, const Vec3i& size) {
  require((size.array() >= 1).all(), "voxels", "the box must have a positive size");
  const Vec3i max = min + size - Vec3i::Ones();
  require(min.cwiseAbs().maxCoeff() < kMaxVoxelCoordinate && max.cwiseAbs().maxCoeff() < kMaxVoxelCoordinate, "voxels",
          "coordinates must stay below 2^19 in magnitude");
  return {Vec3i(floorDiv(min.x(), kB), floorDiv(min.y(), kB), floorDiv(min.z(), kB)),
          Vec3i(floorDiv(max.x(), kB), floorDiv(max.y(), kB), floorDiv(max.z(), kB))};
}

void removeCached(std::vector<BlockKey>& keys, const BlockCache& cache) {
  keys.erase(std::remove_if(keys.begin(), keys.end(), [&](BlockKey k) { return cache.count(k) != 0; }), keys.end());
}

}  // namespace

void validateLazySolidOptions(const LazySolidOptions& options) {
  require(options.levels >= 1 && options.levels <= 8, "levels",
          "must be in [1, 8], got " + std::to_string(options.levels));
  require(!options.neighborhoodSizes.empty(), "neighborhoodSizes", "needs at least one N");
  for (int n : options.neighborhoodSizes)
    require(n >= 3 && n % 2 == 1 && n <= 15, "neighborhoodSizes",
            "each N must be odd and in [3, 15], got " + std::to_string(n));
  require(options.passes >= 0 && options.passes <= 8, "passes",
          "must be in [0, 8], got " + std::to_string(options.passes));
  require(options.coarsestPasses >= 0 && options.coarsestPasses <= 8, "coarsestPasses",
          "must be in [0, 8], got " + std::to_string(options.coarsestPasses));
  require(
      options.gridCellSize >= 4 && options.gridCellSize <= 32 && options.gridCellSize % 2 == 0, "gridCellSize",
      "M must be even (the dual cells are shifted by M/2) and in [4, 32], got " + std::to_string(options.gridCellSize));
  require(options.trilinearLevels >= 0, "trilinearLevels",
          "must be >= 0, got " + std::to_string(options.trilinearLevels));
  require(options.subpassGrid == 1 || options.subpassGrid == 2, "subpassGrid",
          "s must be 1 or 2 (s^3 subpasses), got " + std::to_string(options.subpassGrid));
  require(options.subpartSize >= 1, "subpartSize", "K must be >= 1, got " + std::to_string(options.subpartSize));
  require(options.candidateCount >= 1 && options.candidateCount <= 64, "candidateCount",
          "N_T must be in [1, 64], got " + std::to_string(options.candidateCount));
  require(options.pcaDimensions >= 1, "pcaDimensions", "must be >= 1, got " + std::to_string(options.pcaDimensions));
  require(options.featureMasks.size() <= 1 || options.featureMasks.size() == 3, "featureMasks",
          "give none, one for all planes or three (xy, yz, zx), got " + std::to_string(options.featureMasks.size()));
  require(std::isfinite(options.featureWeight) && options.featureWeight >= 0.0f, "featureWeight",
          "must be finite and >= 0");
  require(std::isfinite(options.jitter) && options.jitter >= 0.0f, "jitter", "must be finite and >= 0");
}

LazySolid::LazySolid(const Image& exemplar, const LazySolidOptions& options, LazyOrientation orientation,
                     Progress& progress)
    : options_(options), orientation_(std::move(orientation)), impl_(std::make_unique<Impl>()) {
  initialize(exemplar, exemplar, exemplar, progress);
}

LazySolid::LazySolid(const Image& xy, const Image& yz, const Image& zx, const LazySolidOptions& options,
                     LazyOrientation orientation, Progress& progress)
    : options_(options), orientation_(std::move(orientation)), impl_(std::make_unique<Impl>()) {
  initialize(xy, yz, zx, progress);
}

LazySolid::~LazySolid() = default;

void LazySolid::initialize(const Image& xy, const Image& yz, const Image& zx, Progress& progress) {
  validateLazySolidOptions(options_);
  const Image* images[3] = {&xy, &yz, &zx};
  for (const Image* image : images) require(!image->empty(), "exemplar", "is empty");
  for (const Image* image : images)
    require(image->width == xy.width && image->height == xy.height && image->channels == xy.channels, "exemplar",
            "the three plane exemplars must have the same size and channels");
  require(xy.channels < kMaxChannels, "exemplar", "has too many channels (" + std::to_string(xy.channels) + ")");
  const int maxLevels = defaultStackLevelCount(xy.width, xy.height);
  require(options_.levels <= maxLevels, "levels",
          std::to_string(options_.levels) + " levels need an exemplar of at least " +
              std::to_string(1 << options_.levels) + " pixels a side (this one allows " + std::to_string(maxLevels) +
              ")");

  AnalysisOptions analysisOptions;
  analysisOptions.levelCount = options_.levels;
  analysisOptions.neighborhoodSize = options_.neighborhoodSizes.back();
  analysisOptions.levelNeighborhoodSizes = options_.neighborhoodSizes;
  analysisOptions.pcaDimensions = options_.pcaDimensions;
  analysisOptions.similarCount = 1;  // correction draws candidates from the triples instead
  const bool shared = &xy == &yz && &yz == &zx && options_.featureMasks.size() <= 1;
  analysisOptions.featureWeight = options_.featureWeight;
  for (int p = 0; p < (shared ? 1 : 3); ++p) {
    if (!options_.featureMasks.empty())
      analysisOptions.featureMask = options_.featureMasks[options_.featureMasks.size() == 3 ? std::size_t(p) : 0];
    analyses_.push_back(options_.cacheDirectory.empty()
                            ? analyzeExemplar(*images[p], analysisOptions, progress)
                            : analyzeExemplarCached(*images[p], analysisOptions, options_.cacheDirectory, progress));
  }

  for (int l = 0; l < options_.levels; ++l) {
    CandidateTripleOptions tripleOptions;
    tripleOptions.count = options_.candidateCount;
    tripleOptions.neighborhoodSize = neighborhoodSizeOf(options_, l);
    const Image& a = analysis(Plane::XY).levels[std::size_t(l)].image;
    const Image& b = analysis(Plane::YZ).levels[std::size_t(l)].image;
    const Image& c = analysis(Plane::ZX).levels[std::size_t(l)].image;
    const int spacing = analyses_[0].levels[std::size_t(l)].spacing;
    triples_.push_back(
        options_.cacheDirectory.empty()
            ? computeCandidateTriples(a, b, c, spacing, tripleOptions, progress)
            : computeCandidateTriplesCached(a, b, c, spacing, tripleOptions, options_.cacheDirectory, progress));
  }
  stats_.assign(std::size_t(options_.levels), {});
  impl_->caches.resize(std::size_t(options_.levels));
}

int LazySolid::colorChannels() const {
  return analyses_[0].colorChannels;
}

const ExemplarAnalysis& LazySolid::analysis(Plane plane) const {
  return analyses_.size() == 1 ? analyses_[0] : analyses_[std::size_t(plane)];
}

void LazySolid::synthesize(std::span<const Vec3i> voxels, Progress& progress) {
  std::vector<BlockKey> blocks;
  blocks.reserve(voxels.size() / 8 + 1);
  for (const Vec3i& v : voxels) {
    require(v.cwiseAbs().maxCoeff() < kMaxVoxelCoordinate, "voxels", "coordinates must stay below 2^19 in magnitude");
    blocks.push_back(blockOfVoxel(v));
  }
  synthesizeBlocks(std::move(blocks), levels() - 1, progress);
}

void LazySolid::synthesizeBox(const Vec3i& min, const Vec3i& size, Progress& progress) {
  std::vector<BlockKey> blocks;
  appendBox(blocks, blocksOfBox(min, size));
  synthesizeBlocks(std::move(blocks), levels() - 1, progress);
}

LazySolid::PlanMargin LazySolid::planMargin(int level) const {
  // A level's plan for a set of blocks is the union of its plans for each block, and it repeats
  // with the grid cells: plan one block at every alignment to the cells and take the widest reach.
  const int alignments = gridded(level) ? std::lcm(options_.gridCellSize, kB) / kB : 1;
  PlanMargin margin;
  for (int i = 0; i < alignments; ++i) {
    const std::vector<BlockKey> deliver = {blockKey(i, i, i)};
    const LazyDependencyPlan plan = planForLevel(level, deliver);
    for (BlockKey key : plan.layers.front())
      for (int a = 0; a < 3; ++a) {
        margin.below = std::max(margin.below, i - blockIndex(key)[a]);
        margin.above = std::max(margin.above, blockIndex(key)[a] - i);
      }
  }
  return margin;
}

void LazySolid::prepareCoarsestLevel(const Vec3i& min, const Vec3i& size, Progress& progress) {
  // The finest blocks of the box, then level by level the blocks any of them can need.
  IndexBox box = blocksOfBox(min, size);
  for (int l = levels() - 1; l >= 1; --l) {
    const PlanMargin margin = planMargin(l);
    for (int a = 0; a < 3; ++a) {
      box.lo[a] = floorDiv(box.lo[a] - margin.below, 2);
      box.hi[a] = floorDiv(box.hi[a] + margin.above, 2);
    }
  }
  std::vector<BlockKey> blocks;
  appendBox(blocks, box);
  synthesizeBlocks(std::move(blocks), 0, progress);
}

bool LazySolid::gridded(int level) const {
  return options_.dualGrid && level > 0 && options_.passes > 0;
}

LazyDependencyPlan LazySolid::planForLevel(int level, const std::vector<BlockKey>& deliver) const {
  if (gridded(level))
    return planGridLevel(deliver, options_.gridCellSize, context(level).readRadius(), options_.passes >= 2);
  std::vector<int> classes;
  for (const CorrectionStep& step : levelSchedule(options_, level, false).steps) classes.push_back(step.voxelClass);
  return planLevel(deliver, classes, context(level).readRadius());
}

LevelContext LazySolid::context(int level) const {
  LevelContext ctx;
  ctx.level = level;
  ctx.levels = options_.levels;
  ctx.spacing = analyses_[0].levels[std::size_t(level)].spacing;
  ctx.neighborhoodSize = neighborhoodSizeOf(options_, level);
  ctx.width = analyses_[0].width;
  ctx.height = analyses_[0].height;
  ctx.channels = analyses_[0].levels[std::size_t(level)].image.channels;
  for (int p = 0; p < 3; ++p) ctx.planes[p] = &analysis(Plane(p)).levels[std::size_t(level)];
  ctx.triples = &triples_[std::size_t(level)];
  ctx.options = &options_;
  ctx.orientation = &orientation_;
  return ctx;
}

void LazySolid::synthesizeBlocks(std::vector<BlockKey> blocks, int deliverLevel, Progress& progress) {
  const int levels = options_.levels;
  std::sort(blocks.begin(), blocks.end());
  blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());

  // Plan, from the delivering level down: what each level delivers and what it must start from.
  std::vector<LazyDependencyPlan> plans(static_cast<std::size_t>(levels));
  std::vector<BlockKey> deliver = std::move(blocks);
  removeCached(deliver, impl_->caches[std::size_t(deliverLevel)]);
  for (int l = deliverLevel; l >= 0 && !deliver.empty(); --l) {
    plans[std::size_t(l)] = planForLevel(l, deliver);
    if (l == 0) break;
    deliver = parentBlocks(plans[std::size_t(l)].layers.front());
    removeCached(deliver, impl_->caches[std::size_t(l - 1)]);
  }

  progress.begin("lazy solid synthesis", levels);
  for (int l = 0; l < levels; ++l) {
    const LazyDependencyPlan& plan = plans[std::size_t(l)];
    if (plan.layers.empty()) {
      progress.advance(1);
      continue;
    }
    const auto started = std::chrono::steady_clock::now();
    const LevelContext ctx = context(l);
    WorkSet current(plan.layers.front());
    const BlockCache* parents = l > 0 ? &impl_->caches[std::size_t(l - 1)] : nullptr;
    parallelForChunks(0, std::int64_t(current.keys.size()), kInitChunk, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t i = begin; i < end; ++i) {
        WorkBlock& block = current.blocks[std::size_t(i)];
        if (parents)
          upsampleBlock(ctx, *parents, block);
        else
          initializeBlock(ctx, block);
        finishBlock(ctx, block);
      }
    });
    LazyLevelStats& stats = stats_[std::size_t(l)];
    stats.voxelsSynthesized += std::int64_t(current.keys.size()) * kBlockVoxels;
    const LevelSchedule schedule = levelSchedule(options_, l, plan.gridScheme);
    const int radius = ctx.readRadius();
    // Per step, the versions its windows read from snapshots (its read tables are rebuilt when it runs).
    std::vector<std::vector<int>> snapshotVersions;
    for (std::size_t k = 0; k < schedule.steps.size(); ++k)
      snapshotVersions.push_back(stepReads(schedule, k, radius).snapshotVersions);
    if (plan.gridScheme)  // every block stays readable; the windows decide which version is read
      std::fill(current.lastLayer.begin(), current.lastLayer.end(), std::int32_t(schedule.steps.size()));
    else
      for (std::size_t i = 1; i < plan.layers.size(); ++i)
        for (BlockKey key : plan.layers[i]) current.lastLayer[std::size_t(current.indexOf(key))] = std::int32_t(i);
    GridPhase phase;
    for (std::size_t k = 0; k < schedule.steps.size(); ++k) {
      const CorrectionStep& step = schedule.steps[k];
      if (k == 0 || schedule.steps[k - 1].pass != step.pass) {
        // A pass begins: keep its starting version if a window reads it later below the latest,
        // and free the snapshots no step reads any more.
        std::vector<int> stillRead;
        for (std::size_t j = k; j < snapshotVersions.size(); ++j)
          stillRead.insert(stillRead.end(), snapshotVersions[j].begin(), snapshotVersions[j].end());
        current.dropSnapshotsExcept(stillRead);
        if (std::find(stillRead.begin(), stillRead.end(), step.pass - 1) != stillRead.end())
          current.takeSnapshot(step.pass - 1);
        stats.peakWorkingBytes = std::max(stats.peakWorkingBytes, workingBytes(current));
      }
      if (step.gridPhase >= 0 && (k == 0 || schedule.steps[k - 1].gridPhase != step.gridPhase))
        phase = gridPhase(current, step.gridPhase == 0 ? plan.primaryCells : plan.dualCells, step.cellSize, step.shift);
      stats +=
          correctStep(ctx, current, int(k) + 1, stepReads(schedule, k, radius), step.gridPhase >= 0 ? &phase : nullptr);
    }
    current.snapshots.clear();
    BlockCache& cache = impl_->caches[std::size_t(l)];
    for (BlockKey key : plan.layers.back())
      cache.emplace(key, current.blocks[std::size_t(current.indexOf(key))].triples);
    stats.blocksCached = std::int64_t(cache.size());
    stats.cachedBytes = std::int64_t(cache.size()) * cachedBlockBytes;
    stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    progress.advance(1);
  }
  progress.end();
}

bool LazySolid::ready(const Vec3i& voxel) const {
  return impl_->caches.back().count(blockOfVoxel(voxel)) != 0;
}

CoordinateTriple LazySolid::triple(const Vec3i& voxel, int level) const {
  TS_CHECK(level >= 0 && level < options_.levels);
  const BlockCache& cache = impl_->caches[std::size_t(level)];
  const auto it = cache.find(blockOfVoxel(voxel));
  TS_CHECK_MSG(it != cache.end(), "voxel not synthesized at this level");
  return it->second[std::size_t(voxelSlot(voxel))];
}

namespace {
// Out of line: building the message inline trips a false -Wrestrict in GCC 12's string code.
[[noreturn]] __attribute__((noinline)) void throwNotSynthesized(const Vec3i& voxel) {
  std::string where = "(";
  for (int axis = 0; axis < 3; ++axis) (where += std::to_string(voxel[axis])) += axis < 2 ? ", " : ")";
  throw ParameterError("voxel", where + " was not synthesized: call prepare/synthesize first");
}
}  // namespace

void LazySolid::color(const Vec3i& voxel, float* out) const {
  const BlockCache& cache = impl_->caches.back();
  const auto it = cache.find(blockOfVoxel(voxel));
  if (it == cache.end()) throwNotSynthesized(voxel);
  const CoordinateTriple t = it->second[std::size_t(voxelSlot(voxel))];
  const int channels = colorChannels();
  const float* a = analysis(Plane::XY).levels.back().image.pixels.data();
  const float* b = analysis(Plane::YZ).levels.back().image.pixels.data();
  const float* c = analysis(Plane::ZX).levels.back().image.pixels.data();
  const std::size_t stride = std::size_t(analyses_[0].channels());
  const float* colors[3] = {a + t.xy * stride, b + t.yz * stride, c + t.zx * stride};
  if (options_.colorRule == LazySolidOptions::ColorRule::Medoid) {
    float spread[3] = {0, 0, 0};
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q)
        for (int i = 0; i < channels; ++i) spread[p] += std::abs(colors[p][i] - colors[q][i]);
    const int pick = spread[1] < spread[0] ? (spread[2] < spread[1] ? 2 : 1) : (spread[2] < spread[0] ? 2 : 0);
    std::copy(colors[pick], colors[pick] + channels, out);
    return;
  }
  for (int i = 0; i < channels; ++i) out[i] = (colors[0][i] + colors[1][i] + colors[2][i]) * (1.0f / 3.0f);
}

}  // namespace texsynth
