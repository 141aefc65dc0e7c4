#pragma once
// How well a texture on a mesh (per-vertex colors) reproduces its exemplar, in the units of the
// image metrics (eval/metrics.h: RGB on 0..255, patchSize x patchSize patches, exact nearest
// exemplar patches, only patches fully inside the exemplar). For meshes whose vertices are
// near-uniform (retiled, as surface synthesis makes them) at spacing s = sqrt(area / vertex
// count): one vertex is one texture pixel.
//
//   coherence          each evaluated vertex's patch is resampled on the surface
//                      (resampleNeighborhoods: cell (dx, dy) at s * (dx t - dy b), b = n x t, t the
//                      given tangent), and compared with its nearest exemplar patch; the RMS over
//                      vertices of the mean squared difference per value.
//   rotationInvariant  the same with each patch's distance the least over its 8 rotations and
//                      mirrors: for textures whose orientation on the surface is not the tangents'
//                      (solid textures cut by a surface), so orientation alone does not count.
//                      Never above coherence.
//   completeness       the reverse of coherence: each exemplar patch (all fully inside the
//                      exemplar, or a hashed sample of 4096 of a larger one) is compared with its
//                      exact nearest among the evaluated vertices' resampled patches; the RMS over
//                      exemplar patches of the mean squared difference per value. High when the
//                      surface shows only part of the exemplar (or none of it). Fewer evaluated
//                      vertices leave more exemplar patches with only shifted copies of themselves
//                      to meet, so it depends on `samples` (bunny, burlap: 17.5 at 4000 samples,
//                      12.7 with all 48K vertices): compare results of equal samples and exemplar.
//   flatness           the share of evaluated vertices whose resampled patch deviates less than the
//                      exemplar's 10th-percentile patch does, minus 0.1. A patch's deviation: the RMS
//                      difference of its values from the patch's mean color, over all its values.
//                      The threshold: the (n / 10)-th smallest (from 0) deviation of the exemplar's n
//                      patches fully inside it, each resampled bilinearly at a hashed sub-pixel
//                      offset as the surface's patches are resampled between vertices (resampling
//                      blurs: with the exemplar's patches as they are, a faithful surface copy of a
//                      fine texture would read 0.2-0.6). So a faithful copy reads about 0 (within
//                      about +-0.05, either side; not clamped), a one-color surface 0.9, and an
//                      exemplar flat in a tenth of its patches has a threshold of 0 and reads -0.1
//                      whatever the surface.
//   histogram          mean over R, G, B of the Wasserstein-1 distance between the colors of all
//                      vertices and the exemplar's pixels (eval/histogram_distance.h).
#include <cstdint>
#include <span>

#include "texsynth/core/image.h"
#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"

namespace texsynth {

struct SurfaceQualityOptions {
  int patchSize = 7;  // odd side of the patches, >= 3 (eval's default)
  // Vertices evaluated (>= 0; 0 = all): the first `samples` of the evaluable vertices in an order
  // hashed from `seed`. 4000 puts the coherence within about 1% of all vertices' at a tenth of
  // the time (CGAL bunny and elephant at 48K, surface synthesis and solids: 0.1-1.1%).
  int samples = 4000;
  std::uint64_t seed = 1;
  // Leave out vertices whose patch may reach past a mesh border (their distance along mesh edges
  // to a border vertex is below 1.25 (radius sqrt(2) + 0.5) s, radius = patchSize / 2): there the
  // resampling continues the texture clamp-to-edge, which is no texture. Closed meshes lose none.
  bool skipBorders = true;
};

struct SurfaceQuality {
  double coherence = 0, rotationInvariant = 0, histogram = 0;
  double completeness = 0;  // RGB 0..255 units, as coherence
  double flatness = 0;      // share of flat patches beyond the exemplar's 0.1, in [-0.1, 0.9]
  int evaluated = 0;        // vertices whose patches were compared
  int nearBorder = 0;       // vertices left out by skipBorders (or in no triangle)
  double spacing = 0;       // s, world units per texture pixel
  double seconds = 0;       // wall time
};

// The quality of `coloredMesh`'s vertex colors (mesh.colors, RGB in [0, 1]) against `exemplar`
// (any channel count: Image::withChannels(3), times 255). `tangents`: one per vertex, the
// exemplar's +x direction on the surface. Normals are the mesh's (area-weighted ones when it has
// none). Deterministic for any thread count. Throws InputError("mesh", ...) for a mesh without
// vertex colors, with non-finite colors, that MeshTopology rejects, or with no vertex to
// evaluate; ParameterError("patchSize" / "samples" / "tangents" / "exemplar", ...) for bad options,
// tangents not one per vertex or not finite, or an exemplar smaller than a patch or not finite.
SurfaceQuality evaluateSurface(const Image& exemplar, const Mesh& coloredMesh, std::span<const Vec3f> tangents,
                               const SurfaceQualityOptions& options = {});

}  // namespace texsynth
