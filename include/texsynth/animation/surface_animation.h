#pragma once
// Flow animation on a mesh surface (see flow_animation.h): vertex colors of the prepared
// surface's finest level, carried by a tangent velocity field (surface_flow.h).
#include <memory>
#include <span>
#include <vector>

#include "texsynth/animation/flow_advection.h"
#include "texsynth/animation/flow_animation.h"
#include "texsynth/core/progress.h"
#include "texsynth/geometry/surface_projector.h"
#include "texsynth/surface/surface_level_measures.h"
#include "texsynth/surface/surface_synthesis.h"

namespace texsynth {

class SurfaceAnimator {
 public:
  // Synthesizes frame 0 (synthesizeSurface). `analyses` and `surface` must outlive the animator.
  // Throws ParameterError as synthesizeSurface and validateFlowAnimationOptions do.
  SurfaceAnimator(std::span<const ExemplarAnalysis> analyses, const PreparedSurface& surface,
                  const TextureOptimizationOptions& synthesis, const FlowAnimationOptions& options,
                  Progress& progress = noProgress());

  // The next frame, carried by `velocities` (per vertex of the finest level, tangent, world units
  // per frame). Throws ParameterError("velocities", ...) for the wrong count.
  void advance(std::span<const Vec3f> velocities, Progress& progress = noProgress());

  int frame() const { return frame_; }
  const std::vector<Vec3f>& colors() const { return colors_; }  // per vertex, RGB
  const std::vector<std::int32_t>& sources() const { return sources_; }
  const ExemplarPositions& positions() const { return positions_; }
  const FrameStatistics& statistics() const { return statistics_; }

 private:
  std::span<const ExemplarAnalysis> analyses_;
  const PreparedSurface& surface_;
  TextureOptimizationOptions synthesis_;
  FlowAnimationOptions options_;
  SurfaceProjector projector_;
  int frame_ = 0;
  std::vector<std::int32_t> sources_;
  ExemplarPositions positions_;
  std::vector<Vec3f> colors_;
  FrameStatistics statistics_;
  SurfaceLevelMeasures reference_;  // frame 0's flatness and distinctive colors
};

}  // namespace texsynth
