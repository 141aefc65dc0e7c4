#include "test_volumes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "texsynth/core/color.h"
#include "texsynth/core/gradient_noise.h"
#include "texsynth/core/math.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"

namespace texsynth::bench {
namespace {

struct Ball {
  Vec3f centre;
  float radius;
  int colour;
};

// Rejection sampling: radii 9..20 voxels, wholly inside, at least 2 voxels apart.
std::vector<Ball> placeBalls(int side, std::uint64_t seed) {
  Rng rng(hashKey(seed, 1));
  std::vector<Ball> balls;
  for (int attempt = 0; attempt < 4000 && balls.size() < 40; ++attempt) {
    const float radius = 9.0f + 11.0f * rng.uniform();
    const float span = float(side - 3) - 2 * radius;
    if (span <= 0) continue;
    const Vec3f centre(1 + radius + span * rng.uniform(), 1 + radius + span * rng.uniform(),
                       1 + radius + span * rng.uniform());
    const bool clear = std::none_of(balls.begin(), balls.end(),
                                    [&](const Ball& b) { return (b.centre - centre).norm() < b.radius + radius + 2; });
    if (clear) balls.push_back({centre, radius, int(rng.below(5))});
  }
  return balls;
}

}  // namespace

Volume makeBallsVolume(int side, std::uint64_t seed, Volume& mask) {
  static constexpr std::array<std::array<float, 3>, 5> kPalette = {{{0.90f, 0.22f, 0.15f},
                                                                    {0.97f, 0.82f, 0.22f},
                                                                    {0.22f, 0.38f, 0.90f},
                                                                    {0.25f, 0.75f, 0.32f},
                                                                    {0.92f, 0.90f, 0.86f}}};
  Volume volume(side, side, side, 3);
  mask = Volume(side, side, side, 1);
  parallelFor(0, side, [&](std::int64_t z) {  // background: slow, low-frequency colour drift
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x)
        for (int c = 0; c < 3; ++c) {
          const float n =
              gradientNoise3(float(x) / 48, float(y) / 48, float(z) / 48, hashKey(seed, 2, std::uint64_t(c)));
          volume.at(x, y, int(z), c) = std::clamp(0.45f + 0.05f * float(c) + 0.3f * n, 0.0f, 1.0f);
        }
  });
  // Shading: a fixed light over the unit "normal" (p - centre) / radius, darker towards the rim;
  // smooth inside each ball, so only the boundary is sharp.
  const Vec3f light = Vec3f(0.5f, 0.6f, 0.62f).normalized();
  for (const Ball& ball : placeBalls(side, seed)) {
    const Vec3i lo = (ball.centre.array() - ball.radius).floor().cast<int>();
    const Vec3i hi = (ball.centre.array() + ball.radius).ceil().cast<int>();
    for (int z = lo.z(); z <= hi.z(); ++z)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int x = lo.x(); x <= hi.x(); ++x) {
          const Vec3f n = (Vec3f(float(x), float(y), float(z)) - ball.centre) / ball.radius;
          if (n.squaredNorm() > 1.0f) continue;
          const float shade = 0.45f + 0.4f * n.dot(light) + 0.25f * (1.0f - n.squaredNorm());
          for (int c = 0; c < 3; ++c) volume.at(x, y, z, c) = std::clamp(kPalette[ball.colour][c] * shade, 0.0f, 1.0f);
          mask.at(x, y, z, 0) = 1.0f;
        }
  }
  return volume;
}

Volume makeCausticsVolume(int side, std::uint64_t seed) {
  // Interference of four plane waves through a noise-warped space; light gathers where their sum is
  // near zero. exp(-k s^2) keeps the bright sheets a few voxels wide, so nothing is sharp.
  static constexpr float kDirections[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  static constexpr float kWavelength = 36.0f;
  auto intensity = [&](const Vec3f& p, std::uint64_t layer, float twist) {
    const Vec3f q = p / kWavelength;
    Vec3f warped = q;
    for (int a = 0; a < 3; ++a)
      warped[a] += 0.6f * gradientNoise3(0.5f * q.x() + twist, 0.5f * q.y(), 0.5f * q.z(), hashKey(seed, layer, a));
    float sum = 0;
    for (int i = 0; i < 4; ++i) {
      const Vec3f d = Vec3f(kDirections[i][0], kDirections[i][1], kDirections[i][2]) / std::sqrt(3.0f);
      sum += std::cos(6.2831853f * d.dot(warped) + float(i) * 1.3f + twist);
    }
    return std::exp(-0.35f * sum * sum);
  };
  Volume volume(side, side, side, 3);
  parallelFor(0, side, [&](std::int64_t z) {
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) {
        const Vec3f p{float(x), float(y), float(z)};
        const float light = 0.8f * intensity(p, 10, 0.0f), glow = 0.3f * intensity(1.37f * p, 20, 2.1f);
        const float hue = 0.5f + 0.5f * gradientNoise3(p.x() / 60, p.y() / 60, p.z() / 60, hashKey(seed, 30));
        const Vec3f water(0.05f, 0.22f, 0.36f), cyan(0.35f, 0.92f, 1.0f), gold(1.0f, 0.84f, 0.3f);
        const Vec3f magenta(0.9f, 0.3f, 0.8f);
        Vec3f colour = water * (1 - light) + (cyan * (1 - hue) + gold * hue) * light;
        colour = Vec3f::Ones() - (Vec3f::Ones() - colour).cwiseProduct(Vec3f::Ones() - glow * magenta);  // screen
        for (int c = 0; c < 3; ++c) volume.at(x, y, int(z), c) = std::clamp(colour[c], 0.0f, 1.0f);
      }
  });
  return volume;
}

std::vector<float> luminanceMask(const std::vector<float>& values, int channels, float quantile, bool above) {
  const std::size_t count = values.size() / std::size_t(channels);
  std::vector<float> luma(count);
  for (std::size_t i = 0; i < count; ++i) luma[i] = luminance(&values[i * std::size_t(channels)], channels);
  std::vector<float> sorted = luma;
  auto at = sorted.begin() + std::ptrdiff_t(std::min(count - 1, std::size_t(quantile * float(count))));
  std::nth_element(sorted.begin(), at, sorted.end());
  std::vector<float> mask(count);
  for (std::size_t i = 0; i < count; ++i) mask[i] = (above ? luma[i] > *at : luma[i] < *at) ? 1.0f : 0.0f;
  return mask;
}

Volume medianLuminanceMask(const Volume& volume) {
  Volume mask(volume.nx, volume.ny, volume.nz, 1);
  mask.voxels = luminanceMask(volume.voxels, volume.channels, 0.5f, true);
  return mask;
}

}  // namespace texsynth::bench
