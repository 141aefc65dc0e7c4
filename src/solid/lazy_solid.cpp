// Lazy solid synthesis driver: exemplar analyses and candidate triples per level, then for each
// request a plan from the finest level down (which blocks each level must deliver, grown by
// its correction reach) and synthesis from the coarsest level up, caching finished blocks.
#include "texsynth/solid/lazy_solid.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <string>

#include "texsynth/core/cache_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/hash.h"
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
constexpr int kMinTorusBlocks = 4;

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

// Requested voxels already final in the cache are dropped, and blocks left with none.
void removeCached(std::vector<BlockMask>& requested, const BlockCache& cache) {
  for (BlockMask& mask : requested)
    if (const auto it = cache.find(mask.key); it != cache.end()) mask.voxels &= ~it->second.done;
  requested.erase(std::remove_if(requested.begin(), requested.end(), [](const BlockMask& m) { return m.voxels == 0; }),
                  requested.end());
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
  require((options.domainSize.array() >= 0).all() &&
              ((options.domainSize.array() == 0).all() || (options.domainSize.array() > 0).all()),
          "domainSize", "must be positive along every axis (or zero for the default domain)");
  require(options.domainMin.cwiseAbs().maxCoeff() < kMaxVoxelCoordinate &&
              (options.domainMin + options.domainSize).cwiseAbs().maxCoeff() < kMaxVoxelCoordinate,
          "domainSize", "the domain must stay within 2^19 voxels of the origin");
}

int lazyLevelsFor(int width, int height, const LazySolidOptions& options, int maxLevels) {
  require(!options.neighborhoodSizes.empty(), "neighborhoodSizes", "needs at least one N");
  const std::int64_t side = std::min(width, height), coarsestN = options.neighborhoodSizes.front();
  int levels = 1;
  while (levels < maxLevels && coarsestN << levels <= side) ++levels;  // N * 2^(L-1) <= side for L = levels + 1
  return levels;
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

  // The coarsest level's torus: the domain in coarsest voxels, one block of margin per side,
  // whole blocks, at least kMinTorusBlocks a side.
  const int finestPerCoarsest = 1 << (options_.levels - 1);
  Vec3i domainMin = options_.domainMin, domainSize = options_.domainSize;
  if ((domainSize.array() == 0).all()) domainMin.setZero(), domainSize.setConstant(2 * std::max(xy.width, xy.height));
  for (int a = 0; a < 3; ++a) {
    const int lo = floorDiv(floorDiv(domainMin[a], finestPerCoarsest), kB) - 1;
    const int hi = floorDiv(floorDiv(domainMin[a] + domainSize[a] - 1, finestPerCoarsest), kB) + 1;
    torusMin_[a] = lo * kB;
    torusSize_[a] = std::max(hi - lo + 1, kMinTorusBlocks) * kB;
  }
  coarsestKey_ = coarsestCacheKey(xy, yz, zx);
}

std::uint64_t LazySolid::coarsestCacheKey(const Image& xy, const Image& yz, const Image& zx) const {
  if (options_.cacheDirectory.empty() || (orientation_ && options_.orientationKey.empty())) return 0;
  Hasher hasher;
  hasher.string("lazy-coarsest").value(kCoarsestCacheFormatVersion);
  for (const Image* image : {&xy, &yz, &zx})
    hasher.value(image->width).value(image->height).value(image->channels).vector(image->pixels);
  for (const Image& mask : options_.featureMasks)
    hasher.value(mask.width).value(mask.height).value(mask.channels).vector(mask.pixels);
  const LazySolidOptions& o = options_;
  hasher.value(o.levels).vector(o.neighborhoodSizes).value(o.coarsestPasses).value(o.trilinearLevels);
  hasher.value(o.subpassGrid).value(o.subpartSize).value(o.candidateCount).value(o.pcaDimensions).value(o.jitter);
  hasher.value(o.featureWeight).value(o.seed);
  for (int a = 0; a < 3; ++a) hasher.value(torusMin_[a]).value(torusSize_[a]);
  hasher.value(bool(orientation_)).string(o.orientationKey);
  return hasher.digest();
}

int LazySolid::colorChannels() const {
  return analyses_[0].colorChannels;
}

const ExemplarAnalysis& LazySolid::analysis(Plane plane) const {
  return analyses_.size() == 1 ? analyses_[0] : analyses_[std::size_t(plane)];
}

void LazySolid::synthesize(std::span<const Vec3i> voxels, Progress& progress) {
  std::vector<BlockMask> masks;
  masks.reserve(voxels.size());
  for (const Vec3i& v : voxels) {
    require(v.cwiseAbs().maxCoeff() < kMaxVoxelCoordinate, "voxels", "coordinates must stay below 2^19 in magnitude");
    masks.push_back({blockOfVoxel(v), std::uint64_t(1) << voxelSlot(v)});
  }
  synthesizeRequested(mergeMasks(std::move(masks)), progress);
}

void LazySolid::synthesizeBox(const Vec3i& min, const Vec3i& size, Progress& progress) {
  std::vector<BlockKey> blocks;
  appendBox(blocks, blocksOfBox(min, size));
  std::vector<BlockMask> masks;
  masks.reserve(blocks.size());
  for (BlockKey key : blocks) {
    const Vec3i origin = blockIndex(key) * kB;
    std::uint64_t bits = 0;
    for (int slot = 0; slot < kBlockVoxels; ++slot) {
      const Vec3i v = origin + Vec3i(slot % kB, slot / kB % kB, slot / (kB * kB));
      if ((v.array() >= min.array()).all() && (v.array() < (min + size).array()).all())
        bits |= std::uint64_t(1) << slot;
    }
    masks.push_back({key, bits});
  }
  synthesizeRequested(mergeMasks(std::move(masks)), progress);
}

void LazySolid::prepareCoarsestLevel(Progress& progress) {
  synthesizeCoarsest(progress);
}

bool LazySolid::gridded(int level) const {
  return options_.dualGrid && level > 0 && options_.passes > 0;
}

bool LazySolid::exactPlans(int level) const {
  return level > 0 && !gridded(level) && options_.subpassGrid == 1;
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
  ctx.torusMin = torusMin_;
  ctx.torusSize = torusSize_;
  return ctx;
}

void LazySolid::synthesizeRequested(std::vector<BlockMask> requested, Progress& progress) {
  const int finest = options_.levels - 1;
  removeCached(requested, impl_->caches[std::size_t(finest)]);
  if (requested.empty()) return;
  if (finest == 0) return synthesizeCoarsest(progress);  // one level: the torus holds everything

  // Plan, from the finest level down to level 1: the voxels each level delivers (the parents of
  // everything the finer level starts from) and the blocks it must start from. The coarsest
  // level is the whole torus, whatever is requested.
  std::vector<LazyDependencyPlan> plans(std::size_t(options_.levels));
  std::vector<std::vector<BlockMask>> deliver(std::size_t(options_.levels));
  deliver[std::size_t(finest)] = std::move(requested);
  for (int l = finest; l >= 1 && !deliver[std::size_t(l)].empty(); --l) {
    std::vector<BlockKey> keys;
    for (const BlockMask& mask : deliver[std::size_t(l)]) keys.push_back(mask.key);
    plans[std::size_t(l)] = exactPlans(l)
                                ? planExactLevel(deliver[std::size_t(l)], options_.passes, context(l).readRadius())
                                : planForLevel(l, keys);
    if (l == 1) break;
    deliver[std::size_t(l - 1)] = exactPlans(l) ? parentMasks(plans[std::size_t(l)].voxels.front())
                                                : parentMasks(plans[std::size_t(l)].layers.front());
    removeCached(deliver[std::size_t(l - 1)], impl_->caches[std::size_t(l - 1)]);
  }
  synthesizeCoarsest(progress);
  for (int l = 1; l <= finest; ++l)
    if (!plans[std::size_t(l)].layers.empty())
      synthesizeLevel(l, plans[std::size_t(l)], false, progress, &deliver[std::size_t(l)]);
}

void LazySolid::synthesizeCoarsest(Progress& progress) {
  BlockCache& cache = impl_->caches[0];
  if (!cache.empty()) return;
  LazyLevelStats& stats = stats_[0];
  const auto started = std::chrono::steady_clock::now();
  const std::string path = coarsestKey_ ? coarsestCachePath(options_.cacheDirectory, coarsestKey_) : std::string();
  if (!path.empty()) {
    if (std::optional<BlockCache> loaded =
            loadCoarsestLevel(path, coarsestKey_, torusMin_, torusSize_, std::int32_t(triples_[0].pixelCount()))) {
      cache = std::move(*loaded);
      stats.fromDiskCache = true;
      stats.blocksCached = std::int64_t(cache.size());
      stats.cachedBytes = std::int64_t(cache.size()) * cachedBlockBytes;
      stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      return;
    }
  }
  LazyDependencyPlan plan;
  const std::vector<BlockKey> keys = torusBlocks(torusMin_, torusSize_);
  plan.layers = {keys, keys};
  synthesizeLevel(0, plan, true, progress);
  if (!path.empty()) detail::writeCacheFile(options_.cacheDirectory, path, serializeCoarsestLevel(cache, coarsestKey_));
}

void LazySolid::synthesizeLevel(int l, const LazyDependencyPlan& plan, bool torus, Progress& progress,
                                const std::vector<BlockMask>* exact) {
  const auto started = std::chrono::steady_clock::now();
  const LevelContext ctx = context(l);
  const LevelSchedule schedule = levelSchedule(options_, l, plan.gridScheme);
  WorkSet current(plan.layers.front());
  progress.begin("lazy solid: level " + std::to_string(l + 1) + " of " + std::to_string(options_.levels) + ", " +
                     std::to_string(current.keys.size() * kBlockVoxels) + " voxels",
                 std::int64_t(schedule.steps.size()) + 1);
  const BlockCache* parents = l > 0 ? &impl_->caches[std::size_t(l - 1)] : nullptr;
  // An exact plan makes and corrects only the voxels it needs (per block, bit per slot).
  const auto neededAt = [&](std::size_t layer) {
    std::vector<std::uint64_t> bits(current.keys.size(), plan.voxels.empty() ? ~std::uint64_t(0) : 0);
    if (!plan.voxels.empty())
      for (const BlockMask& mask : plan.voxels[layer]) bits[std::size_t(current.indexOf(mask.key))] = mask.voxels;
    return bits;
  };
  const std::vector<std::uint64_t> made = neededAt(0);
  parallelForChunks(0, std::int64_t(current.keys.size()), kInitChunk, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i) {
      WorkBlock& block = current.blocks[std::size_t(i)];
      if (parents)
        upsampleBlock(ctx, *parents, block, made[std::size_t(i)]);
      else
        initializeBlock(ctx, block);
      finishBlock(ctx, block, made[std::size_t(i)]);
    }
  });
  progress.advance(1);
  LazyLevelStats& stats = stats_[std::size_t(l)];
  for (std::uint64_t bits : made) stats.voxelsSynthesized += std::popcount(bits);
  const int radius = ctx.readRadius();
  // Per step, the versions its windows read from snapshots (its read tables are rebuilt when it runs).
  std::vector<std::vector<int>> snapshotVersions;
  for (std::size_t k = 0; k < schedule.steps.size(); ++k)
    snapshotVersions.push_back(stepReads(schedule, k, radius).snapshotVersions);
  if (plan.gridScheme || torus)  // every block stays readable; the windows decide which version is read
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
    bool restricted = step.gridPhase >= 0;
    if (!plan.voxels.empty()) {  // an exact plan: the voxels needed after this step
      phase.correct = neededAt(k + 1);
      restricted = true;
    } else if (exact && k + 1 == schedule.steps.size()) {  // nothing reads the last step's other voxels
      if (!restricted) phase.correct.assign(current.keys.size(), ~std::uint64_t(0));
      std::vector<std::uint64_t> requested(current.keys.size(), 0);
      for (const BlockMask& mask : *exact) requested[std::size_t(current.indexOf(mask.key))] = mask.voxels;
      for (std::size_t i = 0; i < requested.size(); ++i) phase.correct[i] &= requested[i];
      restricted = true;
    }
    stats += correctStep(ctx, current, int(k) + 1, stepReads(schedule, k, radius), restricted ? &phase : nullptr);
    progress.advance(1);
  }
  current.snapshots.clear();
  BlockCache& cache = impl_->caches[std::size_t(l)];
  if (exact) {  // only the requested voxels are final; earlier ones of the same blocks stay
    for (const BlockMask& mask : *exact) {
      const TripleBlock& triples = current.blocks[std::size_t(current.indexOf(mask.key))].triples;
      const auto [it, added] = cache.try_emplace(mask.key, CachedBlock{triples, mask.voxels});
      if (added) continue;
      for (int slot = 0; slot < kBlockVoxels; ++slot)
        if (mask.voxels >> slot & 1) it->second.triples[std::size_t(slot)] = triples[std::size_t(slot)];
      it->second.done |= mask.voxels;
    }
  } else {
    for (BlockKey key : plan.layers.back())
      cache.emplace(key, CachedBlock{current.blocks[std::size_t(current.indexOf(key))].triples});
  }
  stats.blocksCached = std::int64_t(cache.size());
  stats.cachedBytes = std::int64_t(cache.size()) * cachedBlockBytes;
  stats.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  progress.end();
}

bool LazySolid::ready(const Vec3i& voxel) const {
  const BlockCache& cache = impl_->caches.back();
  const auto it = cache.find(blockOfVoxel(levels() == 1 ? context(0).wrapCoarsest(voxel) : voxel));
  return it != cache.end() && (levels() == 1 || (it->second.done >> voxelSlot(voxel) & 1));
}

CoordinateTriple LazySolid::triple(const Vec3i& voxel, int level) const {
  TS_CHECK(level >= 0 && level < options_.levels);
  const BlockCache& cache = impl_->caches[std::size_t(level)];
  const Vec3i stored = level == 0 ? context(0).wrapCoarsest(voxel) : voxel;
  const auto it = cache.find(blockOfVoxel(stored));
  TS_CHECK_MSG(it != cache.end() && (it->second.done >> voxelSlot(stored) & 1), "voxel not synthesized at this level");
  return it->second.triples[std::size_t(voxelSlot(stored))];
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
  if (!ready(voxel)) throwNotSynthesized(voxel);
  const CoordinateTriple t = triple(voxel, levels() - 1);
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
