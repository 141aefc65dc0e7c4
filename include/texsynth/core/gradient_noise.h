#pragma once
// Perlin gradient noise (Perlin 1985, with the 2002 quintic fade) in 2D and 3D.
//
// Every lattice point gets a pseudo-random unit gradient chosen by
// hashKey(seed, latticeId(...)), so noise is seedable, stateless and identical on every
// thread. Raw Perlin noise with unit gradients is bounded by sqrt(N)/2 (N = dimension); the
// functions below multiply by 2/sqrt(N), so values always lie in [-1, 1] (typical values are
// within ±0.6, extremes near ±0.95 are rare). Noise is 0 at every lattice point and C2
// continuous. A positive period makes noise periodic along that axis (the lattice wraps:
// noise(x + period) == noise(x) up to the float rounding of x + period); 0 means not periodic.
// The hot path is inline and allocation-free.
#include <cmath>
#include <cstdint>

#include "texsynth/core/random.h"
#include "texsynth/core/wrap.h"

namespace texsynth {

namespace noise_detail {

// 16 unit directions, evenly spaced and rotated half a step off the axes.
inline constexpr float kGradients2[16][2] = {
    {0.980785280f, 0.195090322f},   {0.831469612f, 0.555570233f},   {0.555570233f, 0.831469612f},
    {0.195090322f, 0.980785280f},   {-0.195090322f, 0.980785280f},  {-0.555570233f, 0.831469612f},
    {-0.831469612f, 0.555570233f},  {-0.980785280f, 0.195090322f},  {-0.980785280f, -0.195090322f},
    {-0.831469612f, -0.555570233f}, {-0.555570233f, -0.831469612f}, {-0.195090322f, -0.980785280f},
    {0.195090322f, -0.980785280f},  {0.555570233f, -0.831469612f},  {0.831469612f, -0.555570233f},
    {0.980785280f, -0.195090322f}};

// Perlin's 12 cube-edge directions (2002), normalized to unit length.
inline constexpr float kEdge = 0.707106781f;
inline constexpr float kGradients3[12][3] = {{kEdge, kEdge, 0},   {-kEdge, kEdge, 0},  {kEdge, -kEdge, 0},
                                             {-kEdge, -kEdge, 0}, {kEdge, 0, kEdge},   {-kEdge, 0, kEdge},
                                             {kEdge, 0, -kEdge},  {-kEdge, 0, -kEdge}, {0, kEdge, kEdge},
                                             {0, -kEdge, kEdge},  {0, kEdge, -kEdge},  {0, -kEdge, -kEdge}};

// Quintic fade 6t^5 - 15t^4 + 10t^3: zero first and second derivatives at 0 and 1.
inline float fade(float t) {
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

inline std::int64_t wrapLattice(std::int64_t i, int period) {
  return period <= 0 ? i : wrapIndex(i, period);
}

inline float lerp(float a, float b, float t) {
  return a + (b - a) * t;
}

inline float corner2(std::uint64_t seed, std::int64_t ix, std::int64_t iy, float dx, float dy) {
  const float* g = kGradients2[hashKey(seed, latticeId(ix, iy)) & 15u];
  return g[0] * dx + g[1] * dy;
}

inline float corner3(std::uint64_t seed, std::int64_t ix, std::int64_t iy, std::int64_t iz, float dx, float dy,
                     float dz) {
  const float* g = kGradients3[uniformBelow(hashKey(seed, latticeId(ix, iy, iz)), 12)];
  return g[0] * dx + g[1] * dy + g[2] * dz;
}

}  // namespace noise_detail

// 2D Perlin noise in [-1, 1]; lattice spacing 1. periodX/periodY > 0 wrap the lattice.
inline float gradientNoise2(float x, float y, std::uint64_t seed, int periodX = 0, int periodY = 0) {
  using namespace noise_detail;
  float fx = std::floor(x), fy = std::floor(y);
  float dx = x - fx, dy = y - fy;
  std::int64_t ix = std::int64_t(fx), iy = std::int64_t(fy);
  std::int64_t x0 = wrapLattice(ix, periodX), x1 = wrapLattice(ix + 1, periodX);
  std::int64_t y0 = wrapLattice(iy, periodY), y1 = wrapLattice(iy + 1, periodY);
  float n00 = corner2(seed, x0, y0, dx, dy), n10 = corner2(seed, x1, y0, dx - 1, dy);
  float n01 = corner2(seed, x0, y1, dx, dy - 1), n11 = corner2(seed, x1, y1, dx - 1, dy - 1);
  float u = fade(dx), v = fade(dy);
  constexpr float kNormalize = 1.41421356f;  // 2 / sqrt(2)
  return kNormalize * lerp(lerp(n00, n10, u), lerp(n01, n11, u), v);
}

// 3D Perlin noise in [-1, 1]; lattice spacing 1. Positive periods wrap the lattice.
inline float gradientNoise3(float x, float y, float z, std::uint64_t seed, int periodX = 0, int periodY = 0,
                            int periodZ = 0) {
  using namespace noise_detail;
  float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  float dx = x - fx, dy = y - fy, dz = z - fz;
  std::int64_t ix = std::int64_t(fx), iy = std::int64_t(fy), iz = std::int64_t(fz);
  std::int64_t x0 = wrapLattice(ix, periodX), x1 = wrapLattice(ix + 1, periodX);
  std::int64_t y0 = wrapLattice(iy, periodY), y1 = wrapLattice(iy + 1, periodY);
  std::int64_t z0 = wrapLattice(iz, periodZ), z1 = wrapLattice(iz + 1, periodZ);
  float u = fade(dx), v = fade(dy), w = fade(dz);
  float front =
      lerp(lerp(corner3(seed, x0, y0, z0, dx, dy, dz), corner3(seed, x1, y0, z0, dx - 1, dy, dz), u),
           lerp(corner3(seed, x0, y1, z0, dx, dy - 1, dz), corner3(seed, x1, y1, z0, dx - 1, dy - 1, dz), u), v);
  float back = lerp(
      lerp(corner3(seed, x0, y0, z1, dx, dy, dz - 1), corner3(seed, x1, y0, z1, dx - 1, dy, dz - 1), u),
      lerp(corner3(seed, x0, y1, z1, dx, dy - 1, dz - 1), corner3(seed, x1, y1, z1, dx - 1, dy - 1, dz - 1), u), v);
  constexpr float kNormalize = 1.15470054f;  // 2 / sqrt(3)
  return kNormalize * lerp(front, back, w);
}

// Fractal sum of octaves (fBm): octave k has frequency lacunarity^k, amplitude gain^k and
// its own seed; the sum is divided by the total amplitude, so it stays in [-1, 1].
struct FbmOptions {
  int octaves = 4;          // >= 1
  float lacunarity = 2.0f;  // frequency ratio between octaves (> 0)
  float gain = 0.5f;        // amplitude ratio between octaves (> 0)
};

// Throws ParameterError("octaves" / "lacunarity" / "gain", ...) for invalid options.
float fbm2(float x, float y, std::uint64_t seed, const FbmOptions& options = {});
float fbm3(float x, float y, float z, std::uint64_t seed, const FbmOptions& options = {});

}  // namespace texsynth
