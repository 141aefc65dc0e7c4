#pragma once
// SolidTexture: the one interface every solid-texture method implements (tile-deform,
// tile-blend, lazy synthesis, regions of several solids; gradient solids through
// texsynth/gradient/gradient_solid_texture.h). It answers "which values at these 3D points?"
// for a batch of points, optionally with surface normals. Everything that consumes solids
// (mesh colouring, renderer, slices, volumes) is written once against it.
//
// Units: points are in world units. Each texture maps them to exemplar pixels through a
// SolidPlacement (exemplar = (world - origin) * pixelsPerUnit). fitPlacement() gives the
// usual default: the longest side of a mesh's bounding box spans a chosen number of
// exemplar tiles.
#include <span>
#include <string>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/progress.h"

namespace texsynth {

// World units -> exemplar pixels: exemplar = (world - origin) * pixelsPerUnit.
struct SolidPlacement {
  Vec3f origin = Vec3f::Zero();
  float pixelsPerUnit = 1.0f;  // > 0, finite

  Vec3f toExemplar(const Vec3f& world) const { return (world - origin) * pixelsPerUnit; }
};

// Placement whose origin is bounds.min and under which the longest side of `bounds` spans
// `tiles` exemplar tiles of `tileSize` pixels. Throws ParameterError("bounds" | "tileSize" |
// "tiles", ...) for an empty/degenerate box, tileSize < 1 or tiles not finite and > 0.
SolidPlacement fitPlacement(const Box3f& bounds, int tileSize, float tiles = 2.0f);

// Throws ParameterError("placement.*", ...) unless origin is finite and pixelsPerUnit > 0.
void validatePlacement(const SolidPlacement& placement);

class SolidTexture {
 public:
  virtual ~SolidTexture() = default;

  // Short method name, e.g. "tile-deform-volume".
  virtual std::string name() const = 0;
  // Values per point: colour channels (3 for RGB) followed by any feature channels.
  virtual int channels() const = 0;

  // Writes channels() values per point into `values` (size points.size() * channels()).
  // `normals` is empty or holds one unit normal per point; methods that use normals fall
  // back to a documented normal-free rule when it is empty. Runs serially on the calling
  // thread; must be thread-safe (const) and depend only on each point and its normal, so
  // results never depend on batch split, order or thread count.
  virtual void evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f> normals,
                              std::span<float> values) const = 0;

  // Methods that synthesize on demand (lazy synthesis) compute here what `points` need, before
  // they are evaluated; the others need nothing and do nothing.
  virtual void prepare(std::span<const Vec3f> points, Progress& progress = noProgress()) {
    (void)points, (void)progress;
  }
  // True if evaluate() needs prepare() first.
  virtual bool preparesOnDemand() const { return false; }

  // evaluateSerial in parallel over fixed chunks of points. Throws ParameterError
  // ("normals" | "values") when the span sizes do not match.
  void evaluate(std::span<const Vec3f> points, std::span<const Vec3f> normals, std::span<float> values) const;

  // RGB colours (the first three channels; a single channel is repeated as gray).
  std::vector<Vec3f> evaluateColors(std::span<const Vec3f> points, std::span<const Vec3f> normals = {}) const;
};

}  // namespace texsynth
