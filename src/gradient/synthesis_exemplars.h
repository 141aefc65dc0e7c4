#pragma once
// Internal to gradient synthesis: what a prepared exemplar set holds (see GradientExemplars).
#include <array>
#include <memory>
#include <vector>

#include "texsynth/exemplar/analysis.h"
#include "texsynth/exemplar/color_clusters.h"
#include "texsynth/exemplar/crossbar_index.h"
#include "texsynth/exemplar/projected_index.h"
#include "texsynth/gradient/gradient_synthesis.h"

namespace texsynth {

// Slice planes in matching order: s_x (normal x: u = y, v = z) against the YZ exemplar, s_y (normal y:
// u = z, v = x) against ZX, s_z (normal z: u = x, v = y) against XY (the planes' axes of eq. 4).
enum class SlicePlane { X = 0, Y = 1, Z = 2 };

struct GradientExemplars::Impl {
  GradientExemplarOptions options;
  int width = 0, height = 0;
  int colorChannels = 3;
  bool hasMask = false;
  int features = 3;  // channels of every level image and of the synthesized feature vector

  // Nearest patches are shortlisted on the leading PCA dimensions (a fast low-dimensional KD search) and
  // re-ranked on all of them.
  static constexpr int kTreeDimensions = 8;
  static constexpr float kTreeEpsilon = 1.0f;

  struct Level {
    const ExemplarLevel* level = nullptr;                 // of the plane's analysis
    std::shared_ptr<std::vector<float>> leading;          // per pixel its first kTreeDimensions projected coordinates
    std::shared_ptr<ProjectedNeighborhoodIndex> nearest;  // over `leading`
    std::shared_ptr<CrossbarIndex> crossbars;
  };
  // Per slice plane (X, Y, Z order above); planes sharing an image share everything.
  std::array<std::shared_ptr<const ExemplarAnalysis>, 3> analyses;
  std::array<std::vector<Level>, 3> levels;
  // Clusters of the finest level's colours, over all planes together; labels per plane.
  ColorClusters clusters;
  std::array<std::vector<std::uint8_t>, 3> labels;

  const Level& at(SlicePlane plane, int level) const { return levels[int(plane)][std::size_t(level)]; }
};

}  // namespace texsynth
