#include "texsynth/gradient/gradient_solid.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/core/volume.h"
#include "texsynth/gradient/tricubic_basis.h"

namespace texsynth {
namespace {

using Hermite = std::array<float, 4>;

// The cube holding `point` and the point's parameter inside it.
struct CubeLocation {
  int cube[3];
  float t[3];
};

__attribute__((always_inline)) inline CubeLocation locate(const GradientSolid& solid, const Vec3f& point) {
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
  const std::int64_t base = solid.controlIndex(at.cube[0], at.cube[1], at.cube[2]);
  const std::int64_t dy = solid.controls.x(), dz = std::int64_t(solid.controls.x()) * solid.controls.y();
  for (int p = 0; p < 8; ++p) corners[p] = base + (p & 1) + ((p >> 1) & 1) * dy + ((p >> 2) & 1) * dz;
}

// The tricubic sum over the 8 corners' sets, axis by axis: the x sums first, then y, then z (48
// multiply-adds per channel instead of 96 plus the 64 products of the 32 weights). h* are the axes'
// Hermite functions. Channels is the channel count when fixed at compile time, else 0.
template <int Channels>
void separableSum(const Hermite& hu, const Hermite& hv, const Hermite& hw, int channels, const float* const* sets,
                  float* out) {
  const int n = Channels ? Channels : channels;
  for (int c = 0; c < n; ++c) {
    float values[2], slopesW[2];  // per z: the x-y sums of values and of d/dw
    for (int z = 0; z < 2; ++z) {
      float a[2], b[2], w[2];  // per y: x sums of values (with d/du), of d/dv, of d/dw
      for (int y = 0; y < 2; ++y) {
        const float *s0 = sets[2 * y + 4 * z], *s1 = sets[1 + 2 * y + 4 * z];
        a[y] = hu[0] * s0[c] + hu[1] * s1[c] + hu[2] * s0[n + c] + hu[3] * s1[n + c];
        b[y] = hu[0] * s0[2 * n + c] + hu[1] * s1[2 * n + c];
        w[y] = hu[0] * s0[3 * n + c] + hu[1] * s1[3 * n + c];
      }
      values[z] = hv[0] * a[0] + hv[1] * a[1] + hv[2] * b[0] + hv[3] * b[1];
      slopesW[z] = hv[0] * w[0] + hv[1] * w[1];
    }
    out[c] = hw[0] * values[0] + hw[1] * values[1] + hw[2] * slopesW[0] + hw[3] * slopesW[1];
  }
}

// The same for RGB with the three channels side by side in 4-float vectors: each slot's 3 values are one
// unaligned load from its set (the vectors' last lane is never used), so the sum is 48 vector
// multiply-adds.
using Float4 = float __attribute__((vector_size(16)));

inline Float4 loadSlot(const float* set, int slot) {
  Float4 v = {0, 0, 0, 0};
  std::memcpy(&v, set + 3 * slot, slot < 3 ? 16 : 12);  // slot 3 ends the set: 3 floats only
  return v;
}

__attribute__((always_inline)) inline void separableSumRgb(const Hermite& hu, const Hermite& hv, const Hermite& hw,
                                                           const float* const* sets, float* out) {
  Float4 values[2], slopesW[2];
  for (int z = 0; z < 2; ++z) {
    Float4 a[2], b[2], w[2];
    for (int y = 0; y < 2; ++y) {
      const float *s0 = sets[2 * y + 4 * z], *s1 = sets[1 + 2 * y + 4 * z];
      a[y] = hu[0] * loadSlot(s0, 0) + hu[1] * loadSlot(s1, 0) + hu[2] * loadSlot(s0, 1) + hu[3] * loadSlot(s1, 1);
      b[y] = hu[0] * loadSlot(s0, 2) + hu[1] * loadSlot(s1, 2);
      w[y] = hu[0] * loadSlot(s0, 3) + hu[1] * loadSlot(s1, 3);
    }
    values[z] = hv[0] * a[0] + hv[1] * a[1] + hv[2] * b[0] + hv[3] * b[1];
    slopesW[z] = hv[0] * w[0] + hv[1] * w[1];
  }
  const Float4 sum = hw[0] * values[0] + hw[1] * values[1] + hw[2] * slopesW[0] + hw[3] * slopesW[1];
  out[0] = sum[0], out[1] = sum[1], out[2] = sum[2];
}

void accumulate(const Hermite* axes, int channels, const float* const* sets, float* out) {
  if (channels == 3)
    separableSumRgb(axes[0], axes[1], axes[2], sets, out);
  else if (channels == 1)
    separableSum<1>(axes[0], axes[1], axes[2], 1, sets, out);
  else
    separableSum<0>(axes[0], axes[1], axes[2], channels, sets, out);
}

// The three axes' Hermite functions at a cube location, exact or from the weight table.
void axisFunctions(const CubeLocation& at, const TricubicWeightTable* table, Hermite* axes) {
  for (int a = 0; a < 3; ++a) axes[a] = table ? table->axisFunctions(at.t[a]) : hermiteBasis(at.t[a]);
}

// The 8 corners' sets in `array` (stride floats per control point).
void cornerSets(const std::vector<float>& array, std::size_t stride, const std::int64_t* corners, const float** sets) {
  for (int p = 0; p < 8; ++p) sets[p] = &array[std::size_t(corners[p]) * stride];
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
  if (spacing < 1 || spacing > 64)
    throw ParameterError("spacing", "must be in [1, 64], got " + std::to_string(spacing));
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
  Hermite axes[3];
  axisFunctions(at, nullptr, axes);
  const float* sets[8];
  cornerSets(solid.distance, 4, corners, sets);
  float d;
  accumulate(axes, 1, sets, &d);
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
    Hermite weights[3];
    axisFunctions(at, options.table, weights);
    float distance = 1.0f;
    const float* sets[8];
    if (regions) {
      cornerSets(solid.distance, 4, corners, sets);
      accumulate(weights, 1, sets, &distance);
    }
    const float half = 0.5f * options.antialiasVoxels;
    auto side = [&](bool positive, float* values) {
      for (int p = 0; p < 8; ++p) sets[p] = positive ? positiveSet(corners[p]) : negativeSet(corners[p]);
      accumulate(weights, channels, sets, values);
    };
    if (!regions || distance >= half) {
      side(true, out);
    } else if (distance <= -half) {
      side(false, out);
    } else {  // near the boundary: blend both sides linearly across antialiasVoxels (§5.3)
      float negative[4];
      side(true, out);
      side(false, negative);
      const float t = 0.5f + distance / options.antialiasVoxels;
      for (int c = 0; c < channels; ++c) out[c] = t * out[c] + (1 - t) * negative[c];
    }
  }

  if (options.detail && solid.hasDetail()) {  // §5.4: Gaussian grain of the fitted sigma, fixed per voxel
    const CubeLocation at = locate(solid, point);
    std::int64_t corners[8];
    cornerIndices(solid, at, corners);
    Hermite weights[3];
    axisFunctions(at, nullptr, weights);
    float sigma[4];
    const float* sets[8];
    cornerSets(solid.detail, setSize, corners, sets);
    accumulate(weights, channels, sets, sigma);
    const std::uint64_t cell = latticeId(std::lround(point.x()), std::lround(point.y()), std::lround(point.z()));
    // One draw for all channels: texture grain is mostly light and dark, and independent draws per
    // channel would show as coloured speckle.
    const float grain = gaussianFromKey(hashKey(options.detailSeed, cell));
    for (int c = 0; c < channels; ++c) out[c] += std::max(sigma[c], 0.0f) * grain;
  }
}

namespace {

// Batches of points in one region: consecutive points in the same cube (slices, volumes, render spans)
// reuse its corners.
template <int Channels>
__attribute__((always_inline)) inline void evaluateOneRegion(const GradientSolid& solid, const Vec3f* points,
                                                             std::size_t count, const TricubicWeightTable* table,
                                                             float* out) {
  const std::size_t stride = std::size_t(solid.setSize());
  const int channels = Channels ? Channels : solid.channels;
  std::int64_t cube = -1;
  const float* sets[8];
  for (std::size_t n = 0; n < count; ++n) {
    const CubeLocation at = locate(solid, points[n]);
    const std::int64_t here = solid.controlIndex(at.cube[0], at.cube[1], at.cube[2]);
    if (here != cube) {
      std::int64_t corners[8];
      cornerIndices(solid, at, corners);
      cornerSets(solid.positive, stride, corners, sets);
      cube = here;
    }
    Hermite axes[3];
    axisFunctions(at, table, axes);
    if constexpr (Channels == 3)
      separableSumRgb(axes[0], axes[1], axes[2], sets, out + n * 3);
    else
      separableSum<Channels>(axes[0], axes[1], axes[2], channels, sets, out + n * std::size_t(channels));
  }
}

// GCC also builds these for AVX2 and picks at load time where the CPU has it; the module is compiled
// without FMA contraction (src/CMakeLists.txt), so both give the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define TEXSYNTH_AVX2_CLONE __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define TEXSYNTH_AVX2_CLONE
#endif

TEXSYNTH_AVX2_CLONE void evaluateRgb(const GradientSolid& solid, const Vec3f* points, std::size_t count,
                                     const TricubicWeightTable* table, float* out) {
  evaluateOneRegion<3>(solid, points, count, table, out);
}

TEXSYNTH_AVX2_CLONE void evaluateAnyChannels(const GradientSolid& solid, const Vec3f* points, std::size_t count,
                                             const TricubicWeightTable* table, float* out) {
  evaluateOneRegion<0>(solid, points, count, table, out);
}

}  // namespace

void evaluateGradientSolid(const GradientSolid& solid, std::span<const Vec3f> points,
                           const GradientEvaluateOptions& options, float* out) {
  const bool plain =
      options.exact && !(options.regions && solid.hasRegions()) && !(options.detail && solid.hasDetail());
  if (!plain) {
    for (std::size_t n = 0; n < points.size(); ++n)
      evaluateGradientSolid(solid, points[n], options, out + n * std::size_t(solid.channels));
  } else if (solid.channels == 3) {
    evaluateRgb(solid, points.data(), points.size(), options.table, out);
  } else {
    evaluateAnyChannels(solid, points.data(), points.size(), options.table, out);
  }
}

Volume rasterizeGradientSolid(const GradientSolid& solid, const GradientEvaluateOptions& options) {
  Volume volume(solid.voxels.x(), solid.voxels.y(), solid.voxels.z(), solid.channels);
  parallelFor(0, volume.nz, [&](std::int64_t z) {
    std::vector<Vec3f> row(std::size_t(volume.nx));
    for (int y = 0; y < volume.ny; ++y) {
      for (int x = 0; x < volume.nx; ++x) row[std::size_t(x)] = Vec3f(float(x), float(y), float(z));
      evaluateGradientSolid(solid, row, options, volume.voxel(0, y, int(z)));
    }
  });
  return volume;
}

double gradientSolidRms(const GradientSolid& solid, const Volume& volume, const GradientEvaluateOptions& options) {
  if (volume.nx != solid.voxels.x() || volume.ny != solid.voxels.y() || volume.nz != solid.voxels.z())
    throw ParameterError("volume", "is not the size of the solid's raster");
  if (volume.channels < solid.channels) throw ParameterError("volume", "has fewer channels than the solid");
  std::vector<double> sums(std::size_t(volume.nz), 0.0);
  parallelFor(0, volume.nz, [&](std::int64_t z) {
    std::vector<Vec3f> row(std::size_t(volume.nx));
    std::vector<float> values(row.size() * std::size_t(solid.channels));
    double sum = 0;
    for (int y = 0; y < volume.ny; ++y) {
      for (int x = 0; x < volume.nx; ++x) row[std::size_t(x)] = Vec3f(float(x), float(y), float(z));
      evaluateGradientSolid(solid, row, options, values.data());
      for (int x = 0; x < volume.nx; ++x) {
        const float* original = volume.voxel(x, y, int(z));
        for (int c = 0; c < solid.channels; ++c) {
          const double d = values[std::size_t(x) * solid.channels + std::size_t(c)] - original[c];
          sum += d * d;
        }
      }
    }
    sums[std::size_t(z)] = sum;
  });
  double total = 0;
  for (double s : sums) total += s;
  return 255.0 * std::sqrt(total / (double(volume.voxelCount()) * solid.channels));
}

}  // namespace texsynth
