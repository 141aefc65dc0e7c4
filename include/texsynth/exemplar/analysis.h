#pragma once
// Exemplar analysis: everything synthesizers precompute from an exemplar, once.
// For each Gaussian stack level: the level image (exemplar channels plus an optional
// feature channel), the PCA basis of its N x N neighborhoods, every pixel's projected
// neighborhood, and every pixel's k-coherence similarity set.
#include <cstdint>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/progress.h"
#include "texsynth/exemplar/neighborhood.h"
#include "texsynth/exemplar/pca.h"
#include "texsynth/exemplar/similarity_sets.h"

namespace texsynth {

struct AnalysisOptions {
  // Stack levels L; 0 = floor(log2(min(width, height))) as in L&H 2005.
  int levelCount = 0;
  // Neighborhood side N (odd). 5 as in L&H 2005; lazy solids use 7 and 9, texture optimization 17 and 9.
  int neighborhoodSize = 5;
  // Optional N per level, coarsest first; the last entry also serves every finer level (the
  // sketch-guided solid paper: {7, 9} = 7 at the coarsest, 9 elsewhere). Empty = N everywhere.
  std::vector<int> levelNeighborhoodSizes;
  // PCA dimensions D kept per level (at most N*N*channels). ~20 per the sketch-guided
  // solid paper; L&H 2005 keep a similar handful.
  int pcaDimensions = 20;
  // Similarity set size k including the pixel itself; 2 as in L&H 2005.
  int similarCount = 2;
  // Toroidal exclusion radius r of the similarity sets; -1 = N/2.
  int exclusionRadius = -1;
  // Nearest-neighbour backend and its tuning (backend default chosen by measurement).
  SimilarityOptions search;
  // Optional binary mask the exemplar's size (nonzero = feature). When given, each level
  // gets one more channel: featureWeight * signedDistance / max|signedDistance|.
  Image featureMask;
  // Weight of that channel relative to colors in [0, 1]; 1 makes a feature boundary
  // count like a full-range color edge.
  float featureWeight = 1.0f;
};

struct ExemplarLevel {
  int spacing = 1;                    // h_l = 2^(L-1-l)
  int neighborhoodSize = 5;           // N of this level
  Image image;                        // stack level; channels = exemplar's (+1 feature)
  PcaBasis pca;                       // of this level's neighborhoods
  std::vector<float> projected;       // pixelCount x pca.outputDimension
  std::vector<std::int32_t> similar;  // pixelCount x similarCount; [0] = the pixel itself

  NeighborhoodShape shape() const { return {neighborhoodSize, spacing, image.channels}; }
  const float* projectedAt(std::int32_t pixel) const {
    return projected.data() + std::size_t(pixel) * pca.outputDimension;
  }
  PixelVectors projectedVectors() const { return {projected.data(), image.width, image.height, pca.outputDimension}; }
};

struct ExemplarAnalysis {
  int width = 0, height = 0;
  int colorChannels = 0;           // channels of the exemplar image
  bool hasFeatureChannel = false;  // if so, the last channel of every level
  int neighborhoodSize = 5;        // AnalysisOptions::neighborhoodSize; levels[l].neighborhoodSize may differ
  int similarCount = 2;
  int exclusionRadius = 2;
  std::vector<ExemplarLevel> levels;  // [0] coarsest ... back() = exemplar resolution, h = 1

  int levelCount() const { return int(levels.size()); }
  int channels() const { return colorChannels + (hasFeatureChannel ? 1 : 0); }
  std::int32_t pixelIndex(int x, int y) const { return std::int32_t(y) * width + x; }
  NeighborhoodShape shape(int level) const { return levels[level].shape(); }
  // The k similar pixels of `pixel` at `level` (similarCount entries, first = pixel).
  const std::int32_t* similarAt(int level, std::int32_t pixel) const {
    return levels[level].similar.data() + std::size_t(pixel) * similarCount;
  }
};

// N of `level` (0 = coarsest) under these options.
int neighborhoodSizeAt(const AnalysisOptions& options, int level);

// Validates options against the exemplar; throws ParameterError naming the bad one
// (empty image, even or too large N, D < 1, k < 1, bad level count, mask size mismatch ...).
void validateAnalysisOptions(const Image& exemplar, const AnalysisOptions& options);

// Runs the whole analysis. Progress stages: stack, feature distance, then per level PCA
// and similarity sets. Identical results for any thread count.
ExemplarAnalysis analyzeExemplar(const Image& exemplar, const AnalysisOptions& options = {},
                                 Progress& progress = noProgress());

}  // namespace texsynth
