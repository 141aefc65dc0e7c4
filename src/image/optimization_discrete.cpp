// The discrete (k-coherence) E- and M-steps of texture optimization (Han et al.).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "optimization_steps.h"
#include "texsynth/core/parallel.h"

namespace texsynth::detail {
namespace {

constexpr std::int64_t kActiveRowChunk = 2;
// Candidates measured in full space after the PCA ranking: PCA-20 alone picks a worse match
// (pink_marble 256^2: PCA alone 0.00051, shortlist 8 0.00032, 32 0.00028 = all candidates' 0.00028
// at half the time of measuring all).
constexpr std::size_t kFullSpaceShortlist = 32;

std::int32_t sourcePixel(const OptimizationGrid& grid, const SourceCoordinates& coords, int x, int y) {
  const std::int32_t* s = coords.at(x, y);
  return s[1] * grid.exemplarWidth + s[0];
}

void sortUnique(std::vector<std::int32_t>& values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
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
                           Matches& matches) {
  const PcaBasis& pca = pcaLevel.pca;
  TS_CHECK(pca.inputDimension == grid.dimension());
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
        for (int dy = -grid.radius; dy <= grid.radius; ++dy)
          for (int dx = -grid.radius; dx <= grid.radius; ++dx) {
            const std::int32_t source =
                sourcePixel(grid, coords, wrapIndex(cx + dx, grid.width), wrapIndex(cy + dy, grid.height));
            const std::int32_t proposal = grid.shifted(source, -dx, -dy);
            if (proposals.empty() || proposals.back() != proposal) proposals.push_back(proposal);
          }
        sortUnique(proposals);
        candidates.clear();
        for (std::int32_t u : proposals) {
          const std::int32_t* similar = similarity.similarAt(level, u);
          for (int i = 0; i < k; ++i) candidates.push_back(grid.allowedCentre(similar[i]));
        }
        sortUnique(candidates);
        // Rank in PCA space (L&H 2005), then measure the few best in full space against the
        // current match, which stays on ties: the energy never rises.
        ranked.clear();
        for (std::int32_t c : candidates)
          ranked.push_back({squaredDistance(projected.data(), pcaLevel.projectedAt(c), dimensions), c});
        const std::size_t shortlist = std::min<std::size_t>(ranked.size(), kFullSpaceShortlist);
        std::partial_sort(ranked.begin(), ranked.begin() + std::ptrdiff_t(shortlist), ranked.end());
        const std::int64_t a = std::int64_t(ay) * grid.activeWidth() + ax;
        const std::int32_t current = matches.pixel[a];
        const float infinity = std::numeric_limits<float>::infinity();
        float best = current >= 0 ? grid.distance(query.data(), current, infinity, columns.data()) : infinity;
        std::int32_t bestPixel = current;
        for (std::size_t i = 0; i < shortlist; ++i) {
          if (ranked[i].second == current) continue;
          const float d = grid.distance(query.data(), ranked[i].second, best, columns.data());
          if (d < best) best = d, bestPixel = ranked[i].second;
        }
        if (bestPixel != current) ++changedPerRow[ay];
        matches.pixel[a] = bestPixel;
        matches.distance[a] = best;
      }
  });
  std::int64_t changed = 0;
  for (std::int64_t c : changedPerRow) changed += c;
  return changed;
}

SourceCoordinates updateDiscrete(const OptimizationGrid& grid, const ExemplarAnalysis& analysis, int level,
                                 const SourceCoordinates& coords, const Matches& matches) {
  TS_CHECK(grid.norm == PixelNorm::Euclidean);
  const int k = analysis.similarCount, channels = grid.channels();
  SourceCoordinates next(0, 0, coords.width, coords.height);
  parallelForChunks(0, grid.height, 8, [&](std::int64_t begin, std::int64_t end) {
    std::vector<std::int32_t> votes;
    std::vector<std::pair<std::int32_t, int>> tally;  // distinct votes and how many cast them
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < grid.width; ++x) {
        votes.clear();
        grid.forEachCovering(
            x, y, [&](std::int64_t a, int dx, int dy) { votes.push_back(grid.shifted(matches.pixel[a], dx, dy)); });
        std::sort(votes.begin(), votes.end());
        tally.clear();
        for (std::int32_t v : votes)
          if (!tally.empty() && tally.back().first == v)
            ++tally.back().second;
          else
            tally.push_back({v, 1});
        // This pixel's share of the energy: sum over covering matches of |x - z_p(q)|.
        auto cost = [&](std::int32_t candidate) {
          const float* color = grid.exemplarColor(candidate);
          float sum = 0;
          for (const auto& [vote, count] : tally)
            sum += float(count) * std::sqrt(squaredDistance(color, grid.exemplarColor(vote), channels));
          return sum;
        };
        std::int32_t best = sourcePixel(grid, coords, x, y);
        float bestCost = cost(best);
        for (const auto& entry : tally) {
          const std::int32_t* similar = analysis.similarAt(level, entry.first);
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
