#pragma once
// One place that turns options into a SolidTexture, shared by `texsynth solid`, the demo and the
// studio server: tile-deform (a 2D exemplar stacked, or a 3D exemplar tiled), tile-blend, or lazy
// synthesis following an optional rotation field, with an optional inner exemplar below a mesh's
// surface (lazy). The factory fits the placement to the box, applies the methods' size-dependent
// defaults, and synthesizes a lazy solid's coarsest level over the box (from the disk cache when
// there is one), so every later request reuses it.
//
// Threads: a built texture evaluates from any number of threads; prepare() of a lazy solid must
// not run on two threads at once (callers serialize it, as the studio does with one lock per
// solid). gradient solids have their own library call (gradient_synthesis.h).
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"
#include "texsynth/core/progress.h"
#include "texsynth/core/volume.h"
#include "texsynth/field/rotation_field.h"
#include "texsynth/solid/lazy_solid.h"
#include "texsynth/solid/solid_texture.h"
#include "texsynth/solid/tile_blend_solid.h"
#include "texsynth/solid/tile_deform_solid.h"

namespace texsynth {

enum class SolidMethod { TileDeform, TileBlend, Lazy };

// "tile-deform" | "tile-blend" | "lazy"; ParameterError("method", ...) otherwise.
SolidMethod parseSolidMethod(const std::string& name);
const char* solidMethodName(SolidMethod method);

struct SolidRecipe {
  SolidMethod method = SolidMethod::TileDeform;
  // One 2D exemplar, or three (XY YZ ZX) for lazy; tile-deform takes a 3D `volume` instead.
  std::vector<Image> exemplars;
  std::optional<Volume> volume;
  // The region the solid serves (a mesh's bounds): its longest side spans `tiles` exemplars.
  Box3f box;
  float tiles = 2.0f;
  std::uint64_t seed = 1;

  // Method options; the factory sets their placement and seed. tile-deform: a cell size of 0 on an
  // axis is a quarter of the exemplar.
  TileDeformSolidOptions tileDeform = [] {
    TileDeformSolidOptions options;
    options.deformation.cellSize.setZero();
    return options;
  }();
  TileBlendSolidOptions tileBlend;
  // lazy: levels <= 0 picks lazyLevelsFor the first exemplar; the domain and orientation key are set here.
  LazySolidOptions lazy;
  // lazy: the rotation field the texture follows (null: none).
  std::shared_ptr<const RotationField> field;
  // lazy with a mesh: everything deeper than shellDepth (world units) below `mesh`'s surface
  // comes from `inner`, an independent synthesis.
  std::optional<Image> inner;
  const Mesh* mesh = nullptr;  // only read during buildSolid
  float shellDepth = 0;
};

struct SolidBuild {
  std::unique_ptr<SolidTexture> texture;
  SolidPlacement placement;
  std::string variant;  // what was built, in words (e.g. "lazy, guided by a field")
  // Lazy parts by region name ("shell", "core"), for statistics.
  std::vector<std::pair<std::string, std::shared_ptr<LazySolid>>> lazyParts;
  double coarsestSeconds = 0;  // lazy: the coarsest level over the box, all parts
};

// Throws ParameterError for inconsistent recipes (no exemplar, two exemplars, three for a method
// that takes one, a volume for a 2D method, inner without a mesh) and whatever the methods throw.
SolidBuild buildSolid(const SolidRecipe& recipe, Progress& progress = noProgress());

// Runs `consume(const SolidTexture&)` on `solid`; a solid that synthesizes on demand first
// prepares exactly the points the consumer will ask for (recorded by a dry run that answers zeros).
template <typename Consume>
auto withPrepared(SolidTexture& solid, Progress& progress, Consume consume);

// The dry run's recorder, used by withPrepared.
class PointRecorder : public SolidTexture {
 public:
  explicit PointRecorder(int channels) : channels_(channels) {}
  std::string name() const override { return "point-recorder"; }
  int channels() const override { return channels_; }
  void evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f>, std::span<float> values) const override;
  std::vector<Vec3f> take();

 private:
  int channels_;
  mutable std::mutex mutex_;
  mutable std::vector<Vec3f> points_;
};

template <typename Consume>
auto withPrepared(SolidTexture& solid, Progress& progress, Consume consume) {
  if (solid.preparesOnDemand()) {
    PointRecorder recorder(solid.channels());
    consume(static_cast<const SolidTexture&>(recorder));
    solid.prepare(recorder.take(), progress);
  }
  return consume(static_cast<const SolidTexture&>(solid));
}

}  // namespace texsynth
