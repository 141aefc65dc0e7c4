#pragma once
// Internal to flow animation: one frame's E+M steps on any domain of the discrete solver, from
// the advected sources, with the advected colors as the constraint E_c.
#include <span>
#include <vector>

#include "texsynth/animation/flow_animation.h"
#include "texsynth/core/random.h"
#include "texsynth/image/discrete_steps.h"

namespace texsynth::detail {

struct FrameSolution {
  std::vector<std::int32_t> sources;
  double energy = 0;
};

// E+M at the finest level, for each neighborhood size of `synthesis` from `firstScale` on (17^2
// then 9^2 by default: the larger one sees the distortion a flow piles up, rotation above all)
// (the last one's analysis holds the similarity sets), `animation.iterations` times per size:
// M-step (usage term as in static synthesis, animation.randomCandidates; copies accepted), then the
// E-step with u = the advected sources' colors and lambda = animation.coherence.
// domainFor(scale) gives the domain of a neighborhood size; `key` seeds the random candidates.
template <class DomainFor>
FrameSolution solveFrame(DomainFor&& domainFor, std::span<const ExemplarAnalysis> analyses,
                         const TextureOptimizationOptions& synthesis, const FlowAnimationOptions& animation,
                         std::size_t firstScale, std::span<const std::int32_t> advected, std::uint64_t key) {
  const ExemplarAnalysis& similarity = analyses.back();
  const int level = similarity.levelCount() - 1;
  std::vector<float> target;
  FrameSolution solution{std::vector<std::int32_t>(advected.begin(), advected.end()), 0.0};
  for (std::size_t scale = firstScale; scale < analyses.size(); ++scale) {
    const auto& domain = domainFor(scale);
    const int size = synthesis.neighborhoodSizes[scale];
    const ExemplarWindow window(analyses[scale], level, size, PixelNorm::Euclidean);
    const auto channels = std::size_t(window.channels());
    if (target.empty()) {
      target.resize(advected.size() * channels);
      for (std::size_t i = 0; i < advected.size(); ++i)
        std::copy_n(window.exemplarColor(advected[i]), channels, target.data() + i * channels);
    }
    const ColorConstraint constraint{target, animation.coherence};
    Matches matches(domain.activeCount());
    for (int iteration = 0; iteration < animation.iterations; ++iteration) {
      const UsageMap usage(window, solution.sources, synthesis.coverageWeight);
      const DiscreteStepOptions step{usage.active() ? &usage : nullptr, animation.randomCandidates,
                                     hashKey(key, std::uint64_t(scale), std::uint64_t(iteration))};
      matchDiscrete(domain, window, analyses[scale].levels[std::size_t(level)], similarity, level, solution.sources,
                    step, matches);
      solution.sources = updateDiscrete(domain, window, similarity, level, solution.sources, synthesis.voteExponent,
                                        matches, &constraint);
    }
    solution.energy = normalizedEnergy(matches, size);
  }
  return solution;
}

inline double keptFraction(std::span<const std::int32_t> before, std::span<const std::int32_t> after) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < before.size(); ++i) kept += before[i] == after[i];
  return before.empty() ? 1.0 : double(kept) / double(before.size());
}

}  // namespace texsynth::detail
