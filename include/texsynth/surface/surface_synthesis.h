#pragma once
// Texture synthesis on mesh surfaces by discrete optimization (Han et al., "Fast example-based
// surface texture synthesis via discrete optimization", §2): the texture is grown as vertex
// colors directly on a retiled mesh, so there are no UV seams and no stretching.
//
// - The mesh side (prepareSurface): the retiled hierarchy (geometry/mesh_hierarchy.h), each level
//   smoothed below its pixel scale for the synthesis to read (kSurfaceGeometrySmoothing), a tangent
//   direction per vertex (surface/tangent_field.h: a smooth field, or the tangent projection of a
//   sketch-designed rotation field), and per level and neighborhood size the resampling W_p of
//   the active vertices' neighborhoods (surface/surface_neighborhoods.h). Computed once; flow
//   animation reuses it frame after frame.
// - The synthesis (synthesizeSurface): coarse to fine over the hierarchy, level l reading the
//   exemplar's Gaussian stack level l. At every level first the parallel k-coherence synthesis
//   of surface_parallel.h (random coherent patches at the coarsest level, upsampling, jitter,
//   correction, continuous coordinates), then the paper's E+M iterations at 17^2 and 9^2
//   (Table 2) on those continuous coordinates (surface_optimization.h: k-coherence M-step with
//   the usage term and random candidates of 2D optimize, strongest-vote E-step, votes within a
//   pixel counted together), where the largest neighborhood fits the exemplar. The refined state
//   replaces the start unless it makes the level flat, loses the exemplar's distinctive colors or
//   moves its histogram far (keepsTheTexture, surface_level_measures.h): on flat-background
//   exemplars E+M erodes the sparse features (GIMP cracked on the CGAL dino: flatness 0.85). At
//   the finest level a polish follows under the same rule (SurfaceStartOptions).
// All compare colors and, where the exemplar has distinctive colors, the feature channel of
// surfaceAnalysisOptions (Lefebvre & Hoppe 2006): the distance to them.
// The result is a continuous exemplar COORDINATE per vertex (and the nearest pixel, its SOURCE),
// so colors are looked up at the end and the same synthesis can be re-applied to other maps of
// the material. Deterministic for any thread count.
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/progress.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/field/rotation_field.h"
#include "texsynth/geometry/mesh_hierarchy.h"
#include "texsynth/geometry/mesh_topology.h"
#include "texsynth/image/texture_optimization.h"
#include "texsynth/surface/surface_level_measures.h"
#include "texsynth/surface/surface_neighborhoods.h"
#include "texsynth/surface/surface_parallel.h"
#include "texsynth/surface/surface_stencil.h"
#include "texsynth/surface/tangent_field.h"

namespace texsynth {

// One vertex spacing is one exemplar pixel, so relief below that scale (the bumps of a scanned
// model) is detail the texture cannot follow: unfolded over it, every neighbourhood is stretched
// and no exemplar patch fits. Taubin passes along the normals (mesh_smoothing.h) remove it from
// the geometry the synthesis reads, not from the output. Measured per vertex on GIMP leaves on
// the CGAL armadillo (bumpy at that scale) the coherence error was the same at every curvature,
// 1.70x 2D's; with 10 passes 1.38x. 6 CGAL meshes x 8 GIMP exemplars (bench/surface_synthesis.sh):
// all three targets on 42 / 43 / 41 pairs at seeds 3 / 1 / 2 (40 / 39 / 39 without), geometric
// mean coherence 1.219 / 1.224 / 1.229 -> 1.207 / 1.215 / 1.214x 2D's. Pulling the field less
// towards its guide as well (alignment 300) moved pairs both ways (seed 3: 40).
inline constexpr int kSurfaceGeometrySmoothing = 10;

// How the texture is oriented on the surface: a tangent direction field gives the exemplar's up
// direction (its -y) at every vertex: the tangent projection of `field` when given (the rotation
// field `texsynth field` designs from a sketch, its local x axis), else a smooth field following
// `smooth.guide` (world +Y by default: the exemplar stands upright on the model, its rows
// horizontal).
struct SurfaceOrientation {
  const RotationField* field = nullptr;
  TangentFieldOptions smooth;
  // Taubin passes (mesh_smoothing.h) over each level's mesh before its neighbourhoods are laid
  // out (PreparedSurfaceLevel::geometry); 0 lays them out on the retiled mesh itself.
  int geometrySmoothing = kSurfaceGeometrySmoothing;
};

struct PreparedSurfaceLevel {
  MeshTopology topology;
  // The level's mesh smoothed (SurfaceOrientation::geometrySmoothing): the same vertices and
  // triangles, which the tangents, neighborhoods, stencil and upsampling read; the output keeps
  // the retiled mesh's own positions (PreparedSurface::hierarchy).
  Mesh geometry;
  std::vector<Vec3f> tangents;  // unit, per vertex: the exemplar's +x direction (up x normal of geometry)
  // One per neighborhood size, in the order of the sizes prepareSurface was given; active
  // centres activeStride(N) cells apart.
  std::vector<SurfaceNeighborhoods> neighborhoods;
  // Every vertex's kStencilSize^2 flattened neighbourhood: the start's comparisons
  // (surface_parallel.h).
  SurfaceStencil stencil;
};

// The side of the start's correction stencil, in cells (L&H 2005 correct with 5 x 5).
inline constexpr int kStencilSize = 5;

struct PreparedSurface {
  MeshHierarchy hierarchy;
  std::vector<PreparedSurfaceLevel> levels;  // as hierarchy.levels, coarsest first
  std::vector<int> neighborhoodSizes;
  double seconds = 0;  // orientation and resampling (the hierarchy reports its own time)

  const Mesh& finestMesh() const { return hierarchy.levels.back().mesh; }
};

// Orients every level and precomputes W_p for each neighborhood size. Progress: one stage,
// one unit per level. Throws ParameterError("neighborhood", ...) for an even or out-of-range
// size, InputError("mesh", ...) for a level the topology rejects.
PreparedSurface prepareSurface(MeshHierarchy hierarchy, const SurfaceOrientation& orientation,
                               std::span<const int> neighborhoodSizes, Progress& progress = noProgress());

// How surface synthesis starts and whether the discrete optimization refines the start.
struct SurfaceStartOptions {
  SurfaceParallelOptions parallel;  // its seed is replaced by the synthesis options' seed
  // E+M iterations on top of the start at every level the optimization can run at.
  bool refine = true;
  // At the finest level only (where thin features live and the histogram is read): the start's
  // histogram band and whether it holds usage-paid moves (SurfaceParallelOptions), and the weight
  // of the color histogram term in the refinement's M-step (per member, times sigma;
  // optimizeSurfaceCoordinates). The band acts in the finest level's last correction pass. 0.3
  // against 0.1, with two correction passes per level and the E-step's vote clusters, 6 CGAL
  // meshes x 8 GIMP exemplars at seed 3: histogram distance geometric mean 1.15 -> 1.10, coherence
  // 12.98 -> 12.60 (brick, granite, bark and leaves gain most).
  float finestHistogramBand = 0.3f;
  bool finestHoldsUsagePaidMoves = true;
  float finestRefineHistogramWeight = 2.0f;
  // After the finest level's start and refinement: correction passes without the usage term
  // (noise at a few vertices per exemplar pixel, where it trades coherence for coverage) and with
  // the histogram band, kept under the refinement's rule. The E+M votes leave seams between the
  // copied patches that a neighbourhood-wide correction closes. One pass, 6 CGAL meshes x 8 GIMP
  // exemplars at seed 3: all three targets of bench/surface_synthesis.sh on 40 pairs (34 without),
  // histogram within 1.5x 2D's on 48 (46), geometric mean of the histogram distance 0.65 -> 0.44,
  // coherence 13.36 -> 13.08. With the usage term the same pass raises coherence (cow leaves 1.39x
  // -> 1.48x 2D's); without the band it loses the histogram (elephant bark 0.86x -> 6.6x); a
  // second pass or one at every level moves pairs across the targets both ways (39 with a pass at
  // every level: granite on the bunny and leopard on the armadillo fall out).
  int finestPolishPasses = 1;
};

// The most E+M iterations per neighborhood size and level that surface synthesis runs by default
// (the paper uses 1-3; each stops early when no match changes). 3 against 2, 6 CGAL meshes x 8
// GIMP exemplars (bench/surface_synthesis.sh pairs) at seeds 3 / 1 / 2: all three targets on 44 /
// 43 / 45 pairs (42 / 43 / 43), geometric mean coherence 12.99 / 12.92 / 12.96 -> 12.86 / 12.84 /
// 12.79, histogram 0.39 / 0.41 / 0.42 -> 0.38 / 0.38 / 0.39; mean synthesis 1.9 -> 2.3 s.
inline constexpr int kSurfaceIterations = 3;

// The weight of the exemplar's feature channel in surface synthesis (surfaceAnalysisOptions).
inline constexpr float kSurfaceFeatureWeight = 0.5f;

// The analyses synthesizeSurface reads: optimizationAnalysisOptions(options), each with the
// feature channel of Lefebvre & Hoppe 2006 at `featureWeight` (withFeatureChannel,
// image/texture_optimization.h; 0 = none). On a mesh every level reads it from the start: the
// start's and refinement's measures keep the distinctive colors (surface_level_measures.h).
std::vector<AnalysisOptions> surfaceAnalysisOptions(const Image& exemplar, const TextureOptimizationOptions& options,
                                                    float featureWeight = kSurfaceFeatureWeight);

// What changed a level's coordinates after its start: the E+M optimization or the polish
// (SurfaceStartOptions::finestPolishPasses).
enum class SurfaceRefinementStep { Optimization, Polish };

// Whether a refinement of one level was kept (keepsTheTexture): the measures of the state before
// it and of its result.
struct SurfaceRefinement {
  int level = 0;
  SurfaceRefinementStep step = SurfaceRefinementStep::Optimization;
  SurfaceLevelMeasures start, refined;
  bool kept = false;
};

struct SurfaceSynthesisResult {
  // Per vertex of the finest level: its continuous exemplar coordinate (pixels, centres at
  // integers; surface_parallel.h), which the colors are looked up at.
  std::vector<Vec2f> coordinates;
  // Per vertex of the finest level: the exemplar pixel (y * exemplar width + x) nearest its coordinate.
  std::vector<std::int32_t> sources;
  // Per vertex: the exemplar's color there (RGB in [0, 1]; gray exemplars repeat their channel).
  std::vector<Vec3f> colors;
  std::vector<OptimizationIteration> history;  // one entry per M-step, as 2D optimize reports
  std::vector<SurfaceRefinement> levels;       // one per refinement, coarsest level first
  int firstLevel = 0;                          // the coarsest level E+M may refine (see below)
  double seconds = 0;                          // wall time of the synthesis
};

// Synthesizes on a prepared surface. `analyses` are optimizationAnalysisOptions(options) on one
// exemplar, whose levels must equal the hierarchy's; options.solver must be Discrete (the
// least-squares solver keeps no sources) and options.neighborhoodSizes the prepared ones. The
// start runs at every level; as in 2D, the E+M refinement skips levels whose largest
// neighborhood does not fit inside the exemplar (there a tiled copy of it is a zero-energy
// optimum), and runs only with start.refine; the polish follows at the finest level.
// Progress: one stage per level. Throws ParameterError for options or analyses that do not fit.
SurfaceSynthesisResult synthesizeSurface(std::span<const ExemplarAnalysis> analyses, const PreparedSurface& surface,
                                         const TextureOptimizationOptions& options, Progress& progress = noProgress(),
                                         const SurfaceStartOptions& start = {});

// RGB colors of exemplar pixels `sources` in `image` (any channel count; gray is repeated, a
// fourth channel dropped): the synthesized colors, or another map of the same material through
// the same sources. Throws ParameterError("sources", ...) for a source outside the image.
std::vector<Vec3f> colorsOfSources(const Image& image, std::span<const std::int32_t> sources);

}  // namespace texsynth
