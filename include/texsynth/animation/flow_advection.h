#pragma once
// Semi-Lagrangian transport for flow animation: where the content of every output sample was one
// frame earlier, and what it was there. Animation carries EXEMPLAR POSITIONS (continuous source
// coordinates, exemplar pixels) rather than colors: a slow flow accumulates its sub-pixel steps
// in them, and every frame's colors are looked up in the exemplar afresh, so advection never
// blurs the texture by resampling resampled colors.
#include <cstdint>
#include <span>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"
#include "texsynth/geometry/surface_projector.h"

namespace texsynth {

// Continuous exemplar positions, one per output sample: the nearest exemplar pixel (y * width +
// x, the discrete solver's source) and the sub-pixel offset from its centre, each coordinate in
// [-0.5, 0.5]. Kept apart so that equal motions round equally everywhere: a position stored as
// one float rounds its fraction differently at x = 3 and at x = 300, which tears a translated
// texture apart pixel by pixel where the fraction passes 0.5.
struct ExemplarPositions {
  int exemplarWidth = 0, exemplarHeight = 0;
  std::vector<std::int32_t> pixels;
  std::vector<Vec2f> offsets;

  // Positions at the given pixels exactly.
  static ExemplarPositions atPixels(std::span<const std::int32_t> pixels, int exemplarWidth, int exemplarHeight);
  // Where the solver kept a sample's pixel, its offset stays (the sub-pixel part a slow flow has
  // accumulated); where it chose another pixel, the position becomes that pixel's centre.
  void keepWhereUnchanged(std::span<const std::int32_t> after);
  // Position `from` moved by `shift` exemplar pixels: the new pixel and offset of sample `to`.
  void setMoved(std::size_t to, std::int32_t fromPixel, const Vec2f& fromOffset, const Vec2f& shift);
};

// 2D, on the toroidal output grid (velocities: width x height, 2 channels, output pixels per
// frame; pixel (x, y) at integer coordinates). Where every pixel p came from, as a displacement d
// (the point is p + d): d = -v(p - v(p) / 2), a midpoint step, so that curved flows such as a
// vortex keep their radius. Row by row.
std::vector<Vec2f> backtraceImage(const Image& velocities);

// Each pixel's exemplar position one frame later: the previous position at pixel p + round(d),
// moved by the rest d - round(d) (the output and the exemplar share their axes and scale at the
// finest level). `backtrace` from backtraceImage, `width` the frame's.
ExemplarPositions advectImagePositions(const ExemplarPositions& previous, std::span<const Vec2f> backtrace, int width);

// Mean absolute color difference per channel, in 8-bit levels (0..255), over the first
// min(channels) channels: the temporal change between a frame and its predecessor carried along
// the flow (in exemplar positions, as pure advection would show it: no resampling floor, so a
// perfectly carried frame measures 0).
double meanColorChange(const Image& a, const Image& b);

// On a mesh surface (the synthesis mesh: positions, unit normals; `tangents` the exemplar's +x
// direction per vertex, `spacing` world units per exemplar pixel): each vertex's back-traced
// point p - v (projected onto the surface), and the vertex of that triangle nearest to it.
struct SurfaceBacktrace {
  int triangle = -1;
  Vec3f barycentric = Vec3f(1, 0, 0);
  int nearestVertex = 0;
  Vec3f position = Vec3f::Zero();
};
std::vector<SurfaceBacktrace> backtraceSurface(const Mesh& mesh, const SurfaceProjector& projector,
                                               std::span<const Vec3f> velocities);

// Each vertex's exemplar position one frame later: the nearest vertex u's previous position,
// moved by the back-traced point's offset from u in u's tangent frame (as the hierarchy's
// upsampling moves a child from its parent).
ExemplarPositions advectSurfacePositions(const ExemplarPositions& previous, const Mesh& mesh,
                                         std::span<const Vec3f> tangents, float spacing,
                                         std::span<const SurfaceBacktrace> backtrace);

// Mean absolute color difference per channel in 8-bit levels, over vertices.
double meanColorChange(std::span<const Vec3f> a, std::span<const Vec3f> b);

}  // namespace texsynth
