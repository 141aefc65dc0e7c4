#include "texsynth/animation/surface_flow.h"

#include <cmath>
#include <optional>

#include "flow_spec.h"
#include "surface_flow_fields.h"
#include "texsynth/animation/flow_limits.h"
#include "texsynth/core/error.h"
#include "texsynth/core/frame_pattern.h"

namespace texsynth {

using flow_detail::FlowSpec;
using flow_detail::shortNumber;

namespace {

// Strengths in vertex spacings per frame.
constexpr flow_detail::PresetKey kStrength = {"strength", -kMaxFlowSpeed, kMaxFlowSpeed};
const flow_detail::PresetKeys kPresets[] = {{"along-field", {kStrength}},
                                            {"downhill", {kStrength}},
                                            {"swirl", {kStrength, {"seed", 0, 18446744073709551615.0, true}}}};

std::vector<Vec3f> scaled(std::vector<Vec3f> velocities, float scale) {
  for (Vec3f& v : velocities) flow_detail::scaleVelocities({v.data(), 3}, scale);
  return velocities;
}

}  // namespace

std::span<const flow_detail::PresetKeys> flow_detail::surfacePresets() {
  return kPresets;
}

struct SurfaceFlow::Impl {
  std::string description;
  float scale = 1.0f;
  std::vector<Vec3f> fixed;  // a preset's or a single file's velocities, scaled
  // Per-vertex velocity files: their names and how they reach the synthesis mesh.
  FramePattern files;
  std::size_t inputVertices = 0;
  std::optional<flow_detail::VertexTransfer> transfer;

  std::vector<Vec3f> fromFile(int frame) const {
    return scaled(transfer->tangentVelocities(flow_detail::readVertexVelocities(files.path(frame), inputVertices)),
                  scale);
  }
};

SurfaceFlow::SurfaceFlow() : impl_(std::make_unique<Impl>()) {}
SurfaceFlow::~SurfaceFlow() = default;
SurfaceFlow::SurfaceFlow(SurfaceFlow&&) noexcept = default;
SurfaceFlow& SurfaceFlow::operator=(SurfaceFlow&&) noexcept = default;

SurfaceFlow SurfaceFlow::parse(const std::string& spec, const Mesh& input, const SurfaceFlowMesh& target,
                               const SurfaceFlowOptions& options) {
  TS_CHECK_MSG(target.mesh && target.mesh->normals.size() == target.mesh->vertexCount(),
               "a surface flow needs the synthesis mesh with its vertex normals");
  TS_CHECK_MSG(std::isfinite(target.spacing) && target.spacing > 0, "the vertex spacing must be positive");
  requireFlowScale(options.scale);
  const FlowSpec parsed = FlowSpec::parse(spec, kPresets);
  SurfaceFlow flow;
  Impl& impl = *flow.impl_;
  impl.scale = options.scale;
  const std::string scaleText = options.scale == 1.0f ? "" : ", scale " + shortNumber(options.scale);
  if (parsed.isFile()) {
    impl.files = FramePattern(parsed.name(), "flow");
    impl.inputVertices = input.vertexCount();
    // The file first, so that a bad one is reported before the closest-point work.
    const std::vector<Vec3f> first = flow_detail::readVertexVelocities(impl.files.path(0), impl.inputVertices);
    impl.transfer.emplace(input, *target.mesh);
    if (!impl.files.numbered()) impl.fixed = scaled(impl.transfer->tangentVelocities(first), impl.scale);
    impl.description =
        "per-vertex velocities " + parsed.name() + (impl.files.numbered() ? " (one file per frame)" : "") + scaleText;
    return flow;
  }
  const float strength = parsed.number("strength", 0.5f);
  impl.description = parsed.name() + " strength " + shortNumber(strength);
  if (parsed.name() == "swirl") {
    const std::uint64_t seed = parsed.integer("seed", 1);
    impl.fixed = flow_detail::swirlVelocities(target, strength, seed);
    impl.description += ", seed " + std::to_string(seed);
  } else if (parsed.name() == "downhill") {
    const Vec3f& up = options.up;
    if (!up.allFinite() || up.squaredNorm() == 0)
      parsed.fail("up (" + shortNumber(up.x()) + ", " + shortNumber(up.y()) + ", " + shortNumber(up.z()) +
                  ") is not a direction");
    impl.fixed = flow_detail::downhillVelocities(target, up, strength);
  } else {
    TS_CHECK_MSG(target.fieldUp.size() == target.mesh->vertexCount(), "along-field needs the field's up per vertex");
    impl.fixed = flow_detail::alongFieldVelocities(target, strength);
  }
  impl.fixed = scaled(std::move(impl.fixed), impl.scale);
  impl.description += scaleText;
  return flow;
}

void SurfaceFlow::requireFrames(int frames) const {
  if (!impl_->files.numbered()) return;
  for (int t = 0; t + 1 < frames; ++t) flow_detail::readVertexVelocities(impl_->files.path(t), impl_->inputVertices);
}

std::vector<Vec3f> SurfaceFlow::velocities(int frame) const {
  TS_CHECK_MSG(frame >= 0, "frames count from 0");
  return impl_->files.numbered() ? impl_->fromFile(frame) : impl_->fixed;
}

bool SurfaceFlow::timeVarying() const {
  return impl_->files.numbered();
}

std::string SurfaceFlow::description() const {
  return impl_->description;
}

}  // namespace texsynth
