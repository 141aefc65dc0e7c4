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

// The tricubic sum over a cube's 8 corner sets, contracted axis by axis: first over y and z, leaving
// per channel 4 coefficients of the x axis' Hermite functions (the x values at both corners and the x
// slopes), then over x. Points of a row share y and z, so a row inside one cube computes the
// coefficients once and then costs 4 multiply-adds per channel and point. Channels (1 to 4) sit side by
// side in 4-float vectors, each slot of a set one load.
using Float4 = float __attribute__((vector_size(16)));

template <int Channels>
inline Float4 loadSlot(const float* set, int slot) {
  Float4 v = {0, 0, 0, 0};
  // A set ends with slot 3: read only its own channels there (RGB elsewhere reads one float more).
  std::memcpy(&v, set + Channels * slot, (Channels == 3 && slot < 3 ? 4 : Channels) * sizeof(float));
  return v;
}

struct XCoefficients {
  Float4 value[2], slope[2];  // per x corner: what multiplies its value function, its slope function
};

template <int Channels>
__attribute__((always_inline)) inline XCoefficients contractYZ(const Hermite& hv, const Hermite& hw,
                                                               const float* const* sets) {
  XCoefficients e;
  for (int x = 0; x < 2; ++x) {
    Float4 value = {0, 0, 0, 0}, slope = {0, 0, 0, 0};
    for (int z = 0; z < 2; ++z)
      for (int y = 0; y < 2; ++y) {
        const float* set = sets[x + 2 * y + 4 * z];
        const float both = hv[y] * hw[z];
        value += both * loadSlot<Channels>(set, 0) + (hv[2 + y] * hw[z]) * loadSlot<Channels>(set, 2) +
                 (hv[y] * hw[2 + z]) * loadSlot<Channels>(set, 3);
        slope += both * loadSlot<Channels>(set, 1);
      }
    e.value[x] = value, e.slope[x] = slope;
  }
  return e;
}

template <int Channels>
__attribute__((always_inline)) inline void contractX(const Hermite& hu, const XCoefficients& e, float* out) {
  const Float4 sum = hu[0] * e.value[0] + hu[1] * e.value[1] + hu[2] * e.slope[0] + hu[3] * e.slope[1];
  for (int c = 0; c < Channels; ++c) out[c] = sum[c];
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
  const float* sets[8];
  cornerSets(solid.distance, 4, corners, sets);
  float d;
  contractX<1>(hermiteBasis(at.t[0]), contractYZ<1>(hermiteBasis(at.t[1]), hermiteBasis(at.t[2]), sets), &d);
  return d;
}

namespace {

// Batches of points: consecutive points in one cube share its corners' sets, and points of a row (the
// same y and z inside the cube, as slices and volumes give them) share the y-z contraction of every
// array they need (colours of either side, distance, detail), computed on first use. Single points go
// through here too, so every path gives the same bits.
template <int Channels>
class BatchEvaluator {
 public:
  BatchEvaluator(const GradientSolid& solid, const GradientEvaluateOptions& options)
      : solid_(solid),
        options_(options),
        regions_(options.regions && solid.hasRegions()),
        detail_(options.detail && solid.hasDetail()) {}

  __attribute__((always_inline)) inline void operator()(const Vec3f& point, float* out) {
    const CubeLocation at = locate(solid_, point);
    const std::int64_t cube = solid_.controlIndex(at.cube[0], at.cube[1], at.cube[2]);
    if (cube != cube_) enterCube(at, cube);
    if (at.t[1] != rowV_ || at.t[2] != rowW_) {
      rowV_ = at.t[1], rowW_ = at.t[2];
      hv_ = axis(rowV_), hw_ = axis(rowW_);
      ready_ = 0;
    }
    const Hermite hu = axis(at.t[0]);
    float distance = 1.0f;
    if (regions_) contractX<1>(hu, coefficients(kDistance), &distance);
    const float half = 0.5f * options_.antialiasVoxels;
    if (!regions_ || distance >= half) {
      contractX<Channels>(hu, coefficients(kPositive), out);
    } else if (distance <= -half) {
      contractX<Channels>(hu, coefficients(kNegative), out);
    } else {  // near the boundary: blend both sides linearly across antialiasVoxels (§5.3)
      float negative[4];
      contractX<Channels>(hu, coefficients(kPositive), out);
      contractX<Channels>(hu, coefficients(kNegative), negative);
      const float t = 0.5f + distance / options_.antialiasVoxels;
      for (int c = 0; c < Channels; ++c) out[c] = t * out[c] + (1 - t) * negative[c];
    }
    if (detail_) {  // §5.4: Gaussian grain of the fitted sigma, fixed per voxel
      float sigma[4];
      contractX<Channels>(hu, coefficients(kDetail), sigma);
      const std::uint64_t cell = latticeId(std::lround(point.x()), std::lround(point.y()), std::lround(point.z()));
      // One draw for all channels: texture grain is mostly light and dark, and independent draws per
      // channel would show as coloured speckle.
      const float grain = gaussianFromKey(hashKey(options_.detailSeed, cell));
      for (int c = 0; c < Channels; ++c) out[c] += std::max(sigma[c], 0.0f) * grain;
    }
  }

 private:
  enum Array { kPositive, kNegative, kDistance, kDetail };

  Hermite axis(float t) const { return options_.table ? options_.table->axisFunctions(t) : hermiteBasis(t); }

  void enterCube(const CubeLocation& at, std::int64_t cube) {
    cube_ = cube, rowV_ = -1, ready_ = 0;
    std::int64_t corners[8];
    cornerIndices(solid_, at, corners);
    const std::size_t stride = std::size_t(solid_.setSize());
    cornerSets(solid_.positive, stride, corners, sets_[kPositive]);
    if (regions_) {
      cornerSets(solid_.distance, 4, corners, sets_[kDistance]);
      for (int p = 0; p < 8; ++p) {
        const std::int32_t index = solid_.negativeIndex[std::size_t(corners[p])];
        sets_[kNegative][p] = index < 0 ? sets_[kPositive][p] : &solid_.negative[std::size_t(index) * stride];
      }
    }
    if (detail_) cornerSets(solid_.detail, stride, corners, sets_[kDetail]);
  }

  const XCoefficients& coefficients(Array array) {
    if (!(ready_ & (1u << array))) {
      contracted_[array] =
          array == kDistance ? contractYZ<1>(hv_, hw_, sets_[array]) : contractYZ<Channels>(hv_, hw_, sets_[array]);
      ready_ |= 1u << array;
    }
    return contracted_[array];
  }

  const GradientSolid& solid_;
  const GradientEvaluateOptions& options_;
  const bool regions_, detail_;
  std::int64_t cube_ = -1;
  float rowV_ = -1, rowW_ = -1;
  Hermite hv_{}, hw_{};
  const float* sets_[4][8] = {};
  XCoefficients contracted_[4] = {};
  unsigned ready_ = 0;  // bit per Array: contracted_ holds it for this row
};

template <int Channels>
__attribute__((always_inline)) inline void evaluateBatch(const GradientSolid& solid, const Vec3f* points,
                                                         std::size_t count, const GradientEvaluateOptions& options,
                                                         float* out) {
  BatchEvaluator<Channels> evaluate(solid, options);
  for (std::size_t n = 0; n < count; ++n) evaluate(points[n], out + n * Channels);
}

// GCC also builds these for AVX2 and picks at load time where the CPU has it; the module is compiled
// without FMA contraction (src/CMakeLists.txt), so both give the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define TEXSYNTH_AVX2_CLONE __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define TEXSYNTH_AVX2_CLONE
#endif

TEXSYNTH_AVX2_CLONE void evaluateRgb(const GradientSolid& solid, const Vec3f* points, std::size_t count,
                                     const GradientEvaluateOptions& options, float* out) {
  evaluateBatch<3>(solid, points, count, options, out);
}

TEXSYNTH_AVX2_CLONE void evaluateOtherChannels(const GradientSolid& solid, const Vec3f* points, std::size_t count,
                                               const GradientEvaluateOptions& options, float* out) {
  switch (solid.channels) {
    case 1:
      return evaluateBatch<1>(solid, points, count, options, out);
    case 2:
      return evaluateBatch<2>(solid, points, count, options, out);
    default:
      return evaluateBatch<4>(solid, points, count, options, out);
  }
}

}  // namespace

void evaluateGradientSolid(const GradientSolid& solid, std::span<const Vec3f> points,
                           const GradientEvaluateOptions& options, float* out) {
  if (!options.exact) {
    for (std::size_t n = 0; n < points.size(); ++n)
      evaluateGradientSolid(solid, points[n], options, out + n * std::size_t(solid.channels));
  } else if (solid.channels == 3) {
    evaluateRgb(solid, points.data(), points.size(), options, out);
  } else {
    evaluateOtherChannels(solid, points.data(), points.size(), options, out);
  }
}

void evaluateGradientSolid(const GradientSolid& solid, const Vec3f& point, const GradientEvaluateOptions& options,
                           float* out) {
  if (options.exact) return evaluateGradientSolid(solid, std::span<const Vec3f>(&point, 1), options, out);
  // First-order approximation (§4.2.4), on the side the distance gives.
  const std::size_t setSize = std::size_t(solid.setSize());
  auto positiveSet = [&](std::int64_t control) { return &solid.positive[std::size_t(control) * setSize]; };
  auto negativeSet = [&](std::int64_t control) {
    const std::int32_t index = solid.negativeIndex[std::size_t(control)];
    return index < 0 ? positiveSet(control) : &solid.negative[std::size_t(index) * setSize];
  };
  if (options.regions && solid.hasRegions() && evaluateGradientDistance(solid, point) < 0.0f)
    firstOrder(solid, point, solid.channels, negativeSet, out);
  else
    firstOrder(solid, point, solid.channels, positiveSet, out);
}

namespace {

// Calls row(y, z, values) for every row of the solid's raster, the rows of one z in one task, with the
// row's nx * channels values.
template <typename Row>
void forEachRasterRow(const GradientSolid& solid, const GradientEvaluateOptions& options, Row row) {
  const int nx = solid.voxels.x();
  parallelFor(0, solid.voxels.z(), [&](std::int64_t z) {
    std::vector<Vec3f> points(static_cast<std::size_t>(nx));
    std::vector<float> values(points.size() * std::size_t(solid.channels));
    for (int y = 0; y < solid.voxels.y(); ++y) {
      for (int x = 0; x < nx; ++x) points[std::size_t(x)] = Vec3f(float(x), float(y), float(z));
      evaluateGradientSolid(solid, points, options, values.data());
      row(y, int(z), values.data());
    }
  });
}

}  // namespace

Volume rasterizeGradientSolid(const GradientSolid& solid, const GradientEvaluateOptions& options) {
  Volume volume(solid.voxels.x(), solid.voxels.y(), solid.voxels.z(), solid.channels);
  forEachRasterRow(solid, options, [&](int y, int z, const float* values) {
    std::copy_n(values, std::size_t(volume.nx) * std::size_t(volume.channels), volume.voxel(0, y, z));
  });
  return volume;
}

double gradientSolidRms(const GradientSolid& solid, const Volume& volume, const GradientEvaluateOptions& options) {
  if (volume.nx != solid.voxels.x() || volume.ny != solid.voxels.y() || volume.nz != solid.voxels.z())
    throw ParameterError("volume", "is not the size of the solid's raster");
  if (volume.channels < solid.channels) throw ParameterError("volume", "has fewer channels than the solid");
  std::vector<double> sums(std::size_t(volume.nz), 0.0);  // per z: each written by its own task
  forEachRasterRow(solid, options, [&](int y, int z, const float* values) {
    double& sum = sums[std::size_t(z)];
    for (int x = 0; x < volume.nx; ++x) {
      const float* original = volume.voxel(x, y, z);
      for (int c = 0; c < solid.channels; ++c) {
        const double d = values[std::size_t(x) * solid.channels + std::size_t(c)] - original[c];
        sum += d * d;
      }
    }
  });
  double total = 0;
  for (double s : sums) total += s;
  return 255.0 * std::sqrt(total / (double(volume.voxelCount()) * solid.channels));
}

}  // namespace texsynth
