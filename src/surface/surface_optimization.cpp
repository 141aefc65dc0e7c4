// E+M on continuous coordinates (surface_optimization.h).
#include "texsynth/surface/surface_optimization.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "continuous_coordinates.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/random.h"
#include "texsynth/image/color_histogram_cost.h"
#include "texsynth/image/discrete_steps.h"
#include "texsynth/image/exemplar_usage.h"
#include "texsynth/image/exemplar_window.h"
#include "texsynth/surface/surface_parallel.h"

namespace texsynth {
namespace {

using surface_detail::atPixel;
using surface_detail::NearestLookup;
using surface_detail::nearestPixel;
using surface_detail::subPixel;
using surface_detail::wrapCoordinates;

// The M-step's shortlist: candidates ranked on every kSampleStride-th member, the best
// kShortlist measured on all.
constexpr std::size_t kShortlist = 8, kSampleStride = 7;

// E-step votes this close (exemplar pixels) support each other.
constexpr float kVoteClusterRadius = 1.0f;

struct ContinuousMatches {
  std::vector<Vec2f> position;
  std::vector<float> distance;
  std::vector<std::uint8_t> valid;
  explicit ContinuousMatches(std::size_t count) : position(count), distance(count, 0.0f), valid(count, 0) {}
};

float colorDistance(const float* a, const float* b, int channels) {
  float sum = 0;
  for (int i = 0; i < channels; ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum);
}

// Keeps the first coordinate of each nearest pixel, in pixel order.
void uniqueByPixel(std::vector<std::pair<std::int32_t, Vec2f>>& items) {
  std::stable_sort(items.begin(), items.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  items.erase(std::unique(items.begin(), items.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
              items.end());
}

class Solver {
 public:
  Solver(const SurfaceNeighborhoods& neighborhoods, const ExemplarAnalysis& analysis, int level, std::size_t scale,
         const TextureOptimizationOptions& options, float histogramWeight)
      : neighborhoods_(neighborhoods),
        analysis_(analysis),
        level_(level),
        scale_(scale),
        options_(options),
        histogramWeight_(histogramWeight),
        image_(analysis.levels[std::size_t(level)].image),
        window_(analysis, level, neighborhoods.size, detail::PixelNorm::Euclidean),
        h_(float(analysis.levels[std::size_t(level)].spacing)),
        channels_(image_.channels),
        lookup_{image_, channels_} {}

  // M-step: every active neighborhood's match becomes the best of its candidates (current match
  // first, kept on ties). Returns how many changed.
  std::int64_t match(std::span<const Vec2f> coordinates, ContinuousMatches& matches, int iteration) const {
    const int width = analysis_.width, height = analysis_.height, k = analysis_.similarCount;
    const std::vector<float> colors = colorsAtCoordinates(image_, coordinates);
    const std::vector<std::int32_t> sources = pixelsOfCoordinates(coordinates, width, height);
    const detail::UsageMap usage(window_, sources, options_.coverageWeight);
    // The histogram term per member in the distances' units (sigma, as the usage term's).
    const detail::ColorHistogramCost histogram =
        histogramWeight_ > 0 ? detail::ColorHistogramCost(image_, analysis_.colorChannels, sources)
                             : detail::ColorHistogramCost();
    const float histogramScale = histogram.active() ? histogramWeight_ * detail::colorSpread(window_) : 0.0f;
    const std::uint64_t randomKey =
        hashKey(options_.seed, std::uint64_t(level_), std::uint64_t(scale_), std::uint64_t(iteration) + 0x5e0c);
    std::vector<std::uint8_t> changed(matches.position.size(), 0);
    parallelForChunks(0, std::int64_t(neighborhoods_.activeCount()), 8, [&](std::int64_t begin, std::int64_t end) {
      std::vector<std::pair<std::int32_t, Vec2f>> proposals, candidates;
      std::vector<std::pair<float, std::pair<std::int32_t, Vec2f>>> ranked;
      for (std::int64_t a = begin; a < end; ++a) {
        const std::span<const NeighborhoodMember> members = neighborhoods_.membersOf(std::size_t(a));
        proposals.clear();
        for (const NeighborhoodMember& m : members) {
          const Vec2f& c = coordinates[std::size_t(m.vertex)];
          const Vec2f p = wrapCoordinates(Vec2f(c.x() - h_ * m.dx, c.y() - h_ * m.dy), width, height);
          const std::int32_t pixel = nearestPixel(p, width, height);
          if (proposals.empty() || proposals.back().first != pixel) proposals.push_back({pixel, p});
        }
        uniqueByPixel(proposals);
        candidates.clear();
        for (const auto& [pixel, p] : proposals) {
          const std::int32_t* similar = analysis_.similarAt(level_, pixel);
          for (int i = 0; i < k; ++i) addCandidate(candidates, atPixel(similar[i], width, subPixel(p)));
        }
        for (int r = 0; r < options_.randomCandidates; ++r) {
          const std::uint64_t key = hashKey(randomKey, std::uint64_t(a), std::uint64_t(r));
          addCandidate(candidates, Vec2f(float(uniformBelow(key, std::uint32_t(width))),
                                         float(uniformBelow(mix64(key), std::uint32_t(height)))));
        }
        uniqueByPixel(candidates);
        auto term = [&](const Vec2f& c) {
          if (!usage.active() && !histogram.active()) return 0.0f;
          const std::int32_t pixel = nearestPixel(c, width, height);
          const float cost = (usage.active() ? usage.cost(pixel) : 0.0f) +
                             (histogram.active() ? histogramScale * histogram.cost(pixel) : 0.0f);
          return float(members.size()) * cost;
        };
        // Sum of the members' color distances (every stride-th member) to the level at c + h d.
        auto distance = [&](const Vec2f& c, float sum, float bound, std::size_t stride) {
          for (std::size_t i = 0; i < members.size() && sum < bound; i += stride) {
            const NeighborhoodMember& m = members[i];
            sum += colorDistance(lookup_(c.x() + h_ * m.dx, c.y() + h_ * m.dy),
                                 colors.data() + std::size_t(m.vertex) * std::size_t(channels_), channels_);
          }
          return sum;
        };
        const float infinity = std::numeric_limits<float>::infinity();
        // Rank the candidates on every kSampleStride-th member, measure the best few on all (as
        // 2D ranks in PCA space).
        if (candidates.size() > kShortlist) {
          ranked.clear();
          for (const auto& candidate : candidates)
            ranked.push_back({distance(candidate.second, term(candidate.second), infinity, kSampleStride), candidate});
          std::partial_sort(ranked.begin(), ranked.begin() + std::ptrdiff_t(kShortlist), ranked.end(),
                            [](const auto& x, const auto& y) {
                              return x.first != y.first ? x.first < y.first : x.second.first < y.second.first;
                            });
          candidates.clear();
          for (std::size_t i = 0; i < kShortlist; ++i) candidates.push_back(ranked[i].second);
        }
        const bool had = matches.valid[std::size_t(a)] != 0;
        Vec2f bestPosition = matches.position[std::size_t(a)];
        float bestDistance = had ? distance(bestPosition, 0.0f, infinity, 1) : infinity;
        float best = had ? bestDistance + term(bestPosition) : infinity;
        const std::int32_t current = had ? nearestPixel(bestPosition, width, height) : -1;
        for (const auto& [pixel, c] : candidates) {
          if (pixel == current) continue;
          const float extra = term(c);
          const float d = distance(c, 0.0f, best - extra, 1);
          if (d + extra < best) best = d + extra, bestDistance = d, bestPosition = c;
        }
        changed[std::size_t(a)] = !had || nearestPixel(bestPosition, width, height) != current;
        matches.position[std::size_t(a)] = bestPosition;
        matches.distance[std::size_t(a)] = bestDistance;
        matches.valid[std::size_t(a)] = 1;
      }
    });
    std::int64_t total = 0;
    for (std::uint8_t c : changed) total += c;
    return total;
  }

  // E-step: every vertex takes its strongest vote: the vote with the most weight within
  // kVoteClusterRadius of it (ties keep the earlier covering match). The paper's E-step takes the
  // candidate nearest all votes at once; on a mesh, overlapping neighborhoods unfold a vertex at
  // offsets a fraction of a pixel apart, their votes disagree, and that compromise washes the
  // texture out (GIMP brick on the CGAL bunny: flatness 0.24-0.55 per level against -0.09 for the
  // start; with the strongest vote -0.03 to 0.03, and coherence 15% lower than the start's). The
  // same scatter splits one coherent patch's votes between neighbouring pixels, so votes are
  // counted together within a pixel of each other rather than per nearest pixel: a thin feature's
  // split votes no longer lose to the background's (refinement kept at every level, 8 CGAL/GIMP
  // pairs: histogram distance of brick 4.54 -> 3.41, bark 1.98 -> 1.49, leopard 1.31 -> 0.97, at
  // the same coherence).
  std::vector<Vec2f> update(std::span<const Vec2f> coordinates, const ContinuousMatches& matches) const {
    const int width = analysis_.width, height = analysis_.height;
    std::vector<float> voteWeight(matches.distance.size(), 1.0f);
    if (options_.voteExponent != 0)
      for (std::size_t a = 0; a < voteWeight.size(); ++a) {
        const float perMember =
            matches.distance[a] / float(std::max<std::size_t>(1, neighborhoods_.membersOf(a).size()));
        voteWeight[a] = std::pow(perMember + detail::discrete::kVoteDistanceFloor, -options_.voteExponent);
      }
    // Within the cluster radius on the exemplar torus.
    auto near = [&](const Vec2f& a, const Vec2f& b) {
      float dx = std::abs(a.x() - b.x()), dy = std::abs(a.y() - b.y());
      dx = std::min(dx, float(width) - dx), dy = std::min(dy, float(height) - dy);
      return dx * dx + dy * dy <= kVoteClusterRadius * kVoteClusterRadius;
    };
    std::vector<Vec2f> next(coordinates.begin(), coordinates.end());
    parallelForChunks(0, std::int64_t(coordinates.size()), 1024, [&](std::int64_t begin, std::int64_t end) {
      std::vector<std::pair<Vec2f, float>> votes;  // position, weight
      for (std::int64_t v = begin; v < end; ++v) {
        votes.clear();
        for (const CoveringEntry& entry : neighborhoods_.coveringOf(std::size_t(v))) {
          if (!matches.valid[std::size_t(entry.neighborhood)]) continue;
          const Vec2f& z = matches.position[std::size_t(entry.neighborhood)];
          votes.push_back({wrapCoordinates(Vec2f(z.x() + h_ * entry.dx, z.y() + h_ * entry.dy), width, height),
                           voteWeight[std::size_t(entry.neighborhood)]});
        }
        float strongest = -1;
        for (const auto& [position, weight] : votes) {
          float support = 0;
          for (const auto& [other, otherWeight] : votes)
            if (near(position, other)) support += otherWeight;
          if (support > strongest) strongest = support, next[std::size_t(v)] = position;
        }
      }
    });
    return next;
  }

  double energy(const ContinuousMatches& matches) const {
    double sum = 0;
    for (float d : matches.distance) sum += d;
    const int n = neighborhoods_.size;
    return matches.distance.empty() ? 0.0 : sum / (double(matches.distance.size()) * n * n);
  }

 private:
  void addCandidate(std::vector<std::pair<std::int32_t, Vec2f>>& candidates, const Vec2f& c) const {
    const Vec2f position = allowed(c);
    candidates.push_back({nearestPixel(position, analysis_.width, analysis_.height), position});
  }

  // The nearest allowed match position (inside the exemplar's bounded window, as 2D).
  Vec2f allowed(const Vec2f& c) const {
    const Vec2f w = wrapCoordinates(c, analysis_.width, analysis_.height);
    if (!window_.bounded) return w;
    return Vec2f(std::clamp(w.x(), float(window_.minX), float(window_.maxX)),
                 std::clamp(w.y(), float(window_.minY), float(window_.maxY)));
  }

  const SurfaceNeighborhoods& neighborhoods_;
  const ExemplarAnalysis& analysis_;
  int level_;
  std::size_t scale_;
  const TextureOptimizationOptions& options_;
  float histogramWeight_;
  const Image& image_;
  detail::ExemplarWindow window_;
  float h_;
  int channels_;
  NearestLookup lookup_;
};

}  // namespace

void optimizeSurfaceCoordinates(const SurfaceNeighborhoods& neighborhoods, const ExemplarAnalysis& analysis, int level,
                                std::size_t scale, const TextureOptimizationOptions& options,
                                std::vector<Vec2f>& coordinates, std::vector<OptimizationIteration>& history,
                                Progress& progress, float histogramWeight) {
  const Solver solver(neighborhoods, analysis, level, scale, options, histogramWeight);
  ContinuousMatches matches(neighborhoods.activeCount());
  int iteration = 0;
  auto match = [&] { return solver.match(coordinates, matches, iteration++); };
  auto update = [&] { coordinates = solver.update(coordinates, matches); };
  auto record = [&](int step, std::int64_t changed, double seconds) {
    history.push_back({level, neighborhoods.size, step, solver.energy(matches), changed,
                       std::int64_t(neighborhoods.activeCount()), seconds});
  };
  detail::iterateExpectationMaximization(options.maxIterations, match, update, match, record, progress);
}

}  // namespace texsynth
