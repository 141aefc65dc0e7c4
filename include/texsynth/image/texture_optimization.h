#pragma once
// Texture optimization (Kwatra et al. 2005) with the discrete k-coherence solver of Han et al.
// ("Fast example-based surface texture synthesis via discrete optimization"), on image grids.
//
// The output minimizes E(x) = sum_{p in X} |x_p - z_p|^2 over a sparse set X of output
// neighborhoods (centres `stride` = N/4 apart, as Kwatra), z_p the exemplar neighborhood that
// matches x_p. EM-like iterations alternate
//   E-step: the output given the matches. Discrete (Han): each pixel picks, from its
//           k-coherence candidate set, the exemplar pixel that lowers the energy most, so
//           the output stays a map of SOURCE COORDINATES and stays crisp. Least squares
//           (Kwatra): each pixel becomes the robust (IRLS, exponent 0.8) weighted mean of the
//           colors the overlapping matches vote for, which blurs.
//   M-step: the matches given the output. Discrete: k-coherence search among the candidates
//           the output's own coordinates propose, ranked in PCA space. Least squares: KD-tree
//           search in PCA space (the coordinates k-coherence needs are lost to blending).
// until no match changes. Multiresolution over the exemplar's Gaussian stack (3 levels as in
// Han et al. Table 2), each level run with neighborhoods 17^2 then 9^2.
//
// The plain discrete energy leaves parts of the exemplar out (thin features lose the vote, a
// flat region copied everywhere costs nothing), so by default the discrete solver also weighs
// E-step votes by their match's quality, adds an exemplar-usage term and random candidates to
// the M-step, and is best started from parallel synthesis (see the options and optimizeTexture).
//
// Two guards against the flat optimum: the active neighborhoods' lattice moves every step (no
// straight seams along a fixed grid of patch borders), and a level whose E+M steps raise its
// share of flat patches by more than `collapseTolerance` is undone (GIMP cracked: the thin
// cracks and the fine relief between them would be voted away into one flat gray).
//
// The output domain is a torus (no borders: every pixel sits in full neighborhoods), so an
// output whose sides are multiples of 4 (the largest active-set stride) tiles seamlessly. It is a global
// optimization: unlike the other 2D methods it is not random access. Deterministic for any
// thread count.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/progress.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/image/parallel_synthesis.h"

namespace texsynth {

enum class OptimizationSolver {
  Discrete,      // Han et al.: k-coherence E- and M-steps; keeps source coordinates
  LeastSquares,  // Kwatra et al. 2005: blended E-step, KD-tree M-step
};

// "discrete", "least-squares"; parseOptimizationSolver throws ParameterError("solver") otherwise.
std::string optimizationSolverName(OptimizationSolver solver);
OptimizationSolver parseOptimizationSolver(const std::string& name);

enum class OptimizationStart {
  RandomPatches,  // random coherent blocks of the exemplar (default)
  RandomPixels,   // every pixel random (Han et al. 2.3; washes structured exemplars out)
};

struct TextureOptimizationOptions {
  std::uint64_t seed = 1;  // of the random initialization at the coarsest level
  OptimizationSolver solver = OptimizationSolver::Discrete;
  // Resolution levels (stack levels with spacing 2^(levels-1) ... 1); Han et al. use 3.
  // (With many more, the toroidal exemplar lets the coarse levels settle on a perfect copy of
  // it, energy 0, which the finer levels keep: a tiling.)
  int levels = 3;
  // Neighborhood sizes run in turn at every level (Han et al. Table 2: 17^2 then 9^2).
  std::vector<int> neighborhoodSizes = {17, 9};
  // Most E+M iterations per neighborhood size; stops earlier when no match changes
  // (Table 2: 1-3 per size; 3 lowers coherence by about 1% over 2 at 1.2x the time).
  int maxIterations = 2;
  // The same at the finest level, whose start the coarser levels have already settled (12 GIMP
  // exemplars at 512^2: 1 instead of 2 takes 0.84x the time, coherence and its 90th percentile
  // within 1%).
  int finestIterations = 1;
  // How the coarsest level starts, and the jitter of the finer levels after upsampling
  // (strength as in parallel synthesis; 0 = none: the optimization itself removes it).
  OptimizationStart start = OptimizationStart::RandomPatches;
  int startPatchSize = 4;  // output pixels of the coarsest level per random patch (8: periodicity up ~1.5x)
  float jitter = 0.0f;
  // k of the k-coherence candidate sets (similarity set size, the pixel itself included).
  int similarCount = 4;
  // PCA dimensions of the least-squares solver's KD-tree search.
  int pcaDimensions = 20;
  // Weight of the exemplar-usage term of the discrete M-step (an index histogram, as Chen &
  // Wang 2010): over-used exemplar regions cost more, unused ones less, so the output keeps
  // every part of the exemplar (0 = plain energy, which drops thin or rare features: GIMP rock
  // at 256^2, completeness 20.3 without, 9.5 with 0.15).
  float coverageWeight = 0.15f;
  // The discrete E-step weighs each covering match's vote by (d + 0.01)^-voteExponent, d its
  // mean color distance per pixel (Kwatra's robust weights): well-aligned matches decide, so
  // thin features are not voted away by the misaligned majority (0 = equal votes, Han et al.;
  // rock completeness 9.5 -> 2.5 with 4).
  float voteExponent = 4.0f;
  // Uniformly random candidates per match in the discrete M-step, besides the k-coherence ones,
  // at every level but the finest (where they no longer change the result, at 1.2x its time).
  int randomCandidates = 16;
  // The collapse guard: a level's E+M steps are undone when they raise its share of flat
  // patches (flat_patch_share.h) by more than this (discrete solver only; 1 turns it off).
  double collapseTolerance = 0.15;
  // Active neighborhoods on a lattice that moves before every M-step, to an offset in
  // [0, stride)^2 hashed from (seed, level, size, step), each match carried along. On a fixed
  // lattice the E-step's votes leave square patch borders that line up into straight seams
  // through stones (12 GIMP exemplars at 256^2, means: coherence 6.58 -> 6.31, its 90th
  // percentile 13.28 -> 12.54 with the moving lattice). false = Kwatra's fixed lattice.
  bool movingLattice = true;
  // The discrete solver's output colors: seams between exemplar pieces feathered by a Gaussian
  // of this many output pixels (image/seam_blend.h; the coordinates stay crisp; 0 = none).
  // 12 GIMP exemplars at 256^2: 1.0 -> coherence 6.06, 90th percentile 11.88; 1.5 -> 5.95,
  // 11.59; 2.0 (radius 3) -> 5.86, 11.37 with histogram 1.49 -> 1.79 and sharpness 0.92.
  float seamBlend = 1.5f;
  // Robust exponent r of Kwatra's least-squares E-step (|x_p - z_p|^r, solved by IRLS).
  float robustExponent = 0.8f;
};

// One M-step's outcome: the energy of the current output against the new matches.
struct OptimizationIteration {
  int level = 0;             // 0 = coarsest
  int neighborhoodSize = 0;  // N of this step
  int iteration = 0;         // 0 = the matches of the output as it came in (no E-step yet)
  double energy = 0;         // sum_p |x_p - z_p|^2 / (|X| * N^2): mean squared error per pixel
  std::int64_t changedMatches = 0;
  std::int64_t neighborhoods = 0;  // |X|
  double seconds = 0;              // wall time of this E+M step
};

struct TextureOptimizationResult {
  Image colors;  // width x height, the exemplar's color channels
  // The source coordinates of every output pixel (discrete solver only; empty otherwise).
  SourceCoordinates coords;
  std::vector<OptimizationIteration> history;
  int undoneLevels = 0;  // levels whose E+M steps the collapse guard undid
  // Levels synthesized with the exemplar's feature channel (FeatureAnalyses below): the one
  // whose colors-only E+M steps were undone and every finer one.
  int featureLevels = 0;
};

// The exemplar analyses the solver needs, one per neighborhood size in order (its PCA), all
// with levelCount = options.levels; the discrete solver also reads the last one's similarity
// sets (k = similarCount; the others have k = 1, no search).
std::vector<AnalysisOptions> optimizationAnalysisOptions(const TextureOptimizationOptions& options);

// `analyses` with the feature channel of Lefebvre & Hoppe 2006 made from `exemplar`'s
// distinctive colors (distinctive_colors.h; their signed distance, feature_distance.h) at
// `weight` (colors span 0..1): matching a color and its distance to the nearest feature keeps
// thin features (cracks, veins, mortar) that colors alone let a flat background replace: a
// neighborhood a pixel off a crack pays little for its misregistration in the smooth distance,
// one far from any crack pays for the crack it lacks. Unchanged for weight 0 and for an exemplar
// without distinctive colors (a flat one). Throws ParameterError("feature weight", ...) for a
// negative or non-finite weight.
std::vector<AnalysisOptions> withFeatureChannel(std::vector<AnalysisOptions> analyses, const Image& exemplar,
                                                float weight);

// The weight of the feature channel when 2D optimization falls back to it (FeatureAnalyses). 12
// GIMP exemplars at 256^2, the channel on GIMP cracked from the start, seeds 1-5: sharpness
// 0.61-0.75 -> 0.94-0.96, coherence 4.7-5.6 -> 2.6-2.9 (1.0: the same within noise).
inline constexpr float kOptimizationFeatureWeight = 0.5f;

// The analyses optimizeTexture reads (optimizationAnalysisOptions(options)) for `exemplar`,
// through the analysis cache in `cacheDirectory` (analysis_cache.h).
std::vector<ExemplarAnalysis> cachedOptimizationAnalyses(const Image& exemplar,
                                                         const TextureOptimizationOptions& options,
                                                         const std::string& cacheDirectory,
                                                         Progress& progress = noProgress());

// The analyses of optimizationAnalysisOptions with the feature channel (withFeatureChannel at
// kOptimizationFeatureWeight), made on first use: an analysis takes seconds the first time, and
// most exemplars never need it. Returns none for an exemplar without distinctive colors.
using FeatureAnalyses = std::function<std::vector<ExemplarAnalysis>()>;

// FeatureAnalyses for `exemplar` and `options` through the analysis cache in `cacheDirectory`
// (analysis_cache.h), reporting to `progress`; `exemplar` and `progress` must outlive it.
FeatureAnalyses cachedFeatureAnalyses(const Image& exemplar, const TextureOptimizationOptions& options,
                                      std::string cacheDirectory, Progress& progress = noProgress());

// The start optimizeTexture reads best: parallel synthesis (`parallelAnalysis`, `parallel`)
// run only up to the level of the exemplar's stack that optimization starts at, on that level's
// grid (the finer levels, which the optimization redoes, are never synthesized). Throws what
// optimizeTexture and synthesizeParallelCoordinates throw for bad options.
SourceCoordinates parallelOptimizationStart(const ExemplarAnalysis& parallelAnalysis,
                                            const ParallelSynthesisOptions& parallel,
                                            std::span<const ExemplarAnalysis> analyses,
                                            const TextureOptimizationOptions& options, int width, int height,
                                            Progress& progress = noProgress());

// Synthesizes a width x height texture. `analyses` must be what optimizationAnalysisOptions
// asked for, computed on one exemplar. `start`, if given, are source coordinates to start from:
// of at least width x height output pixels at the finest level, read at the first level, or
// exactly the first level's grid (what parallelOptimizationStart makes). Parallel synthesis is
// the discrete solver's best start (it keeps every part of the exemplar and no lattice);
// without one, options.start. Levels whose largest neighborhood does not fit inside the
// exemplar are skipped: there a tiled copy of the exemplar would be a zero-energy optimum.
// Throws ParameterError for bad options ("levels", "neighborhood", "iterations",
// "similarCount", "robustExponent", "collapseTolerance", "analyses"), size ("width", "height") or start ("start").
// Progress: one stage per level.
// With `featureAnalyses` (discrete solver): a level whose E+M steps the collapse guard undoes is
// run again from its start on the analyses with the feature channel, which every finer level
// then uses too (GIMP cracked: colors alone flatten every level, so the output was the start's
// coarsest level upsampled). The guard judges the second run as the first; exemplars whose
// levels are kept never call it and give the same bits as without.
TextureOptimizationResult optimizeTexture(std::span<const ExemplarAnalysis> analyses,
                                          const TextureOptimizationOptions& options, int width, int height,
                                          Progress& progress = noProgress(), const SourceCoordinates* start = nullptr,
                                          const FeatureAnalyses& featureAnalyses = {});

}  // namespace texsynth
