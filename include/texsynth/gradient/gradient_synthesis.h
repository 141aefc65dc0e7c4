#pragma once
// Gradient solid synthesis from 2D exemplars (gradient-solid-textures §4): optimization directly on the
// control points, never on voxels.
//
//   init     every control point takes a random exemplar pixel, gradients zero (§4.1)
//   match    per cube N_C random check points; at each, three orthogonal N x N slices of the current solid
//            (first-order evaluation, §4.2.4; turned with the rotation field when given) are matched:
//            E_x by nearest neighbour in PCA space, E_y among the N1 exemplar patches whose crossbar agrees
//            best with E_x, E_z among the N2 agreeing best with both (§4.2.1)
//   update   the matched patches' pixels fall into per-voxel buckets; at the finest level only the two
//            clusters (of N_T) with most samples are averaged (two passes, §4.2.2); every control point
//            is refitted from its buckets by eq. 2
//   reuse    cube layers are processed in z order and buckets live only while a check point can still
//            reach them, so memory grows as n^2 N, not n^3 (bucket reuse)
//   levels   the control grid is fixed; coarser levels double the sample spacing, N = 9, 11, 21 (§4.2.3)
//   contrast after each iteration the control points take the exemplar's colour distribution (histogram
//            matching, as Kopf et al. 2007 do for solid optimization): averaging many patches otherwise
//            washes the solid out
//   refine   region separation with dilation, optional eq. 3 optimization and residual detail (§4.3,
//            §5.4), slab by slab through vectorization
//
// Several exemplar sets can share one solid, each in its own part of space (the paper's 'tree').
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/math.h"
#include "texsynth/core/progress.h"
#include "texsynth/gradient/gradient_solid.h"

namespace texsynth {

struct GradientExemplarOptions {
  std::vector<int> levelSizes = {9, 11, 21};  // N per level, coarsest first; level l samples 2^(L-1-l) apart
  int pcaDimensions = 20;                     // of the slice matching (paper: 10-20)
  int crossbarDimensions = 8;                 // of the crossbar searches
  int clusters = 12;                          // N_T
  float featureWeight = 1.0f;                 // of the mask's distance channel against the colours
  std::string cacheDirectory;                 // exemplar analyses are cached here (empty: not cached)
};

// One exemplar set analysed for synthesis: per plane (XY, YZ, ZX; one image may serve all three) and per
// level the stack image, its slice PCA and nearest-neighbour index, and its crossbar index; the colour
// clusters of the finest level. Build once, reuse for any number of solids.
class GradientExemplars {
 public:
  // `planes`: one image (all planes) or three (XY YZ ZX), same size and channel count (gray or RGB; alpha
  // is dropped). `masks`: none, one for all planes, or one per plane, nonzero on the feature.
  // ParameterError / InputError name the bad argument.
  GradientExemplars(const std::vector<Image>& planes, const std::vector<Image>& masks,
                    const GradientExemplarOptions& options = {}, Progress& progress = noProgress());
  ~GradientExemplars();
  GradientExemplars(GradientExemplars&&) noexcept;
  GradientExemplars& operator=(GradientExemplars&&) noexcept;

  int colorChannels() const;
  bool hasMask() const;
  int levels() const;
  const GradientExemplarOptions& options() const;

  struct Impl;
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

struct GradientSynthesisOptions {
  Vec3i voxels = Vec3i::Constant(128);  // the equivalent raster
  int spacing = 4;                      // d
  int iterations = 3;                   // N_O per level
  int checkPoints = 3;                  // N_C per cube
  int matchedSlices = 3;                // 3: E_x, E_y, E_z; 2: E_x and E_y only (anisotropic exemplars)
  bool crossbar = true;                 // false: independent searches per slice
  int candidatesY = 20;                 // N1
  int candidatesZ = 50;                 // N2
  bool regions = true;                  // with a mask: separate the regions sharply (§4.3)
  bool optimize = false;                // eq. 3 control-point optimization in the refinement
  int optimizeIterations = 6;
  bool detail = false;      // residual detail (§5.4)
  bool bucketReuse = true;  // false: buckets for the whole solid (same result, n^3 memory)
  std::uint64_t seed = 1;
  // The local frame at a point (voxel units; global -> local, as rotation fields store it). Empty: axes.
  std::function<Quatf(const Vec3f&)> orientation;
  // With several exemplar sets: which one covers a point (voxel units). Empty: set 0 everywhere.
  std::function<int(const Vec3f&)> exemplarSetOf;
};

struct GradientSynthesisReport {
  double initializeSeconds = 0, synthesisSeconds = 0, refineSeconds = 0, totalSeconds = 0;
  std::vector<double> levelSeconds;
  std::int64_t checkPointsMatched = 0;
  std::int64_t peakBucketBytes = 0;   // the largest bucket window held at once
  std::int64_t fullBucketBytes = 0;   // what buckets for every voxel would take
  std::int64_t boundaryControls = 0;  // control points with a second (negative-side) set
};

// Throws ParameterError naming a bad option (voxels, spacing, iterations, checkPoints, matchedSlices,
// candidates ...) or exemplar sets that do not agree (channels, masks).
GradientSolid synthesizeGradientSolid(const std::vector<const GradientExemplars*>& exemplarSets,
                                      const GradientSynthesisOptions& options = {},
                                      GradientSynthesisReport* report = nullptr, Progress& progress = noProgress());

}  // namespace texsynth
