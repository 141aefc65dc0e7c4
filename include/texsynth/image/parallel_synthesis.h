#pragma once
// Parallel controllable texture synthesis (Lefebvre & Hoppe 2005) in 2D on an infinite
// output domain. Synthesis works on SOURCE COORDINATES into the exemplar (toroidal), level by
// level from the coarsest Gaussian-stack level: coordinate upsampling, deterministic jitter,
// then k-coherence correction passes in PCA space with s^2 = 4 subpasses. Colors are looked
// up at the end from the finest stack level.
//
// Random access: every value depends only on (seed, absolute pixel position, level, pass),
// and each coarser level is synthesized over exactly the padded region the finer level reads,
// so any window is bit-identical to the same region of a larger output, for any thread count.
//
// The building blocks (upsampleCoordinates, jitterCoordinates, correctCoordinates) are
// exposed; texture optimization starts each finer level with the first two. Lazy solid
// synthesis has its own 3D versions (src/solid/lazy_upsample.cpp, lazy_correction.cpp).
#include <cstdint>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/progress.h"
#include "texsynth/exemplar/analysis.h"

namespace texsynth {

struct ParallelSynthesisOptions {
  // Seed of the jitter (the only randomness).
  std::uint64_t seed = 1;
  // Correction passes per level; L&H 2005 use 2. 0 gives the uncorrected, upsampled and
  // jittered coordinates (useful as a baseline).
  int passes = 2;
  // s: each pass corrects the s x s pixel classes in turn (s^2 subpasses), so a pixel sees
  // its already corrected neighbours. L&H 2005: s = 2 (4 subpasses); 1 = all pixels at once.
  int subpassGrid = 2;
  // Jitter strength r_l per level, coarsest first; empty = `defaultJitter` at every level.
  // The displacement is floor(h_l * r_l * xi + 1/2) with xi uniform in [-1, 1]^2, so r_l < 0.5
  // has no effect at the finest level (h = 1). L&H 2005 expose r_l as user sliders; 0.4 at
  // every level gave the lowest coherence with periodicity < 0.05 on full GIMP patterns at
  // 256^2 (pink_marble, granite1, wood1, brick). Raising the two coarsest levels to 1.0 / 0.7
  // breaks the residual lattice of repeated features better (visibly so at 512^2 from 128^2,
  // and for small non-tileable crops) at a ~15% higher coherence.
  std::vector<float> jitter = {};
  float defaultJitter = 0.4f;
  // Where synthesis starts. A GIMP pattern tiles, and its analysis is toroidal, so a tiled copy
  // of it is a perfect solution to every correction: started from L&H 2005's tiling at a level
  // whose neighborhoods span the whole exemplar, the corrections keep the output a jittered
  // tiling, a lattice of repeats (GIMP leaves at 256^2: lattice 0.58). Instead, synthesis
  // starts at the coarsest level whose neighborhood footprint N_l h_l is at most this fraction
  // of the exemplar's smaller side, from uniformly random coordinates there, and the
  // corrections grow coherent patches of it at random places (leaves: lattice 0.09). 0 = L&H
  // 2005: the coarsest level, from the tiling.
  float coarsestFootprint = 1.0f;
  // Correction passes at that first level (at least `passes`; none when passes = 0): random
  // coordinates need more
  // than two to grow coherent patches (6: GIMP rock, bark, brick at 256^2, completeness 1.3x
  // lower than with 2, coherence 3% lower).
  int startPasses = 6;
  // How strongly a correction keeps patches whole: the candidate that continues a neighbor's
  // patch (its coordinate, shifted) has its distance scaled by 1 - bias, so it wins unless a
  // jump is clearly nearer, as Ashikhmin's and Hertzmann's coherence terms favor coherent
  // sources. In [0, 1); 0 = L&H 2005. 12 GIMP exemplars at 256^2, seeds 1-3, 0 -> 0.4: coherence
  // 3-4% lower, completeness 27-33% lower, sharpness 0.91 -> 0.97, coherence's 90th percentile
  // 1.5-2% higher, lattice the same (0.7: no better).
  float continuationBias = 0.4f;
};

// Source coordinates of a window of the (infinite) synthesized grid of one level: pixel
// (x0 + i, y0 + j) stores the exemplar pixel (xy[2k], xy[2k+1]), k = j * width + i, always
// inside [0, exemplar width) x [0, exemplar height).
struct SourceCoordinates {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  std::vector<std::int32_t> xy;

  SourceCoordinates() = default;
  SourceCoordinates(int x0, int y0, int width, int height)
      : x0(x0), y0(y0), width(width), height(height), xy(std::size_t(width) * height * 2, 0) {}
  std::size_t offset(int x, int y) const { return (std::size_t(y - y0) * width + (x - x0)) * 2; }
  // Coordinates of absolute pixel (x, y); it must lie inside the window.
  std::int32_t* at(int x, int y) { return xy.data() + offset(x, y); }
  const std::int32_t* at(int x, int y) const { return xy.data() + offset(x, y); }
  // Every pixel's coordinates as an exemplar pixel index y * exemplarWidth + x, row by row (the
  // discrete solvers' sources).
  std::vector<std::int32_t> pixelIndices(int exemplarWidth) const {
    std::vector<std::int32_t> pixels(xy.size() / 2);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = xy[2 * i + 1] * exemplarWidth + xy[2 * i];
    return pixels;
  }
};

// Synthesizes the source coordinates of output window (x0, y0, w, h) at the finest level.
// Throws ParameterError for an empty analysis ("analysis"), a bad window ("width",
// "height", "x0", "y0": requireWindow's +-2^28), passes < 0 ("passes"), a continuation bias
// outside [0, 1) ("continuationBias"), or a jitter list of the wrong size or with negative / non-finite entries
// ("jitter"). Progress: one stage, one unit per level.
SourceCoordinates synthesizeParallelCoordinates(const ExemplarAnalysis& analysis,
                                                const ParallelSynthesisOptions& options, int x0, int y0, int w, int h,
                                                Progress& progress = noProgress());

// The same at a coarser `level` (0 = coarsest), on that level's own grid (pixel p of level l
// is the parent of the finer level's 2p and 2p + 1): what the finer levels would upsample, at a
// fraction of the cost. Below the level synthesis starts at (firstSynthesizedLevel), that
// level read every 2^(difference) pixels. Also throws ParameterError("level").
SourceCoordinates synthesizeParallelLevelCoordinates(const ExemplarAnalysis& analysis,
                                                     const ParallelSynthesisOptions& options, int level, int x0, int y0,
                                                     int w, int h, Progress& progress = noProgress());

// The same, returning colors (the exemplar's channels, without the feature channel).
Image synthesizeParallel(const ExemplarAnalysis& analysis, const ParallelSynthesisOptions& options, int x0, int y0,
                         int w, int h, Progress& progress = noProgress());

// Colors of `image` at the coordinates (first `channels` channels; 0 = all), a
// coords.width x coords.height image. Also re-applies one synthesis to another map.
Image lookupColors(const Image& image, const SourceCoordinates& coords, int channels = 0);

// ---- Building blocks (also used by texture optimization) ----

// Margin, in pixels of `level`, by which `passes` corrections shrink the valid region: every
// subpass reads neighborhoods of radius max(N_l/2, 1), and a pass has s^2 subpasses.
int correctionMargin(const ExemplarAnalysis& analysis, int level, int passes, int subpassGrid = 2);

// The finer level's coordinates over `region` (x0, y0, width, height; its fields only, xy
// ignored) from the coarser level's `parent`, which must cover floor(region / 2):
//   S_l[p] = (S_{l-1}[floor(p/2)] + floor(h_l * (delta - 1/2))) mod m,  delta = p mod 2,
// the stack form of L&H 2005's upsampling (stack coordinates keep full resolution, so the
// parent coordinate is not doubled; children sit h_l apart, centred on the parent).
SourceCoordinates upsampleCoordinates(const SourceCoordinates& parent, const SourceCoordinates& region, int spacing,
                                      int exemplarWidth, int exemplarHeight);

// The coarsest level's start over `region`: S(p) = (h_0 p) mod m, the exemplar tiled at the
// level's spacing. This is L&H 2005's S = 0 at their one-pixel level (h = m, so all of its
// pixels coincide mod m) upsampled to the first stack level; a constant S = 0 here would put
// the same coordinate h_0 apart and break coherence between neighbors.
SourceCoordinates tilingCoordinates(int x0, int y0, int width, int height, int spacing, int exemplarWidth,
                                    int exemplarHeight);

// Uniformly random coordinates, a function of (seed, absolute position, level) only.
SourceCoordinates randomCoordinates(int x0, int y0, int width, int height, std::uint64_t seed, int level,
                                    int exemplarWidth, int exemplarHeight);

// The level synthesis starts at (see ParallelSynthesisOptions::coarsestFootprint).
int firstSynthesizedLevel(const ExemplarAnalysis& analysis, float coarsestFootprint);

// Adds J_l(p) = floor(h_l * r * xi(seed, p, level) + 1/2), xi in [-1, 1]^2, to every pixel,
// wrapping into the exemplar. r = 0 leaves the coordinates unchanged.
void jitterCoordinates(SourceCoordinates& coords, int level, int spacing, float strength, std::uint64_t seed,
                       int exemplarWidth, int exemplarHeight);

// One correction pass at `level`: s^2 subpasses (s = subpassGrid), one per pixel class
// (x mod s, y mod s): for s = 2 (0,0), (1,1), (1,0), (0,1) in turn, else row by row; each such pixel takes, among the
// candidates similar_k(S[p + d] - h_l d) for d in 3x3 and every k, the one whose exemplar neighborhood is nearest in
// the level's PCA space to the neighborhood of colors gathered at the current coordinates, the continuations (k = 0)
// at 1 - continuationBias times their distance (ties: first candidate in d-major, k-minor order, d = (0,0) first).
// Returns the region shrunk by correctionMargin(analysis, level, 1, s) on every side (the part still exact).
SourceCoordinates correctCoordinates(const ExemplarAnalysis& analysis, int level, const SourceCoordinates& coords,
                                     int subpassGrid = 2, float continuationBias = 0.0f);

// Mean over the window's pixels whose neighborhood lies inside it of the squared PCA-space
// distance between the gathered neighborhood and the exemplar neighborhood at S[p]: how far
// the synthesized level is from being locally a copy of the exemplar (0 = perfect).
double meanNeighborhoodDistance(const ExemplarAnalysis& analysis, int level, const SourceCoordinates& coords);

}  // namespace texsynth
