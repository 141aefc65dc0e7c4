#pragma once
// Lazy (on-demand) solid synthesis guided by a rotation field (sketch-guided solid texturing
// §2, §4, after Dong et al. 2008 and Lefebvre & Hoppe 2005). Every voxel of every pyramid level
// stores a coordinate triple into the three plane exemplars I_xy, I_yz, I_zx; colours are looked
// up at the end. Levels run coarsest first: initialization by tiled candidate slabs (per K^3
// subpart, warped by the field), upsampling with the field (eq. 3-4), then correction passes of
// s^3 subpasses matching three field-aligned N x N neighbourhoods in PCA space against candidate
// triples gathered from the neighbours.
//
// Determinism: a voxel's triple depends only on (seed, domain, voxel, level, pass). The coarsest
// level is request-independent: synthesized once, whole, on a torus covering the domain (the
// paper synthesizes it over the whole volume), and cached in memory and on disk. Finer levels are
// planned per request, finest to coarsest: with s = 1 (the default) voxel by voxel, each level
// delivering exactly the voxels the finer level starts from and starting from those within its
// read radius per pass; with subpasses as 4^3-voxel blocks grown by the full correction reach;
// under dual-grid correction (§5.3) by whole M^3 cells plus the read radius. So the same voxel
// gets the same triple whatever was requested, for any thread count. Finished voxels of every
// level are cached and reused by later requests.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/math.h"
#include "texsynth/core/progress.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/exemplar/candidate_triples.h"

namespace texsynth {

namespace lazy {
struct LevelContext;
struct LazyDependencyPlan;
struct BlockMask;
}  // namespace lazy

struct LazySolidOptions {
  // Pyramid levels L (paper: 4). Level l (0 = coarsest) uses the exemplar stack at spacing
  // h_l = 2^(L-1-l); every exemplar side must be >= 2^(L-1) * 2.
  int levels = 4;
  // N per level, coarsest first; the last entry serves every finer level (paper: 7 at the
  // coarsest, 9 elsewhere). Odd, >= 3.
  std::vector<int> neighborhoodSizes = {7, 9};
  // Correction passes per level above the coarsest (paper: 2). Each pass widens what a request
  // depends on by the read radius: one pass keeps the first picture of a model within seconds
  // (walnut on the elephant: 5 s instead of 32 s with 2) and slices crisper, at 7-10% higher
  // coherence (64^3 volumes of GIMP pink marble and burlap).
  int passes = 1;
  // Dual-grid correction (§5.3) on every level but the coarsest: ceil(P/2) passes in which a
  // voxel reads only its own M^3 cell's current state (and the upsampled state elsewhere), then
  // floor(P/2) passes on the dual cells (shifted by M/2) reading the first phase's result
  // elsewhere. The dependent set then grows by about 2 (M + N/sqrt 2) voxels per side instead of
  // passes * s^3 * N/2 (paper's setting, s = 2). false (default): the standard scheme (every voxel
  // reads its neighbours' latest state), which with s = 1 grows by only passes * N/sqrt 2: 4-6x
  // fewer voxels for a surface or a cut than the grids, at the same slice quality.
  bool dualGrid = false;
  // M, the cell side in voxels (paper: 10-15). Even (the dual cells are shifted by M/2), in [4, 32].
  int gridCellSize = 12;
  // Correction passes at the coarsest level (paper: "3-5 correction passes ... without
  // barriers" there, as its grid is small). In [0, 8].
  int coarsestPasses = 3;
  // Levels 0 .. trilinearLevels - 1 (the coarse ones) sample their neighbourhoods by walking
  // along the field's local axes (numerical integration, so the neighbourhood bends with the
  // field) and reading colours trilinearly; finer levels use the centre voxel's frame and the
  // nearest voxel (§4.3: "trilinear interpolation in coarse levels and nearest neighbor in
  // finer levels"). Only matters with an orientation. >= 0. Default 1: the coarsest level only
  // (synthesized once per model and cached on disk); an integrated correction costs about 10x
  // a nearest one, which on level 1 made a sketched model's first picture take a minute.
  int trilinearLevels = 1;
  // s: each pass corrects the s^3 voxel classes (x mod s, y mod s, z mod s) in turn (paper:
  // s^3 = 8). 1 (default) corrects all voxels at once from the state before the pass. In {1, 2}.
  int subpassGrid = 1;
  // K: the coarsest level is initialized per K^3 subpart (paper: 64), each part's slabs
  // warped about its own centre and shifted by its own random offset. >= 1.
  int subpartSize = 64;
  // N_T candidate triples per exemplar pixel (paper: 12). 6: the same slice quality on 128^3
  // volumes of GIMP pink marble and granite (bench/lazy_solid_table.sh) at half the comparisons.
  int candidateCount = 6;
  // PCA dimensions per plane (paper: "about 20").
  int pcaDimensions = 20;
  // Jitter r_l of L&H 2005 (not in the sketch-guided paper): the upsampled triple moves by
  // floor(h_l * r * xi + 1/2) along each local axis (eq. 4), xi uniform in [-1, 1]^3. Like the
  // 2D engine's default, 0.4 only acts on the coarse levels (h >= 2). >= 0, finite.
  float jitter = 0.4f;
  // Final colour of a voxel from the three exemplar pixels of its finest triple: their mean
  // (each plane's texture contributes equally; soft where the three disagree) or their medoid
  // (the one with the least L1 colour distance to the other two, a real exemplar colour).
  // Medoid by default: the mean turned slices grey and soft (sharpness 0.59 against 0.66 for the
  // medoid on a 64^3 volume of GIMP pink marble).
  enum class ColorRule { Mean, Medoid };
  ColorRule colorRule = ColorRule::Medoid;
  // Feature masks (§4: "a further feature component ... high intensity to indicate feature
  // curves", for regular textures such as bricks): none, one for all planes, or one per plane
  // (xy, yz, zx), each the size of its exemplar. Matching then adds featureWeight times the
  // signed distance to the features as a channel (AnalysisOptions::featureMask).
  std::vector<Image> featureMasks;
  float featureWeight = 1.0f;
  std::uint64_t seed = 1;
  // The domain, in finest-level voxels: [domainMin, domainMin + domainSize), e.g. a model's box.
  // The coarsest level is synthesized whole on a torus just larger than it (a margin of one
  // block per side, rounded up to blocks), so its cost is bounded by the domain, not by what is
  // requested; voxels outside read it periodically. A zero size: a cube of two exemplar widths
  // from the origin. Results depend on the domain: keep it fixed for a model.
  Vec3i domainMin = Vec3i::Zero(), domainSize = Vec3i::Zero();
  // Identifies the orientation function (e.g. a digest of its field and placement) in the disk
  // cache key of the coarsest level; with an orientation and no key that level is not cached on disk.
  std::string orientationKey;
  // Directory of the exemplar-analysis, candidate-triple and coarsest-level caches; empty = no disk cache.
  std::string cacheDirectory;
};

// Throws ParameterError naming the bad option ("levels", "neighborhoodSizes", "passes",
// "subpassGrid", "subpartSize", "candidateCount", "pcaDimensions", "jitter", "coarsestPasses",
// "trilinearLevels", "featureMasks", "featureWeight", "gridCellSize", "domainSize").
void validateLazySolidOptions(const LazySolidOptions& options);

// The most pyramid levels, up to `maxLevels`, whose coarsest neighbourhood (neighborhoodSizes[0]
// taps, 2^(L-1) exemplar pixels apart) fits in a width x height exemplar; at least 1. A wider one
// wraps around the exemplar and matches blurred copies of itself: GIMP's 20-pixel warning stripes
// came out as large blocks at 4 levels and as clean stripes at 2.
int lazyLevelsFor(int width, int height, const LazySolidOptions& options, int maxLevels = 4);

// The local frame (global -> local rotation, as RotationField) at a position of `level`
// (0 = coarsest), given in finest-level voxel units (exemplar pixels). See lazy_field.h for
// the adapter from a RotationField; an empty function means the identity everywhere.
using LazyOrientation = std::function<Quatf(int level, const Vec3f& finestPosition)>;

// Work done per level (accumulated over all requests).
struct LazyLevelStats {
  std::int64_t voxelsSynthesized = 0;  // voxels upsampled / initialized (incl. margins)
  std::int64_t corrections = 0;        // voxel corrections (one per voxel per pass)
  std::int64_t comparisons = 0;        // neighbourhood comparisons (distinct candidates measured)
  std::int64_t blocksCached = 0;       // finished 4^3 blocks now in the cache
  double seconds = 0;                  // wall time spent on the level
  // Memory: the most the level's working set held at once in any request (its blocks with
  // triples, colours and frames, the history snapshots its corrections read, a step's results),
  // and what its cache of finished triples holds now (kept for later requests).
  std::int64_t peakWorkingBytes = 0;
  std::int64_t cachedBytes = 0;
  bool fromDiskCache = false;  // the coarsest level: read from the disk cache instead of synthesized
};

class LazySolid {
 public:
  static constexpr int kBlock = 4;  // block side in voxels (also the planning granularity)

  // One exemplar for all three planes, or three (same size and channels). Analyses and
  // candidate triples are computed (through the cache when options.cacheDirectory is set).
  // Throws ParameterError for bad options or exemplars (too small for `levels`, mismatched).
  LazySolid(const Image& exemplar, const LazySolidOptions& options, LazyOrientation orientation = {},
            Progress& progress = noProgress());
  LazySolid(const Image& xy, const Image& yz, const Image& zx, const LazySolidOptions& options,
            LazyOrientation orientation = {}, Progress& progress = noProgress());
  ~LazySolid();
  LazySolid(const LazySolid&) = delete;
  LazySolid& operator=(const LazySolid&) = delete;

  const LazySolidOptions& options() const { return options_; }
  int levels() const { return options_.levels; }
  int colorChannels() const;
  const ExemplarAnalysis& analysis(Plane plane) const;
  const CandidateTriples& candidates(int level) const { return triples_[std::size_t(level)]; }
  const std::vector<LazyLevelStats>& stats() const { return stats_; }

  // Synthesizes (if not cached) every finest-level voxel listed, and whatever they depend on.
  // |coordinate| must stay below 2^19 (ParameterError("voxels", ...)). Progress: one unit per level.
  void synthesize(std::span<const Vec3i> voxels, Progress& progress = noProgress());
  // Every voxel of the box [min, min + size).
  void synthesizeBox(const Vec3i& min, const Vec3i& size, Progress& progress = noProgress());
  // Synthesizes (or reads from the disk cache) the coarsest level's torus now; the first request
  // does it otherwise. Results do not change: a voxel's triple never depends on what was requested.
  void prepareCoarsestLevel(Progress& progress = noProgress());
  // The coarsest level's torus, in coarsest-level voxels (multiples of kBlock).
  Vec3i coarsestTorusMin() const { return torusMin_; }
  Vec3i coarsestTorusSize() const { return torusSize_; }

  // True if the finest-level voxel has been synthesized.
  bool ready(const Vec3i& voxel) const;
  // The triple of a synthesized voxel at `level` (finest = levels() - 1); TS_CHECK otherwise.
  CoordinateTriple triple(const Vec3i& voxel, int level) const;
  // Colour of a synthesized finest voxel from the three exemplars' colours at its triple (colour
  // channels only), combined by options().colorRule. Throws
  // ParameterError("voxel", ...) if the voxel was never synthesized.
  void color(const Vec3i& voxel, float* out) const;

  struct Impl;

 private:
  void initialize(const Image& xy, const Image& yz, const Image& zx, Progress& progress);
  // Digest of everything the coarsest level depends on (0: not cacheable on disk).
  std::uint64_t coarsestCacheKey(const Image& xy, const Image& yz, const Image& zx) const;
  // The coarsest level, whole, on its torus (from the disk cache when possible).
  void synthesizeCoarsest(Progress& progress);
  // Runs one level's synthesis for a plan (upsampling or initialization, then its corrections)
  // and caches the plan's delivered blocks; `torus`: the coarsest level's whole torus. With
  // `exact` (the voxels the level delivers), the last step corrects only those voxels, and only
  // they are cached as final.
  void synthesizeLevel(int level, const lazy::LazyDependencyPlan& plan, bool torus, Progress& progress,
                       const std::vector<lazy::BlockMask>* exact = nullptr);
  // Synthesizes the requested finest voxels (and what they need on coarser levels).
  void synthesizeRequested(std::vector<lazy::BlockMask> requested, Progress& progress);
  // True where the level runs dual-grid correction (every level but the coarsest, if enabled).
  bool gridded(int level) const;
  // True where the level is planned voxel by voxel (planExactLevel: the standard scheme, s = 1).
  bool exactPlans(int level) const;
  // The dependency plan of one level for blocks it must deliver (lazy_blocks.h).
  lazy::LazyDependencyPlan planForLevel(int level, const std::vector<std::uint64_t>& deliver) const;
  lazy::LevelContext context(int level) const;

  LazySolidOptions options_;
  LazyOrientation orientation_;
  std::vector<ExemplarAnalysis> analyses_;  // 1 (shared) or 3
  std::vector<CandidateTriples> triples_;   // per level
  std::vector<LazyLevelStats> stats_;
  Vec3i torusMin_ = Vec3i::Zero(), torusSize_ = Vec3i::Zero();
  std::uint64_t coarsestKey_ = 0;
  std::unique_ptr<Impl> impl_;  // the per-level block caches
};

}  // namespace texsynth
