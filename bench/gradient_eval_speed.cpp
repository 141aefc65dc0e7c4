#include "gradient_eval_speed.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/gradient/tricubic_basis.h"

namespace texsynth::bench {
namespace {

std::vector<Vec3f> randomPoints(const Vec3i& voxels, std::int64_t count) {
  std::vector<Vec3f> points(static_cast<std::size_t>(count));
  parallelFor(
      0, count,
      [&](std::int64_t i) {
        for (int a = 0; a < 3; ++a)
          points[std::size_t(i)][a] = uniform01(hashKey(7, std::uint64_t(i), std::uint64_t(a))) * float(voxels[a] - 1);
      },
      1 << 16);
  return points;
}

// The smallest cubic grid with at least `count` points spanning the solid, x fastest.
std::vector<Vec3f> slicePoints(const Vec3i& voxels, std::int64_t count) {
  const int side = int(std::ceil(std::cbrt(double(count))));
  std::vector<Vec3f> points;
  points.reserve(std::size_t(side) * side * side);
  for (int z = 0; z < side; ++z)
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x)
        points.emplace_back(
            Vec3f(float(x), float(y), float(z)).cwiseProduct((voxels.cast<float>() - Vec3f::Ones()) / float(side - 1)));
  return points;
}

// Million points per second, best of `repeats`; the values are summed so nothing is optimized away.
double pointsPerSecond(const GradientSolid& solid, const std::vector<Vec3f>& points,
                       const GradientEvaluateOptions& options, int repeats) {
  static std::atomic<double> sink{0};
  double best = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    parallelForChunks(0, std::int64_t(points.size()), 1 << 16, [&](std::int64_t begin, std::int64_t end) {
      // Batches of 256 points, as SolidTexture consumers hand them over.
      float out[256 * 4], sum = 0;
      for (std::int64_t i = begin; i < end; i += 256) {
        const std::size_t count = std::size_t(std::min<std::int64_t>(256, end - i));
        evaluateGradientSolid(solid, std::span<const Vec3f>(&points[std::size_t(i)], count), options, out);
        sum += out[0];
      }
      sink.store(sink.load(std::memory_order_relaxed) + sum, std::memory_order_relaxed);
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, double(points.size()) / seconds * 1e-6);
  }
  return best;
}

}  // namespace

void printEvaluationSpeeds(const std::vector<std::pair<std::string, const GradientSolid*>>& solids, std::int64_t points,
                           int repeats) {
  const TricubicWeightTable table33(33), table17(17);
  GradientEvaluateOptions exact, fine, coarse, first;
  fine.table = &table33;
  coarse.table = &table17;
  first.exact = false;
  std::printf("Evaluation, M points/s, %lld single points per run, best of %d, %d threads (parallelFor)\n\n",
              static_cast<long long>(points), repeats, threadLimit());
  std::printf("| solid | regions | point order | exact | table 33 | table 17 | first order |\n");
  std::printf("|---|---|---|---:|---:|---:|---:|\n");
  for (const auto& [name, solid] : solids) {
    const std::vector<Vec3f> orders[2] = {randomPoints(solid->voxels, points), slicePoints(solid->voxels, points)};
    for (int o = 0; o < 2; ++o) {
      std::printf("| %s | %s | %s", name.c_str(), solid->hasRegions() ? "yes" : "no", o == 0 ? "shuffled" : "slices");
      for (const GradientEvaluateOptions* options : {&exact, &fine, &coarse, &first})
        std::printf(" | %.1f", pointsPerSecond(*solid, orders[o], *options, repeats));
      std::printf(" |\n");
      std::fflush(stdout);
    }
  }
}

}  // namespace texsynth::bench
