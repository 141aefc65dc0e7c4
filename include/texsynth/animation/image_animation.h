#pragma once
// Flow animation on a toroidal image (see flow_animation.h): each frame a width x height
// texture that tiles, carried by a velocity field (image_flow.h) from the frame before.
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/animation/flow_advection.h"
#include "texsynth/animation/flow_animation.h"
#include "texsynth/core/image.h"
#include "texsynth/core/progress.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/image/texture_optimization.h"

namespace texsynth {

class ImageAnimator {
 public:
  // Synthesizes frame 0: optimizeTexture with `synthesis` (seed included), started from parallel
  // synthesis at its defaults when `parallelAnalysis` is given (the static `optimize` method's
  // best start). `analyses` are optimizationAnalysisOptions(synthesis) and must outlive the
  // animator, as must `parallelAnalysis`. width and height must be multiples of 4 (the torus
  // holds whole strides). Throws ParameterError for options, sizes or analyses that do not fit.
  ImageAnimator(std::span<const ExemplarAnalysis> analyses, const ExemplarAnalysis* parallelAnalysis,
                const TextureOptimizationOptions& synthesis, const FlowAnimationOptions& options, int width, int height,
                Progress& progress = noProgress());

  // The next frame, carried by `velocities` (width x height, 2 channels, output pixels per frame).
  void advance(const Image& velocities, Progress& progress = noProgress());

  int frame() const { return frame_; }
  const Image& colors() const { return colors_; }  // the exemplar's color channels
  const ExemplarPositions& positions() const { return positions_; }
  const FrameStatistics& statistics() const { return statistics_; }

 private:
  std::vector<std::int32_t> staticSynthesis(std::uint64_t seed, Progress& progress) const;
  Image colorsOf(std::span<const std::int32_t> sources) const;

  std::span<const ExemplarAnalysis> analyses_;
  const ExemplarAnalysis* parallelAnalysis_;
  TextureOptimizationOptions synthesis_;
  FlowAnimationOptions options_;
  int width_, height_;
  int frame_ = 0;
  ExemplarPositions positions_;
  Image colors_;
  FrameStatistics statistics_;
};

}  // namespace texsynth
