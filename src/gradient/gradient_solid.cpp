#include "texsynth/gradient/gradient_solid.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/core/volume.h"
#include "texsynth/gradient/tricubic_basis.h"

namespace texsynth {
namespace {

// The cube holding `point` and the point's parameter inside it.
struct CubeLocation {
  int cube[3];
  float t[3];
};

CubeLocation locate(const GradientSolid& solid, const Vec3f& point) {
  CubeLocation at;
  const float inverse = 1.0f / float(solid.spacing);
  for (int a = 0; a < 3; ++a) {
    const float p = std::clamp(point[a], 0.0f, float(solid.voxels[a] - 1)) * inverse;
    at.cube[a] = std::min(int(p), solid.controls[a] - 2);
    at.t[a] = std::min(p - float(at.cube[a]), 1.0f);
  }
  return at;
}

// The 8 corners' control indices, in tricubic weight order (x + 2y + 4z).
void cornerIndices(const GradientSolid& solid, const CubeLocation& at, std::int64_t* corners) {
  for (int p = 0; p < 8; ++p)
    corners[p] = solid.controlIndex(at.cube[0] + (p & 1), at.cube[1] + ((p >> 1) & 1), at.cube[2] + ((p >> 2) & 1));
}

// Sum over the 8 corners of weights x their sets (`set(p)` points at corner p's 4 * channels floats).
template <typename SetOf>
void accumulate(const float* weights, int channels, SetOf set, float* out) {
  std::fill(out, out + channels, 0.0f);
  for (int p = 0; p < 8; ++p) {
    const float* s = set(p);
    for (int slot = 0; slot < 4; ++slot) {
      const float w = weights[4 * p + slot];
      const float* values = s + slot * channels;
      for (int c = 0; c < channels; ++c) out[c] += w * values[c];
    }
  }
}

// First-order approximation (§4.2.4): the nearest control point's value plus its gradients times the offset.
template <typename SetOf>
void firstOrder(const GradientSolid& solid, const Vec3f& point, int channels, SetOf setAt, float* out) {
  int nearest[3];
  float offset[3];
  for (int a = 0; a < 3; ++a) {
    const float p = std::clamp(point[a], 0.0f, float(solid.voxels[a] - 1)) / float(solid.spacing);
    nearest[a] = std::clamp(int(std::lround(p)), 0, solid.controls[a] - 1);
    offset[a] = p - float(nearest[a]);
  }
  const float* s = setAt(solid.controlIndex(nearest[0], nearest[1], nearest[2]));
  for (int c = 0; c < channels; ++c)
    out[c] = s[c] + offset[0] * s[channels + c] + offset[1] * s[2 * channels + c] + offset[2] * s[3 * channels + c];
}

// A standard normal number from a key (Box-Muller on two uniforms).
float gaussianFromKey(std::uint64_t key) {
  const float u1 = std::max(uniform01(key), 1e-7f), u2 = uniform01(mix64(key));
  return std::sqrt(-2.0f * std::log(u1)) * std::cos(6.2831853f * u2);
}

}  // namespace

GradientSolid GradientSolid::zeros(const Vec3i& voxels, int channels, int spacing) {
  if ((voxels.array() < 1).any()) throw ParameterError("voxels", "must be >= 1 on every axis");
  if (spacing < 1 || spacing > 64) throw ParameterError("spacing", "must be in [1, 64], got " + std::to_string(spacing));
  if (channels < 1 || channels > 4) throw ParameterError("channels", "must be 1 to 4, got " + std::to_string(channels));
  GradientSolid solid;
  solid.voxels = voxels;
  solid.spacing = spacing;
  solid.channels = channels;
  for (int a = 0; a < 3; ++a) solid.controls[a] = controlsFor(voxels[a], spacing);
  solid.positive.assign(std::size_t(solid.controlCount()) * solid.setSize(), 0.0f);
  return solid;
}

void GradientSolid::checkConsistent() const {
  const auto n = std::size_t(controlCount());
  TS_CHECK(spacing >= 1 && channels >= 1 && channels <= 4);
  for (int a = 0; a < 3; ++a) TS_CHECK(voxels[a] >= 1 && controls[a] == controlsFor(voxels[a], spacing));
  TS_CHECK(positive.size() == n * std::size_t(setSize()));
  TS_CHECK(detail.empty() || detail.size() == n * std::size_t(setSize()));
  if (distance.empty()) {
    TS_CHECK(negativeIndex.empty() && negative.empty());
    return;
  }
  TS_CHECK(distance.size() == 4 * n && negativeIndex.size() == n);
  const std::int64_t sets = std::int64_t(negative.size() / std::size_t(setSize()));
  TS_CHECK(negative.size() == std::size_t(sets) * std::size_t(setSize()));
  for (std::int32_t index : negativeIndex) TS_CHECK(index >= -1 && index < sets);
}

float evaluateGradientDistance(const GradientSolid& solid, const Vec3f& point) {
  if (!solid.hasRegions()) return 0.0f;
  const CubeLocation at = locate(solid, point);
  std::int64_t corners[8];
  cornerIndices(solid, at, corners);
  float weights[kTricubicWeights], d;
  tricubicWeights(at.t[0], at.t[1], at.t[2], weights);
  accumulate(weights, 1, [&](int p) { return &solid.distance[std::size_t(corners[p]) * 4]; }, &d);
  return d;
}

void evaluateGradientSolid(const GradientSolid& solid, const Vec3f& point, const GradientEvaluateOptions& options,
                           float* out) {
  const int channels = solid.channels;
  const std::size_t setSize = std::size_t(solid.setSize());
  auto positiveSet = [&](std::int64_t control) { return &solid.positive[std::size_t(control) * setSize]; };
  auto negativeSet = [&](std::int64_t control) {
    const std::int32_t index = solid.negativeIndex[std::size_t(control)];
    return index < 0 ? positiveSet(control) : &solid.negative[std::size_t(index) * setSize];
  };
  const bool regions = options.regions && solid.hasRegions();

  if (!options.exact) {
    const bool negativeSide = regions && evaluateGradientDistance(solid, point) < 0.0f;
    if (negativeSide)
      firstOrder(solid, point, channels, negativeSet, out);
    else
      firstOrder(solid, point, channels, positiveSet, out);
  } else {
    const CubeLocation at = locate(solid, point);
    std::int64_t corners[8];
    cornerIndices(solid, at, corners);
    float weights[kTricubicWeights];
    if (options.table)
      options.table->weights(at.t[0], at.t[1], at.t[2], weights);
    else
      tricubicWeights(at.t[0], at.t[1], at.t[2], weights);
    float distance = 1.0f;
    if (regions)
      accumulate(weights, 1, [&](int p) { return &solid.distance[std::size_t(corners[p]) * 4]; }, &distance);
    const float half = 0.5f * options.antialiasVoxels;
    if (!regions || distance >= half) {
      accumulate(weights, channels, [&](int p) { return positiveSet(corners[p]); }, out);
    } else if (distance <= -half) {
      accumulate(weights, channels, [&](int p) { return negativeSet(corners[p]); }, out);
    } else {  // near the boundary: blend both sides linearly across antialiasVoxels (§5.3)
      float negative[4];
      accumulate(weights, channels, [&](int p) { return positiveSet(corners[p]); }, out);
      accumulate(weights, channels, [&](int p) { return negativeSet(corners[p]); }, negative);
      const float t = 0.5f + distance / options.antialiasVoxels;
      for (int c = 0; c < channels; ++c) out[c] = t * out[c] + (1 - t) * negative[c];
    }
  }

  if (options.detail && solid.hasDetail()) {  // §5.4: Gaussian grain of the fitted sigma, fixed per voxel
    const CubeLocation at = locate(solid, point);
    std::int64_t corners[8];
    cornerIndices(solid, at, corners);
    float weights[kTricubicWeights], sigma[4];
    tricubicWeights(at.t[0], at.t[1], at.t[2], weights);
    accumulate(weights, channels, [&](int p) { return &solid.detail[std::size_t(corners[p]) * setSize]; }, sigma);
    const std::uint64_t cell = latticeId(std::lround(point.x()), std::lround(point.y()), std::lround(point.z()));
    for (int c = 0; c < channels; ++c)
      out[c] += std::max(sigma[c], 0.0f) * gaussianFromKey(hashKey(options.detailSeed, cell, std::uint64_t(c)));
  }
}

Volume rasterizeGradientSolid(const GradientSolid& solid, const GradientEvaluateOptions& options) {
  Volume volume(solid.voxels.x(), solid.voxels.y(), solid.voxels.z(), solid.channels);
  parallelFor(0, volume.nz, [&](std::int64_t z) {
    for (int y = 0; y < volume.ny; ++y)
      for (int x = 0; x < volume.nx; ++x)
        evaluateGradientSolid(solid, Vec3f(float(x), float(y), float(z)), options, volume.voxel(x, y, int(z)));
  });
  return volume;
}

double gradientSolidRms(const GradientSolid& solid, const Volume& volume, const GradientEvaluateOptions& options) {
  if (volume.nx != solid.voxels.x() || volume.ny != solid.voxels.y() || volume.nz != solid.voxels.z())
    throw ParameterError("volume", "is not the size of the solid's raster");
  if (volume.channels < solid.channels) throw ParameterError("volume", "has fewer channels than the solid");
  std::vector<double> sums(std::size_t(volume.nz), 0.0);
  parallelFor(0, volume.nz, [&](std::int64_t z) {
    float values[4];
    double sum = 0;
    for (int y = 0; y < volume.ny; ++y)
      for (int x = 0; x < volume.nx; ++x) {
        evaluateGradientSolid(solid, Vec3f(float(x), float(y), float(z)), options, values);
        const float* original = volume.voxel(x, y, int(z));
        for (int c = 0; c < solid.channels; ++c) sum += double(values[c] - original[c]) * (values[c] - original[c]);
      }
    sums[std::size_t(z)] = sum;
  });
  double total = 0;
  for (double s : sums) total += s;
  return 255.0 * std::sqrt(total / (double(volume.voxelCount()) * solid.channels));
}

}  // namespace texsynth
