#pragma once
// Internal to gradient synthesis: the final refinement (§4.3). The last iteration's complete buckets
// (the finest level's voxels) arrive layer by layer; every few control layers, the slab they fill is
// vectorized in overlapping tiles (region separation with dilation, optional eq. 3, residual detail:
// vectorize.h) and the tiles' inner control points are kept. Memory stays a slab, not the volume.
#include <vector>

#include "synthesis_sweep.h"
#include "texsynth/gradient/vectorize.h"

namespace texsynth::gradient_synthesis {

class SlabRefiner {
 public:
  // `state`: the feature-vector solid (fills voxels no sample reached); `colorChannels` of its channels
  // are colours, and with `regions` the next one is the mask's signed distance feature.
  SlabRefiner(const GradientSolid& state, int colorChannels, bool regions, const VectorizeOptions& options);
  void take(const ClosedLayer& layer);  // in z order, every voxel layer once
  GradientSolid finish();               // after the last layer
  std::int64_t peakBytes() const { return peakBytes_; }

 private:
  void refineSlab();
  void refineTile(const Vec3i& coreBegin, const Vec3i& coreEnd);

  const GradientSolid& state_;
  int colors_;
  bool regions_;
  VectorizeOptions options_;
  GradientSolid out_;
  int nextCore_ = 0;           // first control layer of the next slab's core
  int bufferBegin_ = 0;        // voxel z of buffer_'s first layer
  std::vector<float> buffer_;  // voxel layers [bufferBegin_, ...), colours (+ 1 mask) per voxel
  std::int64_t peakBytes_ = 0;
};

}  // namespace texsynth::gradient_synthesis
