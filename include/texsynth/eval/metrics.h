#pragma once
// Quality metrics for texture synthesis: how well an output image (or the slices of a solid
// texture) reproduces its exemplar. All metrics work on RGB values scaled to 0..255, on
// patchSize×patchSize neighbourhoods, with exact nearest neighbours.
//
//   coherence     RMS over output patches of the mean squared difference per value to the
//                 nearest exemplar patch (low: the output invents nothing).
//   coherence tail the 90th percentile over output patches of that difference's root mean
//                 square: where seams live (a few straight cuts hardly move the mean).
//   completeness  the same from exemplar patches to output patches (low: nothing is missing).
//   histogram     mean over R, G, B of the 1D Wasserstein-1 distance of the value distributions.
//   periodicity   share of sampled output patches that repeat at the single most common offset
//                 (tiling scores high, good synthesis near 0); see periodicity.h.
//   lattice       the largest normalized autocorrelation of the output's luminance detail
//                 outside its central lobe (0..1: a shifted repeat of the same content, as in a
//                 tiling or a grid of copies, scores high; noise and good synthesis near 0); see
//                 lattice.h.
//   sharpness     mean gradient magnitude of the output over the exemplar's (1 = as crisp,
//                 below 1 blurrier); see sharpness.h.
//
// Patches are taken only where they lie fully inside an image, for outputs and exemplars alike:
// the exemplar is not assumed tileable, so no wrapped patch can invent a seam that is absent
// from the real exemplar, and an output is never compared across its own (unrelated) borders.
#include <cstdint>

#include "texsynth/core/image.h"
#include "texsynth/core/progress.h"
#include "texsynth/core/volume.h"

namespace texsynth {

struct MetricOptions {
  int patchSize = 7;                // odd side of the square neighbourhoods (>= 1)
  int periodicitySamples = 2000;    // output patches sampled for periodicity (>= 1)
  double duplicateThreshold = 4.0;  // mean squared difference per value (0..255 units) under
                                    // which two patches count as duplicates (>= 0)
  std::uint64_t seed = 1;           // picks the periodicity sample
  int slicesPerAxis = 4;            // volumes: slices evaluated per axis (>= 1)
};

struct QualityMetrics {
  double coherence = 0, completeness = 0, histogram = 0, periodicity = 0, lattice = 0, sharpness = 0;
  double coherenceTail = 0;  // the 90th percentile of per-patch coherence
  double seconds = 0;        // wall time spent computing these metrics
};

// Metrics of `output` against `exemplar`. Any channel count is converted to RGB first
// (Image::withChannels(3)); values are multiplied by 255 (not clipped, so HDR stays HDR).
// Throws ParameterError for bad options or an image smaller than the patch size (naming
// "exemplar" or "output"). The result does not depend on the thread count.
QualityMetrics evaluateImage(const Image& exemplar, const Image& output, const MetricOptions& options = {});

struct VolumeQuality {
  QualityMetrics axis[3];  // slices normal to x, y, z
  QualityMetrics mean;     // arithmetic mean of the three axes; `seconds` is the total time
};

// Metrics of a solid texture, on `slicesPerAxis` slices normal to each axis. Slice i of n along
// an axis of extent N is at index floor((i + 0.5) * N / n), i.e. evenly spread, away from the
// borders. Slice image axes (u right, v down): normal x -> (y, z); normal y -> (x, z);
// normal z -> (x, y); so a volume made by stacking the exemplar along z has z-slices equal to
// the exemplar. Per axis, coherence and completeness are the RMS over all patches of all its
// slices (each slice has as many patches), coherence tail, histogram, periodicity, lattice and
// sharpness the mean over its slices.
// Before any work, throws ParameterError for bad options, slicesPerAxis above an extent
// ("slicesPerAxis"), a patch larger than the smallest slice ("patchSize", naming the slices'
// size), a non-finite voxel ("volume") or an exemplar smaller than the patch ("exemplar").
// `progress` gets a stage for indexing the exemplar and one unit per evaluated slice.
VolumeQuality evaluateVolume(const Image& exemplar, const Volume& volume, const MetricOptions& options = {},
                             Progress& progress = noProgress());

}  // namespace texsynth
