#pragma once
// Parallel (k-coherence) texture synthesis on a mesh hierarchy: the surface version of 2D
// `parallel` (Lefebvre & Hoppe 2005; on surfaces in the spirit of Lefebvre & Hoppe 2006), the
// start that surface synthesis refines. Every vertex keeps a CONTINUOUS exemplar coordinate
// (exemplar pixels, pixel centres at integers, wrapped into [0, width) x [0, height)). A
// neighbourhood is compared at its vertices' own flattened offsets (surface_stencil.h) against
// the exemplar looked up at the candidate coordinate plus h times those offsets, so a coherent
// copy of the exemplar costs exactly 0 however the vertices fall between exemplar pixels (with
// whole-pixel sources it pays a misregistration floor that makes flat matches cheaper than
// textured ones). Colors are the nearest pixel's at a coordinate (see NearestLookup).
//
// Per level, coarse to fine: random coherent patches at the coarsest level, then several
// correction passes; at every finer level coordinate upsampling through each vertex's parent
// triangle, jitter and correction. A correction's candidates are the coordinates the vertex's
// near neighbours propose and their k-coherence sets; a usage term (the exemplar usage map of
// texture optimization) makes over-used exemplar regions cost more, which keeps the sparse
// features of a flat-background exemplar from eroding pass after pass. Each pass runs
// `subpasses` classes of vertices in turn, each reading the state before it: the result is the
// same for any thread count.
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/math.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/geometry/mesh_hierarchy.h"
#include "texsynth/surface/surface_stencil.h"

namespace texsynth {

// Defaults measured on CGAL dino, cow, bunny, armadillo, elephant, pig x GIMP cracked, bark,
// burlap, pink_marble, leaves, leopard at 48K vertices (texsynth eval): each further pass per
// level lowers the coherence by 5-15% but erodes sparse features (cracked on the dino, 6 passes
// at the coarsest level: flatness -0.08 with one pass at the finer levels, 0.14 with two, 0.34
// with three; histogram 4.3 / 6.2 / 7.1); 2 instead of 6 at the coarsest level changes the
// measures by a few percent on these pairs and keeps a flat-background exemplar's features on
// thin parts (tests/surface/surface_parallel_test.cpp: 6 passes halve their share). Usage weight
// 4 against 0 takes the dino's cracked from flatness 0.37 to 0.14 at two passes per level.
// With the usage term, the finest level's histogram band (0.3) and the refinement's vote clusters,
// two passes per finer level no longer erode (48 pairs, seed 3: flatness <= 0.010 everywhere,
// cracked's histogram as with one pass) and lower the coherence against one pass: 12.98 -> 12.60
// geometric mean, pairs within 1.3x 2D's coherence on a retiled plane 31 -> 38 of 48.
// The finest level's histogram band and hold: the correction passes prefer the background beside
// thin dark features to the features themselves, so the start empties the histogram's tails (pink
// marble's veins, brick's mortar, bark's furrows: histogram distance 1.3-3.6 against 2D optimize's
// 0.5-1.2 on the CGAL cow and dino). An additive histogram term (weight 2-4, every level) halves
// that but costs 10-25% coherence (leopard, leaves). At the finest level only, with the histogram
// choosing only between candidates within 10% of the least energy, and with the usage term (noise
// there, at a few vertices per exemplar pixel) not allowed to move a vertex on its own (it freezes
// about half of them on bark and the cow), 8 exemplars x cow and dino: histogram within 1.5x 2D's
// on 12 of 16 pairs (7 before), coherence within 1.3x 2D's measured on a retiled plane on 12 (13
// before), flatness <= 0.05 on 16 (15). Both are needed: bark / leopard / pink marble on the cow
// read histogram 0.30 / 0.80 / 1.45 with both, 1.95 / 2.27 / 1.54 with the band alone, 0.78 /
// 1.14 / 1.46 with the hold alone, 1.29 / 1.49 / 2.11 with neither.
struct SurfaceParallelOptions {
  std::uint64_t seed = 1;
  int passes = 2;            // correction passes per finer level (L&H 2005: 2)
  int startPasses = 2;       // at the coarsest level, to join the random patches
  int subpasses = 4;         // vertex classes corrected in turn per pass (L&H: s^2 = 4)
  float jitter = 0.4f;       // r_l: displacement round(h_l r_l xi), xi in [-1, 1]^2, at every finer level
  float usageWeight = 4.0f;  // times sigma^2 (usage - 1) per stencil member; 0 = no usage term
  // Color histogram matching (image/color_histogram_cost.h): among the candidates whose energy is
  // within (1 + histogramBand) of the least, the one with the least energy plus histogramWeight *
  // sigma^2 * (share / exemplar share - 1) per member. 0 = off, as at every level but the finest
  // in surface synthesis (synthesizeSurface sets it there).
  float histogramBand = 0.0f;
  float histogramWeight = 50.0f;
  // Where the usage term is mostly noise (the finest level: a few vertices per exemplar pixel),
  // a vertex whose least energy is negative (an under-used region's reward exceeds its color
  // distance: the move would be the usage term's alone) keeps its coordinate.
  bool holdUsagePaidMoves = false;
};

// Random coherent patches: every vertex copies the exemplar around a random pixel of its
// nearest neighbourhood centre, at h times its flattened offset from that centre. Pieces of
// real exemplar structure, where random coordinates make the first corrections choose the
// exemplar's most average (flattest) neighbourhoods.
std::vector<Vec2f> patchSurfaceCoordinates(const SurfaceNeighborhoods& neighborhoods, std::uint64_t seed, int level,
                                           int spacing, int exemplarWidth, int exemplarHeight);

// The finer level's coordinates: each vertex continues the coordinate of the corner u of its
// parent triangle (fine.parentTriangle, fine.parentBarycentric) with the largest barycentric
// weight, moved by its offset from u in u's tangent frame (t = coarseTangents[u], b = n x t),
// `pixelsPerUnit` exemplar pixels per world unit (h_fine / fine spacing). Positions and normals
// are those of the geometry the levels' neighbourhoods were laid out on (the same vertices and
// triangles as coarse.mesh and fine.mesh).
std::vector<Vec2f> upsampleSurfaceCoordinates(const Mesh& coarseGeometry, std::span<const Vec3f> coarseTangents,
                                              const MeshLevel& fine, const Mesh& fineGeometry,
                                              std::span<const Vec2f> coarseCoordinates, float pixelsPerUnit,
                                              int exemplarWidth, int exemplarHeight);

// Adds round(h r xi(seed, vertex, level)), xi uniform in [-1, 1]^2, wrapping.
void jitterSurfaceCoordinates(std::vector<Vec2f>& coordinates, int level, int spacing, float strength,
                              std::uint64_t seed, int exemplarWidth, int exemplarHeight);

// One correction pass at stack `level` of `analysis` (its image and spacing h; its similarity
// sets give the k-coherence candidates): every vertex takes, among the coordinates its members
// within 1.6 cells propose (c_q - h d_q) and their k-coherence sets (keeping the proposal's
// sub-pixel part), the one whose exemplar neighbourhood best matches the colors of its stencil
// (squared distance summed over members and channels) plus the usage term. Ties keep the
// earlier candidate, the vertex's own coordinate first. Returns the mean matched distance per
// member and channel.
double correctSurfaceCoordinates(const SurfaceStencil& stencil, const ExemplarAnalysis& analysis, int level,
                                 const SurfaceParallelOptions& options, std::vector<Vec2f>& coordinates);

// Every vertex's distance to a coherent copy of the exemplar around its own coordinate: the
// mean squared difference per member and channel between its stencil's colors and the level
// looked up at its coordinate plus h times the members' offsets. 0 inside a coherent copy.
std::vector<float> stencilDistances(const SurfaceStencil& stencil, const ExemplarAnalysis& analysis, int level,
                                    std::span<const Vec2f> coordinates);
// The same against one stack level.
std::vector<float> stencilDistances(const SurfaceStencil& stencil, const ExemplarLevel& level,
                                    std::span<const Vec2f> coordinates);

// The level's image at every coordinate (the nearest pixel, wrapped): `channels` floats per vertex
// (0 = all of the image's).
std::vector<float> colorsAtCoordinates(const Image& image, std::span<const Vec2f> coordinates, int channels = 0);

// The nearest exemplar pixel (y * width + x) of every coordinate.
std::vector<std::int32_t> pixelsOfCoordinates(std::span<const Vec2f> coordinates, int exemplarWidth,
                                              int exemplarHeight);

// Every pixel's centre: the coordinates of whole-pixel sources.
std::vector<Vec2f> coordinatesOfPixels(std::span<const std::int32_t> pixels, int exemplarWidth);

}  // namespace texsynth
