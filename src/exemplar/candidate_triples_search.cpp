// The candidate-triple search. Each pixel has a u-row and a v-column crossbar vector (N samples
// `spacing` apart). Crossbar j of a triple (t_0, t_1, t_2) = (xy, yz, zx) joins the v-column of
// t_j with the u-row of t_{j+1} (j = 0: y line, 1: z line, 2: x line). For an anchor t_P both
// partners are shortlisted by KD-trees (L2, PCA space) on the one crossbar they share with t_P,
// re-ranked by exact L1, paired and scored with the third crossbar; the best 2 * count are
// kept, refined, and a second pass applies the spatial-consistency rule.
#include <algorithm>
#include <cmath>
#include <memory>
#include <ranges>
#include <tuple>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"
#include "texsynth/exemplar/candidate_triples.h"
#include "texsynth/exemplar/crossbar_index.h"

namespace texsynth {
namespace {

constexpr std::int64_t kChunk = 64;         // pixels per parallel work item (fixed: results never depend on it)
constexpr float kConsistencySlack = 1e-6f;  // absolute slack of the consistency rule (exact matches at 0)
constexpr int kSearchDimensions = 8;        // PCA dimensions the KD-trees search in (raw: N*C = 27 at N = 9)
constexpr float kSearchEpsilon = 2.0f;      // approximate KD search (prunes within 1 + eps); exact L1 re-ranks
constexpr int kRefineWidth = 8;             // partners tried per joint re-search (TripleSearch::refine)
constexpr int kJointDimensions = 4;         // leading PCA dimensions per crossbar in the joint index (8-D)

// The canonical total of the three crossbar sums; every error goes through it so the same
// triple gets the same float from any anchor plane.
float combine(const float d[3]) {
  return (d[0] + d[1]) + d[2];
}

template <typename Triple>  // CoordinateTriple or const CoordinateTriple
auto& component(Triple& t, int plane) {
  return plane == 0 ? t.xy : plane == 1 ? t.yz : t.zx;
}

// The k nearest points of `tree` to `query` (approximate: see kSearchEpsilon), nearest first.
std::vector<std::uint32_t> nearest(const CrossbarIndex& index, CrossbarIndex::Tree tree, const float* query, int k) {
  std::vector<std::uint32_t> indices;
  index.nearest(tree, query, k, kSearchEpsilon, indices);
  return indices;
}

// A triple with its crossbar sum; ordered by sum, ties by coordinates (a canonical order).
struct Entry {
  float total;
  CoordinateTriple triple;
  bool operator<(const Entry& o) const {
    return std::tie(total, triple.xy, triple.yz, triple.zx) < std::tie(o.total, o.triple.xy, o.triple.yz, o.triple.zx);
  }
};

// A shortlisted partner with its exact crossbar L1 sum; ordered by sum, then pixel.
struct Partner {
  float distance;
  std::int32_t pixel;
  auto operator<=>(const Partner&) const = default;
};

class TripleSearch {
 public:
  TripleSearch(const Image* images[3], int spacing, const CandidateTripleOptions& options)
      : width_(int(std::min<std::int64_t>(options.searchWidth, images[0]->pixelCount()))),
        refineWidth_(int(std::min<std::int64_t>(kRefineWidth, images[0]->pixelCount()))),
        refine_(options.refineTriples),
        pool_(int(std::min<std::int64_t>(2LL * options.count, std::int64_t(width_) * width_))) {
    // One set of crossbars per distinct image (one exemplar usually serves all three planes).
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < p && !bars_[p]; ++q)
        if (images[q] == images[p] || images[q]->pixels == images[p]->pixels) bars_[p] = bars_[q];
      if (!bars_[p]) bars_[p] = std::make_shared<CrossbarIndex>(*images[p], spacing, options.neighborhoodSize);
    }
    std::vector<CrossbarIndex*> distinct;
    for (int p = 0; p < 3; ++p)
      if (std::find(distinct.begin(), distinct.end(), bars_[p].get()) == distinct.end())
        distinct.push_back(bars_[p].get());
    CrossbarIndex::indexTogether(distinct, kSearchDimensions, kJointDimensions);
  }
  int pool() const { return pool_; }

  // The best pool() triples containing `pixel` as their `plane` coordinate, ascending.
  void search(int plane, std::int32_t pixel, std::vector<Partner>& next, std::vector<Partner>& prev,
              std::vector<Entry>& best) const {
    const int q = (plane + 1) % 3, s = (plane + 2) % 3;
    const CrossbarIndex &self = *bars_[plane], &nextBars = *bars_[q], &prevBars = *bars_[s];
    const int dim = self.dimension();
    // Plane q's u-row meets our v-column (crossbar `plane`); plane s's v-column meets our u-row (crossbar s).
    shortlist(nextBars, CrossbarIndex::Tree::Rows, self.columnReduced(pixel), self.column(pixel), dim, next);
    shortlist(prevBars, CrossbarIndex::Tree::Columns, self.rowReduced(pixel), self.row(pixel), dim, prev);
    best.clear();
    float worst = std::numeric_limits<float>::infinity();
    float d[3];
    for (const Partner& ps : prev) {
      if (int(best.size()) == pool_ && ps.distance + next[0].distance > worst) break;
      for (const Partner& pq : next) {
        // Lower bound: the third crossbar only adds (float rounding is monotone).
        if (int(best.size()) == pool_ && ps.distance + pq.distance > worst) break;
        d[plane] = pq.distance;
        d[s] = ps.distance;
        // Third crossbar: plane q's v-column against plane s's u-row.
        d[q] = crossbarL1(nextBars.column(pq.pixel), prevBars.row(ps.pixel), dim);
        if (int(best.size()) == pool_ && combine(d) > worst) continue;
        Entry entry{combine(d), {}};
        component(entry.triple, plane) = pixel;
        component(entry.triple, q) = pq.pixel;
        component(entry.triple, s) = ps.pixel;
        insert(best, entry);
        if (int(best.size()) == pool_) worst = best.back().total;
      }
    }
    refine(plane, best);
  }

  // Total crossbar sum of any triple (same floats as search).
  float total(const CoordinateTriple& t) const {
    const std::int32_t p[3] = {t.xy, t.yz, t.zx};
    float d[3];
    for (int j = 0; j < 3; ++j)
      d[j] = crossbarL1(bars_[j]->column(p[j]), bars_[(j + 1) % 3]->row(p[(j + 1) % 3]), bars_[j]->dimension());
    return combine(d);
  }

 private:
  // The k nearest by L2 in PCA space, re-ranked by the exact L1 crossbar sum.
  void shortlist(const CrossbarIndex& bars, CrossbarIndex::Tree tree, const float* reducedQuery, const float* query,
                 int dim, std::vector<Partner>& out) const {
    out.clear();
    for (std::uint32_t i : nearest(bars, tree, reducedQuery, width_)) {
      const float* vector =
          tree == CrossbarIndex::Tree::Rows ? bars.row(std::int32_t(i)) : bars.column(std::int32_t(i));
      out.push_back({crossbarL1(query, vector, dim), std::int32_t(i)});
    }
    std::sort(out.begin(), out.end());
  }

  // The pairing shortlists each partner by one crossbar, blind to the third. For the best few
  // triples, re-search each partner with both of its crossbars at once (the joint index), the
  // other two coordinates fixed, and merge what is found.
  void refine(int plane, std::vector<Entry>& best) const {
    const std::vector<Entry> seeds(best.begin(), best.begin() + std::min(refine_, int(best.size())));
    std::vector<float> query;
    for (const CoordinateTriple& seed : seeds | std::views::transform(&Entry::triple))
      for (int j : {(plane + 1) % 3, (plane + 2) % 3}) {
        // t_j's u-row meets the v-column of t_{j-1}; its v-column meets the u-row of t_{j+1}.
        const CrossbarIndex &before = *bars_[(j + 2) % 3], &after = *bars_[(j + 1) % 3], &self = *bars_[j];
        const int r = self.jointHalf();
        query.resize(2 * r);
        std::copy_n(before.columnReduced(component(seed, (j + 2) % 3)), r, query.begin());
        std::copy_n(after.rowReduced(component(seed, (j + 1) % 3)), r, query.begin() + r);
        for (std::uint32_t i : nearest(self, CrossbarIndex::Tree::Joint, query.data(), refineWidth_)) {
          CoordinateTriple t = seed;
          component(t, j) = std::int32_t(i);
          const Entry entry{total(t), t};
          if (int(best.size()) == pool_ && !(entry < best.back())) continue;
          if (std::none_of(best.begin(), best.end(), [&](const Entry& e) { return e.triple == t; }))
            insert(best, entry);
        }
      }
  }

  void insert(std::vector<Entry>& best, const Entry& entry) const {
    if (int(best.size()) == pool_) {
      if (!(entry < best.back())) return;
      best.pop_back();
    }
    best.insert(std::upper_bound(best.begin(), best.end(), entry), entry);
  }

  int width_, refineWidth_, refine_, pool_;
  std::shared_ptr<CrossbarIndex> bars_[3];
};

// The four in-plane neighbour steps (+-u, +-v) of each plane as 3D offsets (eq. 4 axes):
// xy has (u, v) = (x, y), yz (y, z), zx (z, x).
constexpr int kSteps[3][4][3] = {{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}},
                                 {{0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
                                 {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}}};

}  // namespace

float crossbarError(const Image& xy, const Image& yz, const Image& zx, const CoordinateTriple& triple, int spacing,
                    int neighborhoodSize) {
  validateCandidateTripleInputs(xy, yz, zx, spacing, {.count = 1, .neighborhoodSize = neighborhoodSize});
  const Image* images[3] = {&xy, &yz, &zx};
  const std::int32_t pixels[3] = {triple.xy, triple.yz, triple.zx};
  for (std::int32_t p : pixels)
    if (p < 0 || std::int64_t(p) >= std::int64_t(xy.pixelCount()))
      throw ParameterError("triple", "pixel index " + std::to_string(p) + " out of range");
  const int dimension = neighborhoodSize * xy.channels;
  std::vector<float> rows(3 * dimension), columns(3 * dimension);
  for (int j = 0; j < 3; ++j)
    gatherCrossbars(*images[j], pixels[j] % xy.width, pixels[j] / xy.width, spacing, neighborhoodSize,
                    &rows[j * dimension], &columns[j * dimension]);
  float d[3];
  for (int j = 0; j < 3; ++j) d[j] = crossbarL1(&columns[j * dimension], &rows[(j + 1) % 3 * dimension], dimension);
  return combine(d) / float(3 * neighborhoodSize);
}

CandidateTriples computeCandidateTriples(const Image& xy, const Image& yz, const Image& zx, int spacing,
                                         const CandidateTripleOptions& options, Progress& progress) {
  validateCandidateTripleInputs(xy, yz, zx, spacing, options);
  const Image* images[3] = {&xy, &yz, &zx};
  const std::int64_t pixels = xy.pixelCount();
  const int count = options.count;
  const float samples = float(3 * options.neighborhoodSize);
  const TripleSearch search(images, spacing, options);  // crossbars, PCA, KD-trees: quick
  const int pool = search.pool();

  // Pass 1: the best `pool` triples of every pixel of every plane.
  std::vector<Entry> pools[3];
  progress.begin("candidate triples: pairing", 3 * pixels);
  for (int plane = 0; plane < 3; ++plane) {
    pools[plane].resize(std::size_t(pixels) * pool);
    parallelForChunks(0, pixels, kChunk, [&](std::int64_t begin, std::int64_t end) {
      std::vector<Partner> next, prev;
      std::vector<Entry> best;
      for (std::int64_t p = begin; p < end; ++p) {
        search.search(plane, std::int32_t(p), next, prev, best);
        TS_CHECK(int(best.size()) == pool);
        std::copy(best.begin(), best.end(), pools[plane].begin() + p * pool);
      }
      progress.advance(end - begin);
    });
  }
  progress.end();

  // Pass 2: keep the spatially consistent triples (see CandidateTripleOptions::consistencyFactor),
  // topped up with the best inconsistent ones, ascending.
  CandidateTriples result;
  result.width = xy.width, result.height = xy.height, result.count = count;
  result.neighborhoodSize = options.neighborhoodSize;
  progress.begin("candidate triples: consistency", 3 * pixels);
  for (int plane = 0; plane < 3; ++plane) {
    result.triples[plane].resize(std::size_t(pixels) * count);
    result.errors[plane].resize(std::size_t(pixels) * count);
    const std::vector<Entry>& all = pools[plane];
    parallelForChunks(0, pixels, kChunk, [&](std::int64_t begin, std::int64_t end) {
      std::vector<Entry> kept, rest;
      for (std::int64_t p = begin; p < end; ++p) {
        kept.clear();
        rest.clear();
        for (int i = 0; i < pool; ++i) {
          const Entry& entry = all[std::size_t(p) * pool + i];
          bool consistent = std::isinf(options.consistencyFactor);
          for (int e = 0; e < 4 && !consistent; ++e) {
            const int* d = kSteps[plane][e];
            const CoordinateTriple moved =
                offsetTriple(entry.triple, xy.width, xy.height, spacing * d[0], spacing * d[1], spacing * d[2]);
            const float neighbourBest = all[std::size_t(component(moved, plane)) * pool].total / samples;
            consistent = search.total(moved) / samples <= options.consistencyFactor * neighbourBest + kConsistencySlack;
          }
          (consistent ? kept : rest).push_back(entry);
          if (int(kept.size()) == count) break;
        }
        for (std::size_t i = 0; int(kept.size()) < count; ++i) kept.push_back(rest[i]);
        std::sort(kept.begin(), kept.end());
        for (int i = 0; i < count; ++i) {
          result.triples[plane][std::size_t(p) * count + i] = kept[i].triple;
          result.errors[plane][std::size_t(p) * count + i] = kept[i].total / samples;
        }
      }
      progress.advance(end - begin);
    });
  }
  progress.end();
  return result;
}

}  // namespace texsynth
