#pragma once
// The E- and M-steps of the discrete texture-optimization solver (Han et al., "Fast
// example-based surface texture synthesis via discrete optimization", Table 1), written once for
// every output domain: image grids (image/texture_optimization) and mesh vertices
// (surface/surface_synthesis). The output is a map of SOURCES, one exemplar pixel index per
// output sample, so it stays crisp and k-coherence keeps working.
//
// A domain describes the output's active neighborhoods X and how they read the samples:
//   std::int64_t sampleCount() const, activeCount() const;
//   std::int64_t sampleChunk() const, activeChunk() const;  parallel grains
//   int size() const;                                         N
//   void gather(std::int64_t a, ColorOf colorOf, float* out) const;
//       x_p = W_p x of neighborhood a, in the layout of ExemplarWindow::distance;
//       colorOf(sample) gives a sample's color (const float*)
//   bool masksCells() const;
//       whether gather may mark cells as missing (NaN in their first channel: past a mesh's
//       border or around a part thinner than the neighborhood); those are left out of the
//       M-step's comparisons
//   void forEachMember(std::int64_t a, Visit visit) const;
//       visit(sample, dx, dy) for the samples inside neighborhood a at their offsets from its
//       centre (output pixels; int on grids, float on meshes)
//   void forEachCovering(std::int64_t sample, Visit visit) const;
//       visit(a, dx, dy): the transpose, the neighborhoods a sample lies in
// Every step reads only the state before it and writes a new one, sample by sample or
// neighborhood by neighborhood, so results never depend on scheduling.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/progress.h"
#include "texsynth/core/random.h"
#include "texsynth/core/timing.h"
#include "texsynth/exemplar/analysis.h"
#include "texsynth/image/exemplar_usage.h"
#include "texsynth/image/exemplar_window.h"
#include "texsynth/image/texture_optimization.h"

namespace texsynth::detail {

// The matches z_p of the active neighborhoods and their distances |x_p - z_p|.
struct Matches {
  std::vector<std::int32_t> pixel;  // exemplar pixel whose neighborhood matches; -1 = none yet
  std::vector<float> distance;
  explicit Matches(std::int64_t count = 0) : pixel(std::size_t(count), -1), distance(std::size_t(count), 0.0f) {}
};

// Sum of the distances in index order (independent of the thread count), over |X| N^2.
inline double normalizedEnergy(const Matches& matches, int neighborhoodSize) {
  double sum = 0;
  for (float d : matches.distance) sum += d;
  return matches.distance.empty() ? 0.0 : sum / (double(matches.distance.size()) * neighborhoodSize * neighborhoodSize);
}

// Kwatra et al.: neighborhoods of width w overlap by 3/4, centres w/4 apart (in output pixels).
inline int activeStride(int neighborhoodSize) {
  return neighborhoodSize / 4 > 1 ? neighborhoodSize / 4 : 1;
}

// What the discrete M-step adds to plain k-coherence.
struct DiscreteStepOptions {
  const UsageMap* usage = nullptr;  // the usage term; null = none
  int randomCandidates = 0;         // uniformly random exemplar neighborhoods per match
  std::uint64_t randomKey = 0;      // their hash key (seed, level, size, iteration)
};

namespace discrete {

// Candidates measured in full space after the PCA ranking: PCA-20 alone picks a worse match
// (pink_marble 256^2: PCA alone 0.00051, shortlist 8 0.00032, 32 0.00028 = all candidates' 0.00028
// at half the time of measuring all).
// With the usage term and random candidates 8 keep the same quality (GIMP rock and leaves at
// 512^2: coherence within 1%) at 0.78x the time of 32.
inline constexpr std::size_t kFullSpaceShortlist = 8;
// The vote weights' floor, in mean color distance per pixel: a perfect match does not outvote
// every other one infinitely.
inline constexpr float kVoteDistanceFloor = 0.01f;
// E-step with weighted votes: votes below this share of the strongest are left out of the
// cost, and only the strongest few votes propose candidates (their similarity sets): 2 instead
// of 4 leaves coherence and its 90th percentile within 0.5% (12 GIMP exemplars at 256^2) at
// 0.96x the time (512^2).
inline constexpr float kNegligibleVote = 1e-3f;
inline constexpr std::size_t kProposingVotes = 2;

// Which exemplar pixels a neighborhood has seen since clear(), in O(1) per pixel: a stamp per
// pixel, kept per thread across calls (sorting the candidates to drop repeats took 13% of a
// 512^2 optimization).
class SeenPixels {
 public:
  explicit SeenPixels(std::int32_t pixelCount) {
    if (stamps().size() < std::size_t(pixelCount)) stamps().assign(std::size_t(pixelCount), 0), epoch() = 0;
  }
  void clear() {
    if (++epoch() == 0) std::fill(stamps().begin(), stamps().end(), 0), epoch() = 1;
  }
  // True the first time `pixel` is inserted after a clear().
  bool insert(std::int32_t pixel) {
    std::uint32_t& stamp = stamps()[std::size_t(pixel)];
    if (stamp == epoch()) return false;
    stamp = epoch();
    return true;
  }

 private:
  static std::vector<std::uint32_t>& stamps() {
    thread_local std::vector<std::uint32_t> values;
    return values;
  }
  static std::uint32_t& epoch() {
    thread_local std::uint32_t value = 0;
    return value;
  }
};

inline float squaredDistance(const float* a, const float* b, int channels) {
  float sum = 0;
  for (int i = 0; i < channels; ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return sum;
}

}  // namespace discrete

// x_p of active neighborhood a into `query`. Missing cells (a domain that masksCells()) take
// the PCA mean (no pull in a PCA ranking) and are left out of the full distance: returns the
// distance's mask (null: none missing; else `kept`, one byte per cell) and scale.
template <class Domain, class ColorOf>
std::pair<const std::uint8_t*, float> gatherQuery(const Domain& domain, const ExemplarWindow& window,
                                                  const PcaBasis& pca, std::int64_t a, ColorOf&& colorOf, float* query,
                                                  std::uint8_t* kept) {
  domain.gather(a, colorOf, query);
  if (!domain.masksCells()) return {nullptr, 1.0f};
  const int c = window.channels(), cells = window.size * window.size;
  int keptCount = 0;
  for (int i = 0; i < cells; ++i) {
    float* cell = query + std::size_t(i) * c;
    kept[i] = !std::isnan(cell[0]);
    if (kept[i])
      ++keptCount;
    else
      std::copy_n(pca.mean.data() + std::size_t(i) * c, c, cell);
  }
  if (keptCount == cells) return {nullptr, 1.0f};
  return {kept, float(cells) / float(std::max(keptCount, 1))};
}

// The distances |x_p - z_p| of the active neighborhoods to their current matches, without a
// search: the energy of an output against the matches its last E-step used.
template <class Domain>
void measureDiscrete(const Domain& domain, const ExemplarWindow& window, const PcaBasis& pca,
                     std::span<const std::int32_t> sources, Matches& matches) {
  TS_CHECK(std::int64_t(matches.pixel.size()) == domain.activeCount());
  parallelForChunks(0, domain.activeCount(), domain.activeChunk(), [&](std::int64_t begin, std::int64_t end) {
    std::vector<float> query(static_cast<std::size_t>(window.dimension()));
    std::vector<int> columns(std::size_t(window.size));
    std::vector<std::uint8_t> kept(std::size_t(window.size * window.size));
    auto colorOf = [&](std::int64_t sample) { return window.exemplarColor(sources[std::size_t(sample)]); };
    for (std::int64_t a = begin; a < end; ++a) {
      const std::int32_t match = matches.pixel[std::size_t(a)];
      if (match < 0) continue;
      const auto [mask, scale] = gatherQuery(domain, window, pca, a, colorOf, query.data(), kept.data());
      matches.distance[std::size_t(a)] =
          window.distance(query.data(), match, std::numeric_limits<float>::infinity(), columns.data(), mask, scale);
    }
  });
}

// Discrete M-step: each active neighborhood's match becomes the best of its k-coherence
// candidates (the exemplar neighborhoods that the sources of its samples propose, with their
// similarity sets at `level` of `similarity`) and random ones, ranked in the PCA space of
// `pcaLevel` (this neighborhood size's analysis); the winner replaces the current match only if
// it is nearer in full space, usage term included. Returns how many matches changed.
template <class Domain>
std::int64_t matchDiscrete(const Domain& domain, const ExemplarWindow& window, const ExemplarLevel& pcaLevel,
                           const ExemplarAnalysis& similarity, int level, std::span<const std::int32_t> sources,
                           const DiscreteStepOptions& step, Matches& matches) {
  using namespace discrete;
  const PcaBasis& pca = pcaLevel.pca;
  TS_CHECK(pca.inputDimension == window.dimension());
  TS_CHECK(std::int64_t(matches.pixel.size()) == domain.activeCount());
  const int k = similarity.similarCount, dimensions = pca.outputDimension;
  std::vector<std::uint8_t> changed(matches.pixel.size(), 0);
  parallelForChunks(0, domain.activeCount(), domain.activeChunk(), [&](std::int64_t begin, std::int64_t end) {
    std::vector<float> query(static_cast<std::size_t>(window.dimension()));
    std::vector<float> projected(static_cast<std::size_t>(dimensions));
    std::vector<int> columns(std::size_t(window.size));
    std::vector<std::int32_t> proposals, candidates;
    std::vector<std::pair<float, std::int32_t>> ranked;
    std::vector<std::uint8_t> kept(std::size_t(window.size * window.size));
    SeenPixels seen(window.pixelCount());
    auto colorOf = [&](std::int64_t sample) { return window.exemplarColor(sources[std::size_t(sample)]); };
    for (std::int64_t a = begin; a < end; ++a) {
      // Each sample q = c + d proposes the exemplar neighborhood centred at S(q) - h d; coherent
      // runs propose the same one, so repeats of the previous proposal are skipped early. (The
      // order of proposals and candidates does not matter: they are ranked by distance and pixel.)
      proposals.clear();
      seen.clear();
      domain.forEachMember(a, [&](std::int64_t q, auto dx, auto dy) {
        const std::int32_t proposal = window.shifted(sources[std::size_t(q)], -dx, -dy);
        if ((proposals.empty() || proposals.back() != proposal) && seen.insert(proposal)) proposals.push_back(proposal);
      });
      // A neighborhood whose samples all propose the same exemplar neighborhood is a copy of it:
      // that is its match (distance 0), without a search. The usage term could move such a
      // match elsewhere, but searching them too changed 11 of 12 GIMP exemplars' outputs at 256^2
      // by no pixel (and pine's metrics by less than 0.001) and took 1.16x the time (rock,
      // 512^2); animation frames are mostly such copies.
      if (proposals.size() == 1 && window.isAllowedCentre(proposals[0]) && !domain.masksCells()) {
        changed[std::size_t(a)] = proposals[0] != matches.pixel[std::size_t(a)];
        matches.pixel[std::size_t(a)] = proposals[0];
        matches.distance[std::size_t(a)] = 0;
        continue;
      }
      const auto [mask, scale] = gatherQuery(domain, window, pca, a, colorOf, query.data(), kept.data());
      candidates.clear();
      seen.clear();
      auto propose = [&](std::int32_t candidate) {
        if (seen.insert(candidate)) candidates.push_back(candidate);
      };
      for (std::int32_t u : proposals) {
        const std::int32_t* similar = similarity.similarAt(level, u);
        for (int i = 0; i < k; ++i) propose(window.allowedCentre(similar[i]));
      }
      // Random candidates reach exemplar parts that no coherent candidate proposes (after the
      // start dropped them), as PatchMatch's random search does.
      for (int r = 0; r < step.randomCandidates; ++r) {
        const std::uint64_t key = hashKey(step.randomKey, std::uint64_t(a), std::uint64_t(r));
        const auto x = std::int32_t(uniformBelow(key, std::uint32_t(window.exemplarWidth)));
        const auto y = std::int32_t(uniformBelow(mix64(key), std::uint32_t(window.exemplarHeight)));
        propose(window.allowedCentre(y * window.exemplarWidth + x));
      }
      // Rank in PCA space (L&H 2005), then measure the few best in full space, with the usage
      // term, against the current match, which stays on ties. No more candidates than the
      // shortlist (coherent neighborhoods without random candidates): all of them, unranked.
      ranked.clear();
      if (candidates.size() > kFullSpaceShortlist) {
        pca.project(query.data(), projected.data());
        for (std::int32_t c : candidates)
          ranked.push_back({squaredDistance(projected.data(), pcaLevel.projectedAt(c), dimensions), c});
      } else {
        for (std::int32_t c : candidates) ranked.push_back({0.0f, c});
      }
      const std::size_t shortlist = std::min<std::size_t>(ranked.size(), kFullSpaceShortlist);
      std::partial_sort(ranked.begin(), ranked.begin() + std::ptrdiff_t(shortlist), ranked.end());
      const std::int32_t current = matches.pixel[std::size_t(a)];
      // The usage term counts once per neighborhood pixel; the energy reported is the plain
      // distance.
      const float infinity = std::numeric_limits<float>::infinity();
      const float pixels = float(window.size * window.size);
      auto term = [&](std::int32_t pixel) { return step.usage ? pixels * step.usage->cost(pixel) : 0.0f; };
      float bestDistance =
          current >= 0 ? window.distance(query.data(), current, infinity, columns.data(), mask, scale) : infinity;
      float best = current >= 0 ? bestDistance + term(current) : infinity;
      std::int32_t bestPixel = current;
      for (std::size_t i = 0; i < shortlist; ++i) {
        const std::int32_t candidate = ranked[i].second;
        if (candidate == current) continue;
        const float extra = term(candidate);
        const float d = window.distance(query.data(), candidate, best - extra, columns.data(), mask, scale);
        if (d + extra < best) best = d + extra, bestDistance = d, bestPixel = candidate;
      }
      changed[std::size_t(a)] = bestPixel != current;
      matches.pixel[std::size_t(a)] = bestPixel;
      matches.distance[std::size_t(a)] = bestDistance;
    }
  });
  std::int64_t total = 0;
  for (std::uint8_t c : changed) total += c;
  return total;
}

// The color constraint E_c of frame-coherent animation (Kwatra et al. 2005 §4, Han et al.
// Table 1): every sample's color should stay near u, the previous frame carried along the flow.
struct ColorConstraint {
  std::span<const float> colors;  // u: window.channels() floats per sample
  // lambda: the constraint's weight against all of a sample's votes together (1 = as much as
  // every covering match; 0 = none).
  float weight = 0;
};

// Discrete E-step (window.norm must be Euclidean): each sample takes, among the exemplar pixels
// its covering matches vote for, their similarity sets and its current source, the one with the
// least weighted sum of color distances to the votes, plus lambda W |x - u| with a `constraint`
// (W the sample's total vote weight). A vote weighs (d_p + 0.01)^-voteExponent, d_p its match's
// mean color distance per pixel (Kwatra's robust weights; 0 = equal votes). Returns the new
// sources.
template <class Domain>
std::vector<std::int32_t> updateDiscrete(const Domain& domain, const ExemplarWindow& window,
                                         const ExemplarAnalysis& analysis, int level,
                                         std::span<const std::int32_t> sources, float voteExponent,
                                         const Matches& matches, const ColorConstraint* constraint = nullptr) {
  using namespace discrete;
  TS_CHECK(window.norm == PixelNorm::Euclidean);
  TS_CHECK(std::int64_t(sources.size()) == domain.sampleCount());
  const int k = analysis.similarCount, channels = window.channels();
  std::vector<std::int32_t> next(sources.size());
  // Each match's vote weight, once.
  std::vector<float> voteWeight(matches.distance.size(), 1.0f);
  if (voteExponent != 0) {
    const float perPixel = 1.0f / float(window.size * window.size);
    for (std::size_t a = 0; a < voteWeight.size(); ++a)
      voteWeight[a] = std::pow(matches.distance[a] * perPixel + kVoteDistanceFloor, -voteExponent);
  }
  parallelForChunks(0, domain.sampleCount(), domain.sampleChunk(), [&](std::int64_t begin, std::int64_t end) {
    std::vector<std::pair<std::int32_t, float>> votes, tally;  // (vote, weight); distinct votes, summed weights
    std::vector<float> voteColors;                             // the tally's colors, in its order
    for (std::int64_t sample = begin; sample < end; ++sample) {
      votes.clear();
      std::int32_t best = sources[std::size_t(sample)];
      bool unanimous = true;  // every vote is for the current source
      domain.forEachCovering(sample, [&](std::int64_t a, auto dx, auto dy) {
        const std::int32_t match = matches.pixel[std::size_t(a)];
        if (match < 0) return;
        votes.push_back({window.shifted(match, dx, dy), voteWeight[std::size_t(a)]});
        unanimous = unanimous && votes.back().first == best;
      });
      // No votes, or a cost of 0 that nothing beats (without a constraint to move it).
      if (votes.empty() || (unanimous && !(constraint && constraint->weight > 0))) {
        next[std::size_t(sample)] = best;
        continue;
      }
      std::sort(votes.begin(), votes.end());
      tally.clear();
      for (const auto& [vote, weight] : votes)
        if (!tally.empty() && tally.back().first == vote)
          tally.back().second += weight;
        else
          tally.push_back({vote, weight});
      // This sample's share of the (weighted) energy: sum over covering matches of w_p |x - z_p(q)|,
      // plus lambda W |x - u|.
      float constraintWeight = 0;
      const float* target = nullptr;
      if (constraint && constraint->weight > 0) {
        for (const auto& entry : tally) constraintWeight += entry.second;
        constraintWeight *= constraint->weight;
        target = constraint->colors.data() + std::size_t(sample) * std::size_t(channels);
      }
      // Weighted votes concentrate on the few well-aligned matches: the rest hardly move the
      // cost, and the candidates come from the strongest votes only.
      float strongest = 0;
      for (const auto& entry : tally) strongest = std::max(strongest, entry.second);
      std::erase_if(tally, [&](const auto& entry) { return entry.second < kNegligibleVote * strongest; });
      std::sort(tally.begin(), tally.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second > b.second : a.first < b.first;
      });
      voteColors.clear();
      for (const auto& entry : tally) {
        const float* color = window.exemplarColor(entry.first);
        voteColors.insert(voteColors.end(), color, color + channels);
      }
      // The cost, abandoned (returning a value >= bound) once its partial sum reaches `bound`:
      // every term is non-negative and the strongest votes come first, so most candidates stop
      // after a few votes.
      auto cost = [&](std::int32_t candidate, float bound) {
        const float* color = window.exemplarColor(candidate);
        float sum = target ? constraintWeight * std::sqrt(squaredDistance(color, target, channels)) : 0.0f;
        const float* voteColor = voteColors.data();
        for (std::size_t t = 0; t < tally.size() && sum < bound; ++t, voteColor += channels)
          sum += tally[t].second * std::sqrt(squaredDistance(color, voteColor, channels));
        return sum;
      };
      const float infinity = std::numeric_limits<float>::infinity();
      float bestCost = cost(best, infinity);
      // Nothing beats a cost of 0 (ties keep the current source): a sample every vote and the
      // constraint agree on needs no search.
      const std::size_t proposing = bestCost == 0      ? 0
                                    : voteExponent > 0 ? std::min(tally.size(), kProposingVotes)
                                                       : tally.size();
      for (std::size_t t = 0; t < proposing; ++t) {
        const std::int32_t* similar = analysis.similarAt(level, tally[t].first);
        for (int i = 0; i < k; ++i) {
          if (similar[i] == best) continue;
          const float c = cost(similar[i], bestCost);
          if (c < bestCost) bestCost = c, best = similar[i];
        }
      }
      next[std::size_t(sample)] = best;
    }
  });
  return next;
}

// E+M iterations at one level and neighborhood size (Table 1): the matches of the output as it
// comes in, then up to `maxIterations` E+M steps, until no match changes. match() runs an M-step
// and returns how many matches changed, update() an E-step, measure() the energy of the output
// against the matches its E-step used; record(iteration, changed, seconds) logs each step. After
// the last allowed E-step, measure() stands in for match(): those matches would guide no further
// E-step, and a search for them took a third of the M-steps' time; the step is logged with the
// changes measure() returns (none when it returns nothing). Progress advances maxIterations + 1 units in all.
template <class Match, class Update, class Measure, class Record>
void iterateExpectationMaximization(int maxIterations, Match&& match, Update&& update, Measure&& measure,
                                    Record&& record, Progress& progress) {
  using Clock = std::chrono::steady_clock;
  Clock::time_point start = Clock::now();
  const std::int64_t first = match();
  record(0, first, secondsSince(start));
  progress.advance(1);
  int iteration = 1;
  for (; iteration <= maxIterations; ++iteration) {
    start = Clock::now();
    update();
    std::int64_t changed = 0;
    if (iteration < maxIterations)
      changed = match();
    else if constexpr (std::is_void_v<decltype(measure())>)
      measure();
    else
      changed = measure();  // a solver whose last search is its measure
    record(iteration, changed, secondsSince(start));
    progress.advance(1);
    if (changed == 0) break;
  }
  if (iteration < maxIterations) progress.advance(maxIterations - iteration);
}

// The discrete solver at one level and neighborhood size `options.neighborhoodSizes[scale]` on
// any domain: M-steps with the usage term and random candidates of `options`, E-steps with its
// vote exponent, PCA from analyses[scale], similarity sets from analyses.back(). A domain with
// moveLattice(key, matches) (an image grid) moves its active neighborhoods before every M-step
// when options.movingLattice is set. Updates `sources` and appends one OptimizationIteration
// per M-step to `history`.
template <class Domain>
void optimizeDiscreteScale(Domain& domain, std::span<const ExemplarAnalysis> analyses, int level, std::size_t scale,
                           const TextureOptimizationOptions& options, std::vector<std::int32_t>& sources,
                           std::vector<OptimizationIteration>& history, Progress& progress) {
  const int size = options.neighborhoodSizes[scale];
  const ExemplarWindow window(analyses[scale], level, size, PixelNorm::Euclidean);
  const ExemplarAnalysis& similarity = analyses.back();
  Matches matches(domain.activeCount());
  int matchCount = 0;
  auto match = [&] {
    const std::uint64_t key =
        hashKey(options.seed, std::uint64_t(level), std::uint64_t(scale), std::uint64_t(matchCount++));
    if constexpr (requires { domain.moveLattice(key, matches); })
      if (options.movingLattice) domain.moveLattice(mix64(key ^ 0x1a77), matches);
    const UsageMap usage(window, sources, options.coverageWeight);
    const DiscreteStepOptions step{usage.active() ? &usage : nullptr, options.randomCandidates, key};
    return matchDiscrete(domain, window, analyses[scale].levels[std::size_t(level)], similarity, level, sources, step,
                         matches);
  };
  auto update = [&] {
    sources = updateDiscrete(domain, window, similarity, level, sources, options.voteExponent, matches);
  };
  auto measure = [&] {
    measureDiscrete(domain, window, analyses[scale].levels[std::size_t(level)].pca, sources, matches);
  };
  auto record = [&](int iteration, std::int64_t changed, double seconds) {
    history.push_back(
        {level, size, iteration, normalizedEnergy(matches, size), changed, domain.activeCount(), seconds});
  };
  iterateExpectationMaximization(options.maxIterations, match, update, measure, record, progress);
}

}  // namespace texsynth::detail
