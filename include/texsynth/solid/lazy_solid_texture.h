#pragma once
// LazySolidTexture: lazy solid synthesis (lazy_solid.h) behind the SolidTexture interface.
// evaluateSerial is const and cannot synthesize, so callers first prepare() exactly the points
// they will evaluate; evaluating a point whose voxel was never prepared throws ParameterError.
// A point maps to the finest voxel floor(placement.toExemplar(p)) (one voxel = one exemplar
// pixel); its value is that voxel's colour (nearest, no interpolation).
#include <memory>
#include <span>

#include "texsynth/solid/lazy_solid.h"
#include "texsynth/solid/solid_texture.h"

namespace texsynth {

// Sets options.domainMin / domainSize to the finest voxels of `box` (world units) under
// `placement`: the domain the coarsest level is synthesized over. ParameterError("box", ...) for
// an empty box or one too far from the placement origin.
void setLazyDomain(LazySolidOptions& options, const SolidPlacement& placement, const Box3f& box);

class LazySolidTexture : public SolidTexture {
 public:
  // Throws ParameterError("solid", ...) for a null solid, ("placement.*", ...) for a bad placement.
  LazySolidTexture(std::shared_ptr<LazySolid> solid, const SolidPlacement& placement);

  std::string name() const override { return "lazy"; }
  int channels() const override { return solid_->colorChannels(); }

  // Synthesizes (or finds cached) every voxel the points fall in. Throws ParameterError
  // ("points", ...) for non-finite points or points too far from the placement origin.
  void prepare(std::span<const Vec3f> points, Progress& progress = noProgress()) override;
  bool preparesOnDemand() const override { return true; }
  // The finest voxel of a point.
  Vec3i voxelOf(const Vec3f& point) const;

  // Colours of prepared points; ParameterError("voxel", ...) for an unprepared one.
  void evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f> normals,
                      std::span<float> values) const override;

  LazySolid& solid() { return *solid_; }
  const LazySolid& solid() const { return *solid_; }
  const SolidPlacement& placement() const { return placement_; }

 private:
  std::shared_ptr<LazySolid> solid_;
  SolidPlacement placement_;
};

}  // namespace texsynth
