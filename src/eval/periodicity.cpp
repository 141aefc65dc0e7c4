#include "texsynth/eval/periodicity.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <unordered_map>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"

namespace texsynth {
namespace {

// Samples searched per parallel round; bounds memory when an image is nearly flat and every
// patch duplicates every other.
constexpr int kSamplesPerRound = 64;

// (dx, dy) and (-dx, -dy) are the same period: keep the one with dy > 0, or dy == 0 and dx > 0.
std::uint64_t periodKey(int dx, int dy) {
  if (dy < 0 || (dy == 0 && dx < 0)) dx = -dx, dy = -dy;
  return (std::uint64_t(std::uint32_t(dx)) << 32) | std::uint32_t(dy);
}

// The distinct periods at which the patch at `position` has a non-overlapping duplicate.
std::vector<std::uint64_t> duplicatePeriods(const PatchIndex& index, std::size_t position, double threshold) {
  const int columns = index.columns(), size = index.patchSize();
  const int x = int(position % columns), y = int(position / columns);
  std::vector<std::uint64_t> periods;
  for (int other : index.within(index.image(), x, y, threshold)) {
    const int dx = other % columns - x, dy = other / columns - y;
    if (std::abs(dx) < size && std::abs(dy) < size) continue;  // overlaps the sample itself
    periods.push_back(periodKey(dx, dy));
  }
  std::sort(periods.begin(), periods.end());
  periods.erase(std::unique(periods.begin(), periods.end()), periods.end());
  return periods;
}

}  // namespace

double periodicity(const PatchIndex& index, const PeriodicityOptions& options) {
  if (options.samples < 1)
    throw ParameterError("periodicitySamples", "must be at least 1, got " + std::to_string(options.samples));
  if (!(options.duplicateThreshold >= 0) || !std::isfinite(options.duplicateThreshold))
    throw ParameterError("duplicateThreshold",
                         "must be a finite value >= 0, got " + std::to_string(options.duplicateThreshold));
  const std::size_t positions = index.size();
  TS_CHECK(positions <= UINT32_MAX);  // uniformBelow draws 32-bit positions
  const bool everyPosition = positions <= std::size_t(options.samples);
  const std::size_t samples = everyPosition ? positions : std::size_t(options.samples);
  auto samplePosition = [&](std::size_t i) -> std::size_t {
    if (everyPosition) return i;
    return uniformBelow(hashKey(options.seed, i), std::uint32_t(positions));
  };

  std::unordered_map<std::uint64_t, int> samplesWithPeriod;
  std::vector<std::vector<std::uint64_t>> round(kSamplesPerRound);
  for (std::size_t first = 0; first < samples; first += kSamplesPerRound) {
    const std::size_t count = std::min<std::size_t>(kSamplesPerRound, samples - first);
    parallelFor(0, std::int64_t(count), [&](std::int64_t k) {
      round[k] = duplicatePeriods(index, samplePosition(first + k), options.duplicateThreshold);
    });
    for (std::size_t k = 0; k < count; ++k)
      for (std::uint64_t period : round[k]) ++samplesWithPeriod[period];
  }
  int most = 0;
  for (const auto& [period, count] : samplesWithPeriod) most = std::max(most, count);
  return double(most) / double(samples);
}

}  // namespace texsynth
