// Slab-by-slab final refinement of synthesized gradient solids (see synthesis_refine.h).
#include "synthesis_refine.h"

#include <algorithm>

#include "synthesis_matching.h"
#include "texsynth/core/error.h"
#include "texsynth/core/volume.h"

namespace texsynth::gradient_synthesis {
namespace {

constexpr int kCoreControls = 16;   // control points per tile side (x, y) kept
constexpr int kSlabControls = 4;    // control layers per slab (z) kept: the slab buffer is what grows with n^2
constexpr int kMarginControls = 2;  // fitted around each core and dropped: covers the dilation and eq. 3's reach

}  // namespace

SlabRefiner::SlabRefiner(const GradientSolid& state, int colorChannels, bool regions, const VectorizeOptions& options)
    : state_(state), colors_(colorChannels), regions_(regions), options_(options) {
  out_ = GradientSolid::zeros(state.voxels, colorChannels, state.spacing);
  if (regions_) {
    out_.distance.assign(std::size_t(out_.controlCount()) * 4, 0.0f);
    out_.negativeIndex.assign(std::size_t(out_.controlCount()), -1);
  }
  if (options_.detail) out_.detail.assign(out_.positive.size(), 0.0f);
  options_.quantize = false;  // tiles are quantized together when the solid is written
}

void SlabRefiner::take(const ClosedLayer& layer) {
  const int width = state_.voxels.x(), height = state_.voxels.y(), f = state_.channels;
  const int stride = colors_ + (regions_ ? 1 : 0);
  TS_CHECK_MSG(layer.z == bufferBegin_ + int(buffer_.size() / (std::size_t(width) * height * stride)),
               "refinement layers out of order");
  const std::size_t base = buffer_.size();
  buffer_.resize(base + std::size_t(width) * height * stride);
  std::vector<float> value(static_cast<std::size_t>(f));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t voxel = std::size_t(y) * width + x;
      const float* source = &layer.averages[voxel * f];
      if (!layer.filled[voxel]) {  // no sample: the current solid's value
        sampleFirstOrder(state_, Vec3f(float(x), float(y), float(layer.z)), value.data());
        source = value.data();
      }
      float* target = &buffer_[base + voxel * stride];
      std::copy_n(source, colors_, target);
      if (regions_) target[colors_] = source[colors_] < 0.0f ? 1.0f : 0.0f;  // the feature side
    }
  peakBytes_ = std::max(peakBytes_, std::int64_t(buffer_.capacity() * sizeof(float)));
  // Every slab whose voxels are all here (the last layer completes every remaining one).
  const int d = state_.spacing;
  while (nextCore_ < state_.controls.z()) {
    const int coreEnd = std::min(state_.controls.z(), nextCore_ + kSlabControls);
    if (layer.z < std::min(state_.voxels.z() - 1, d * (coreEnd - 1 + kMarginControls))) break;
    refineSlab();
  }
}

void SlabRefiner::refineSlab() {
  const int coreEnd = std::min(state_.controls.z(), nextCore_ + kSlabControls);
  for (int ty = 0; ty < state_.controls.y(); ty += kCoreControls)
    for (int tx = 0; tx < state_.controls.x(); tx += kCoreControls)
      refineTile({tx, ty, nextCore_}, {std::min(state_.controls.x(), tx + kCoreControls),
                                       std::min(state_.controls.y(), ty + kCoreControls), coreEnd});
  nextCore_ = coreEnd;
  // Keep the voxels the next slab's margin needs.
  const int keepFrom = std::max(0, state_.spacing * (nextCore_ - kMarginControls));
  const std::size_t layerFloats =
      std::size_t(state_.voxels.x()) * state_.voxels.y() * std::size_t(colors_ + (regions_ ? 1 : 0));
  if (keepFrom > bufferBegin_) {
    buffer_.erase(buffer_.begin(),
                  buffer_.begin() + std::ptrdiff_t(std::size_t(keepFrom - bufferBegin_) * layerFloats));
    bufferBegin_ = keepFrom;
  }
}

void SlabRefiner::refineTile(const Vec3i& coreBegin, const Vec3i& coreEnd) {
  const int d = state_.spacing, stride = colors_ + (regions_ ? 1 : 0);
  Vec3i first, size, controlOffset;
  for (int a = 0; a < 3; ++a) {
    controlOffset[a] = std::max(0, coreBegin[a] - kMarginControls);
    first[a] = d * controlOffset[a];
    const int last = std::min(state_.voxels[a] - 1, d * (coreEnd[a] - 1 + kMarginControls));
    size[a] = last - first[a] + 1;
  }
  Volume colors(size.x(), size.y(), size.z(), colors_), mask;
  if (regions_) mask = Volume(size.x(), size.y(), size.z(), 1);
  bool inside = false, outside = false;
  const std::size_t width = std::size_t(state_.voxels.x()), height = std::size_t(state_.voxels.y());
  for (int z = 0; z < size.z(); ++z)
    for (int y = 0; y < size.y(); ++y)
      for (int x = 0; x < size.x(); ++x) {
        const float* source =
            &buffer_[((std::size_t(first.z() + z - bufferBegin_) * height + std::size_t(first.y() + y)) * width +
                      std::size_t(first.x() + x)) *
                     stride];
        std::copy_n(source, colors_, colors.voxel(x, y, z));
        if (regions_) {
          mask.at(x, y, z, 0) = source[colors_];
          (source[colors_] > 0.5f ? inside : outside) = true;
        }
      }
  // One side only: nothing to separate here.
  const bool separate = regions_ && inside && outside;
  const GradientSolid tile = vectorizeVolume(colors, separate ? mask : Volume(), options_);
  const float sideDistance = inside ? 1.0f : -1.0f;  // a tile on one side keeps that side's sign
  for (int k = coreBegin.z(); k < coreEnd.z(); ++k)
    for (int j = coreBegin.y(); j < coreEnd.y(); ++j)
      for (int i = coreBegin.x(); i < coreEnd.x(); ++i) {
        const std::int64_t local =
            tile.controlIndex(i - controlOffset.x(), j - controlOffset.y(), k - controlOffset.z());
        const std::int64_t global = out_.controlIndex(i, j, k);
        const std::size_t setSize = std::size_t(out_.setSize());
        std::copy_n(&tile.positive[std::size_t(local) * setSize], setSize,
                    &out_.positive[std::size_t(global) * setSize]);
        if (options_.detail)
          std::copy_n(&tile.detail[std::size_t(local) * setSize], setSize, &out_.detail[std::size_t(global) * setSize]);
        if (!regions_) continue;
        float* distance = &out_.distance[std::size_t(global) * 4];
        if (!separate) {
          distance[0] = sideDistance * 3.0f * float(d), distance[1] = distance[2] = distance[3] = 0.0f;
          continue;
        }
        std::copy_n(&tile.distance[std::size_t(local) * 4], 4, distance);
        const std::int32_t negative = tile.negativeIndex[std::size_t(local)];
        if (negative < 0) continue;
        out_.negativeIndex[std::size_t(global)] = std::int32_t(out_.negative.size() / setSize);
        out_.negative.insert(out_.negative.end(),
                             tile.negative.begin() + std::ptrdiff_t(std::size_t(negative) * setSize),
                             tile.negative.begin() + std::ptrdiff_t(std::size_t(negative + 1) * setSize));
      }
}

GradientSolid SlabRefiner::finish() {
  TS_CHECK_MSG(nextCore_ == state_.controls.z(), "refinement finished before the last slab");
  if (regions_ && out_.negative.empty()) {  // one region everywhere after all
    out_.distance.clear();
    out_.negativeIndex.clear();
  }
  out_.checkConsistent();
  return std::move(out_);
}

}  // namespace texsynth::gradient_synthesis
