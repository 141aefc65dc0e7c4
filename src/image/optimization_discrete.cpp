// The discrete (k-coherence) E- and M-steps of texture optimization (Han et al.).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "optimization_steps.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"

namespace texsynth::detail {
namespace {

constexpr std::int64_t kActiveRowChunk = 2;
// Candidates measured in full space after the PCA ranking: PCA-20 alone picks a worse match
// (pink_marble 256^2: PCA alone 0.00051, shortlist 8 0.00032, 32 0.00028 = all candidates' 0.00028
// at half the time of measuring all).
// With the usage term and random candidates 8 keep the same quality (GIMP rock and leaves at
// 512^2: coherence within 1%) at 0.78x the time of 32.
constexpr std::size_t kFullSpaceShortlist = 8;
// The vote weights' floor, in mean color distance per pixel: a perfect match does not outvote
// every other one infinitely.
constexpr float kVoteDistanceFloor = 0.01f;
// E-step with weighted votes: votes below this share of the strongest are left out of the
// cost, and only the strongest few votes propose candidates (their similarity sets).
constexpr float kNegligibleVote = 1e-3f;
constexpr std::size_t kProposingVotes = 4;

std::int32_t sourcePixel(const OptimizationGrid& grid, const SourceCoordinates& coords, int x, int y) {
  const std::int32_t* s = coords.at(x, y);
  return s[1] * grid.exemplarWidth + s[0];
}

void sortUnique(std::vector<std::int32_t>& values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
}

// v mod n for v in (-n, 2n): one conditional step instead of a division.
int wrapOnce(int v, int n) {
  return v < 0 ? v + n : (v >= n ? v - n : v);
}

float squaredDistance(const float* a, const float* b, int channels) {
  float sum = 0;
  for (int i = 0; i < channels; ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return sum;
}

}  // namespace

Image colorsAt(const OptimizationGrid& grid, const SourceCoordinates& coords) {
  Image out(coords.width, coords.height, grid.channels());
  parallelForChunks(0, coords.height, 8, [&](std::int64_t begin, std::int64_t end) {
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < coords.width; ++x) {
        const float* color = grid.exemplarColor(sourcePixel(grid, coords, x, y));
        std::copy(color, color + grid.channels(), out.pixel(x, y));
      }
  });
  return out;
}

std::int64_t matchDiscrete(const OptimizationGrid& grid, const ExemplarLevel& pcaLevel,
                           const ExemplarAnalysis& similarity, int level, const SourceCoordinates& coords,
                           const DiscreteStepOptions& step, Matches& matches) {
  const PcaBasis& pca = pcaLevel.pca;
  TS_CHECK(pca.inputDimension == grid.dimension());
  // Proposal offsets d h wrap by one conditional step, unless the neighborhood outreaches a tiny
  // exemplar.
  const bool wrapsOnce = grid.radius * grid.spacing() < std::min(grid.exemplarWidth, grid.exemplarHeight);
  auto wrap = [wrapsOnce](int v, int n) { return wrapsOnce ? wrapOnce(v, n) : wrapIndex(v, n); };
  const int k = similarity.similarCount, dimensions = pca.outputDimension;
  std::vector<std::int64_t> changedPerRow(std::size_t(grid.activeHeight()), 0);
  parallelForChunks(0, grid.activeHeight(), kActiveRowChunk, [&](std::int64_t begin, std::int64_t end) {
    std::vector<float> query(static_cast<std::size_t>(grid.dimension()));
    std::vector<float> projected(static_cast<std::size_t>(dimensions));
    std::vector<int> columns(std::size_t(grid.size));
    std::vector<std::int32_t> proposals, candidates;
    std::vector<std::pair<float, std::int32_t>> ranked;
    auto colorAt = [&](int x, int y) { return grid.exemplarColor(sourcePixel(grid, coords, x, y)); };
    for (int ay = int(begin); ay < int(end); ++ay)
      for (int ax = 0; ax < grid.activeWidth(); ++ax) {
        const int cx = ax * grid.stride, cy = ay * grid.stride;
        grid.gatherOutput(cx, cy, colorAt, query.data());
        pca.project(query.data(), projected.data());
        // Each pixel q = c + d proposes the exemplar neighborhood centred at S(q) - h d; coherent
        // runs propose the same one, so repeats of the previous proposal are skipped early.
        proposals.clear();
        const int h = grid.spacing(), ew = grid.exemplarWidth, eh = grid.exemplarHeight;
        for (int dy = -grid.radius; dy <= grid.radius; ++dy) {
          const std::int32_t* row = coords.at(0, wrapIndex(cy + dy, grid.height));
          for (int dx = -grid.radius; dx <= grid.radius; ++dx) {
            const std::int32_t* s = row + 2 * std::size_t(wrapIndex(cx + dx, grid.width));
            const std::int32_t proposal = wrap(s[1] - dy * h, eh) * ew + wrap(s[0] - dx * h, ew);
            if (proposals.empty() || proposals.back() != proposal) proposals.push_back(proposal);
          }
        }
        sortUnique(proposals);
        candidates.clear();
        for (std::int32_t u : proposals) {
          const std::int32_t* similar = similarity.similarAt(level, u);
          for (int i = 0; i < k; ++i) candidates.push_back(grid.allowedCentre(similar[i]));
        }
        // Random candidates reach exemplar parts that no coherent candidate proposes (after the
        // start dropped them), as PatchMatch's random search does.
        const std::int64_t a = std::int64_t(ay) * grid.activeWidth() + ax;
        for (int r = 0; r < step.randomCandidates; ++r) {
          const std::uint64_t key = hashKey(step.randomKey, std::uint64_t(a), std::uint64_t(r));
          const auto x = std::int32_t(uniformBelow(key, std::uint32_t(grid.exemplarWidth)));
          const auto y = std::int32_t(uniformBelow(mix64(key), std::uint32_t(grid.exemplarHeight)));
          candidates.push_back(grid.allowedCentre(y * grid.exemplarWidth + x));
        }
        sortUnique(candidates);
        // Rank in PCA space (L&H 2005), then measure the few best in full space, with the usage
        // term, against the current match, which stays on ties.
        ranked.clear();
        for (std::int32_t c : candidates)
          ranked.push_back({squaredDistance(projected.data(), pcaLevel.projectedAt(c), dimensions), c});
        const std::size_t shortlist = std::min<std::size_t>(ranked.size(), kFullSpaceShortlist);
        std::partial_sort(ranked.begin(), ranked.begin() + std::ptrdiff_t(shortlist), ranked.end());
        const std::int32_t current = matches.pixel[a];
        // The usage term counts once per neighborhood pixel; the energy reported is the plain
        // distance.
        const float infinity = std::numeric_limits<float>::infinity();
        const float pixels = float(grid.size * grid.size);
        auto term = [&](std::int32_t pixel) { return step.usage ? pixels * step.usage->cost(pixel) : 0.0f; };
        float bestDistance = current >= 0 ? grid.distance(query.data(), current, infinity, columns.data()) : infinity;
        float best = current >= 0 ? bestDistance + term(current) : infinity;
        std::int32_t bestPixel = current;
        for (std::size_t i = 0; i < shortlist; ++i) {
          const std::int32_t candidate = ranked[i].second;
          if (candidate == current) continue;
          const float extra = term(candidate);
          const float d = grid.distance(query.data(), candidate, best - extra, columns.data());
          if (d + extra < best) best = d + extra, bestDistance = d, bestPixel = candidate;
        }
        if (bestPixel != current) ++changedPerRow[ay];
        matches.pixel[a] = bestPixel;
        matches.distance[a] = bestDistance;
      }
  });
  std::int64_t changed = 0;
  for (std::int64_t c : changedPerRow) changed += c;
  return changed;
}

SourceCoordinates updateDiscrete(const OptimizationGrid& grid, const ExemplarAnalysis& analysis, int level,
                                 const SourceCoordinates& coords, float voteExponent, const Matches& matches) {
  TS_CHECK(grid.norm == PixelNorm::Euclidean);
  const int k = analysis.similarCount, channels = grid.channels();
  SourceCoordinates next(0, 0, coords.width, coords.height);
  // Each match's vote weight, once.
  std::vector<float> voteWeight(matches.distance.size(), 1.0f);
  if (voteExponent != 0) {
    const float perPixel = 1.0f / float(grid.size * grid.size);
    for (std::size_t a = 0; a < voteWeight.size(); ++a)
      voteWeight[a] = std::pow(matches.distance[a] * perPixel + kVoteDistanceFloor, -voteExponent);
  }
  parallelForChunks(0, grid.height, 8, [&](std::int64_t begin, std::int64_t end) {
    std::vector<std::pair<std::int32_t, float>> votes, tally;  // (vote, weight); distinct votes, summed weights
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < grid.width; ++x) {
        votes.clear();
        grid.forEachCovering(x, y, [&](std::int64_t a, int dx, int dy) {
          votes.push_back({grid.shifted(matches.pixel[a], dx, dy), voteWeight[std::size_t(a)]});
        });
        std::sort(votes.begin(), votes.end());
        tally.clear();
        for (const auto& [vote, weight] : votes)
          if (!tally.empty() && tally.back().first == vote)
            tally.back().second += weight;
          else
            tally.push_back({vote, weight});
        // This pixel's share of the (weighted) energy: sum over covering matches of w_p |x - z_p(q)|.
        auto cost = [&](std::int32_t candidate) {
          const float* color = grid.exemplarColor(candidate);
          float sum = 0;
          for (const auto& [vote, weight] : tally)
            sum += weight * std::sqrt(squaredDistance(color, grid.exemplarColor(vote), channels));
          return sum;
        };
        // Weighted votes concentrate on the few well-aligned matches: the rest hardly move the
        // cost, and the candidates come from the strongest votes only.
        float strongest = 0;
        for (const auto& entry : tally) strongest = std::max(strongest, entry.second);
        std::erase_if(tally, [&](const auto& entry) { return entry.second < kNegligibleVote * strongest; });
        std::sort(tally.begin(), tally.end(), [](const auto& a, const auto& b) {
          return a.second != b.second ? a.second > b.second : a.first < b.first;
        });
        std::int32_t best = sourcePixel(grid, coords, x, y);
        float bestCost = cost(best);
        const std::size_t proposing = voteExponent > 0 ? std::min(tally.size(), kProposingVotes) : tally.size();
        for (std::size_t t = 0; t < proposing; ++t) {
          const std::int32_t* similar = analysis.similarAt(level, tally[t].first);
          for (int i = 0; i < k; ++i) {
            if (similar[i] == best) continue;
            const float c = cost(similar[i]);
            if (c < bestCost) bestCost = c, best = similar[i];
          }
        }
        std::int32_t* target = next.at(x, y);
        target[0] = best % grid.exemplarWidth;
        target[1] = best / grid.exemplarWidth;
      }
  });
  return next;
}

}  // namespace texsynth::detail
