#pragma once
// Different solid textures in different regions of space, chosen per point by a rule: the
// sketch-guided solid paper's tree has bark near the surface and wood inside. Each part only
// prepares and evaluates the points that fall in its region, so a lazy part synthesizes nothing
// elsewhere.
#include <functional>
#include <memory>
#include <vector>

#include "texsynth/core/mesh.h"
#include "texsynth/solid/solid_texture.h"

namespace texsynth {

class RegionSolidTexture : public SolidTexture {
 public:
  // Index into the parts of the region a point is in.
  using RegionRule = std::function<int(const Vec3f&)>;

  // Throws ParameterError("parts", ...) for no parts, a null part or parts with different
  // channel counts, ("rule", ...) for an empty rule.
  RegionSolidTexture(std::vector<std::shared_ptr<SolidTexture>> parts, RegionRule rule);

  std::string name() const override { return "regions"; }
  int channels() const override { return parts_.front()->channels(); }
  void prepare(std::span<const Vec3f> points, Progress& progress = noProgress()) override;
  bool preparesOnDemand() const override;
  // A rule result outside the parts is an InternalError.
  void evaluateSerial(std::span<const Vec3f> points, std::span<const Vec3f> normals,
                      std::span<float> values) const override;

 private:
  int regionOf(const Vec3f& point) const;

  std::vector<std::shared_ptr<SolidTexture>> parts_;
  RegionRule rule_;
};

// Region 0 within `depth` (world units, > 0) of the mesh's surface or outside it, region 1
// deeper inside: a shell and a core (inside by ray parity: the mesh should be closed). Throws ParameterError("depth",
// ...) unless depth is finite and > 0, InputError
// ("mesh", ...) for a mesh without triangles.
RegionSolidTexture::RegionRule surfaceShellRule(const Mesh& mesh, float depth);

}  // namespace texsynth
