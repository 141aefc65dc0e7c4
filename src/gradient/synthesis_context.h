#pragma once
// Internal to gradient synthesis: one level's settings, check points and the bucket geometry shared by
// matching, bucket filling and fitting.
#include <cmath>
#include <cstdint>
#include <vector>

#include "synthesis_exemplars.h"
#include "texsynth/core/math.h"
#include "texsynth/gradient/gradient_solid.h"

namespace texsynth::gradient_synthesis {

// What one sweep (one iteration of one level) works with.
struct LevelContext {
  std::vector<const GradientExemplars::Impl*> sets;
  std::vector<int> clusterOffset;  // per set: its first cluster in the joint numbering
  int clusterCount = 0;            // over all sets
  const GradientSynthesisOptions* options = nullptr;
  int level = 0;     // index into every set's levels
  int spacing = 1;   // h: sample spacing, in voxels and exemplar pixels
  int size = 9;      // N
  int features = 3;  // channels of the feature vector
  int iteration = 0;
  bool quantized = false;  // two passes, averaging only each voxel's two dominant clusters
  bool rotated = false;    // a field turns the slices

  int radius() const { return size / 2; }
  // How far (voxels) a sample may lie from its check point along any axis.
  float reach() const { return float(spacing) * float(radius()) * (rotated ? 1.41421356f : 1.0f); }
};

// A check point and what it matched: per slice plane (X, Y, Z) the exemplar pixel at the patch centre,
// -1 where the plane is not matched.
struct CheckPoint {
  Vec3f position = Vec3f::Zero();   // voxel units
  Mat3f frame = Mat3f::Identity();  // columns: the local axes in the solid
  int set = 0;
  std::int32_t pixel[3] = {-1, -1, -1};
};

// The in-plane axes (u, v) of slice plane p in local coordinates: X (y, z), Y (z, x), Z (x, y).
inline void planeAxes(int plane, int& u, int& v) {
  u = (plane + 1) % 3;
  v = (plane + 2) % 3;
}

// Buckets sit at voxel positions h * b: nb = (voxels - 1) / h + 1 per axis. Bucket b belongs to the
// control point nearest to h * b (eq. 2's samples of that control).
struct BucketGrid {
  Vec3i buckets = Vec3i::Zero();
  Vec3i controls = Vec3i::Zero();
  int spacing = 1;         // h
  int controlSpacing = 4;  // d

  BucketGrid(const GradientSolid& solid, int h) : controls(solid.controls), spacing(h), controlSpacing(solid.spacing) {
    for (int a = 0; a < 3; ++a) buckets[a] = (solid.voxels[a] - 1) / h + 1;
  }
  std::int64_t layerSize() const { return std::int64_t(buckets.x()) * buckets.y(); }
  // Buckets [begin, end) along `axis` owned by control i.
  int ownedBegin(int axis, int i) const {
    if (i == 0) return 0;
    const int first = i * controlSpacing - controlSpacing / 2;  // voxel
    return std::min((first + spacing - 1) / spacing, buckets[axis]);
  }
  int ownedEnd(int axis, int i) const { return i == controls[axis] - 1 ? buckets[axis] : ownedBegin(axis, i + 1); }
};

}  // namespace texsynth::gradient_synthesis
