// The candidate-triple search. Each pixel has a u-row and a v-column crossbar vector (N samples
// `spacing` apart). Crossbar j of a triple (t_0, t_1, t_2) = (xy, yz, zx) joins the v-column of
// t_j with the u-row of t_{j+1} (j = 0: y line, 1: z line, 2: x line). For an anchor t_P both
// partners are shortlisted by KD-trees (L2, PCA space) on the one crossbar they share with t_P,
// re-ranked by exact L1, paired and scored with the third crossbar; the best 2 * count are
// kept, refined, and a second pass applies the spatial-consistency rule.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <nanoflann.hpp>
#include <ranges>
#include <tuple>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"
#include "texsynth/exemplar/candidate_triples.h"

namespace texsynth {
namespace {

constexpr std::int64_t kChunk = 64;         // pixels per parallel work item (fixed: results never depend on it)
constexpr float kConsistencySlack = 1e-6f;  // absolute slack of the consistency rule (exact matches at 0)
constexpr int kSearchDimensions = 8;        // PCA dimensions the KD-trees search in (raw: N*C = 27 at N = 9)
constexpr float kSearchEpsilon = 2.0f;      // approximate KD search (prunes within 1 + eps); exact L1 re-ranks
constexpr int kRefineWidth = 8;             // partners tried per joint re-search (TripleSearch::refine)
constexpr int kJointDimensions = 4;         // leading PCA dimensions per crossbar in the joint index (8-D)

struct Dataset {
  const float* data = nullptr;
  std::size_t count = 0;
  int dimension = 0;
  std::size_t kdtree_get_point_count() const { return count; }
  float kdtree_get_pt(std::uint32_t i, std::size_t d) const { return data[std::size_t(i) * dimension + d]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using Metric = nanoflann::L2_Adaptor<float, Dataset, float, std::uint32_t>;
using KdTree = nanoflann::KDTreeSingleIndexAdaptor<Metric, Dataset, -1, std::uint32_t>;

// The u-row and v-column through (x, y): N samples `spacing` apart, centred, toroidal.
void gatherCrossbars(const Image& image, int x, int y, int spacing, int n, float* row, float* column) {
  const int w = image.width, h = image.height, c = image.channels;
  for (int k = 0; k < n; ++k) {
    const std::int64_t offset = std::int64_t(k - n / 2) * spacing;
    std::copy_n(image.pixel(wrapIndex(x + offset, w), y), c, row + k * c);
    std::copy_n(image.pixel(x, wrapIndex(y + offset, h)), c, column + k * c);
  }
}

// u-row and v-column vectors of one image, their PCA projections, and a KD-tree over each.
struct Crossbars {
  int dimension = 0, reduced = 0, jointHalf = 0;
  std::vector<float> rows, columns, rowsReduced, columnsReduced;
  std::vector<float> joint;  // per pixel [reduced row, reduced column]: both crossbars of a partner at once
  Dataset rowData, columnData, jointData;
  std::unique_ptr<KdTree> rowTree, columnTree, jointTree;

  Crossbars(const Image& image, int spacing, int n) : dimension(n * image.channels) {
    const std::size_t pixels = image.pixelCount();
    rows.resize(pixels * dimension);
    columns.resize(pixels * dimension);
    parallelForChunks(0, std::int64_t(pixels), 256, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t p = begin; p < end; ++p)
        gatherCrossbars(image, int(p % image.width), int(p / image.width), spacing, n, &rows[p * dimension],
                        &columns[p * dimension]);
    });
  }
  const float* row(std::int32_t p) const { return &rows[std::size_t(p) * dimension]; }
  const float* column(std::int32_t p) const { return &columns[std::size_t(p) * dimension]; }
  const float* rowReduced(std::int32_t p) const { return &rowsReduced[std::size_t(p) * reduced]; }
  const float* columnReduced(std::int32_t p) const { return &columnsReduced[std::size_t(p) * reduced]; }

  // Projects both vector sets on the shared basis and indexes them.
  void index(const Eigen::VectorXd& mean, const Eigen::MatrixXf& basis) {
    reduced = int(basis.cols());
    const std::int64_t pixels = std::int64_t(rows.size()) / dimension;
    rowsReduced.resize(std::size_t(pixels) * reduced);
    columnsReduced.resize(std::size_t(pixels) * reduced);
    const Eigen::VectorXf center = mean.cast<float>();
    parallelForChunks(0, pixels, 1024, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t p = begin; p < end; ++p) {
        using Map = Eigen::Map<const Eigen::VectorXf>;
        Eigen::Map<Eigen::VectorXf>(&rowsReduced[p * reduced], reduced) =
            basis.transpose() * (Map(row(std::int32_t(p)), dimension) - center);
        Eigen::Map<Eigen::VectorXf>(&columnsReduced[p * reduced], reduced) =
            basis.transpose() * (Map(column(std::int32_t(p)), dimension) - center);
      }
    });
    jointHalf = std::min(reduced, kJointDimensions);
    joint.resize(std::size_t(pixels) * 2 * jointHalf);
    for (std::int64_t p = 0; p < pixels; ++p)
      for (int i = 0; i < 2 * jointHalf; ++i)
        joint[p * 2 * jointHalf + i] =
            i < jointHalf ? rowsReduced[p * reduced + i] : columnsReduced[p * reduced + i - jointHalf];
    rowData = {rowsReduced.data(), std::size_t(pixels), reduced};
    columnData = {columnsReduced.data(), std::size_t(pixels), reduced};
    jointData = {joint.data(), std::size_t(pixels), 2 * jointHalf};
    const nanoflann::KDTreeSingleIndexAdaptorParams params(16);
    rowTree = std::make_unique<KdTree>(reduced, rowData, params);
    columnTree = std::make_unique<KdTree>(reduced, columnData, params);
    jointTree = std::make_unique<KdTree>(2 * jointHalf, jointData, params);
  }
};

// The principal axes of every row and column vector of the distinct images, so distances
// between rows of one image and columns of another survive the projection. Accumulated in
// double, single-threaded, in pixel order: the basis never depends on the thread count.
void fitBasis(const std::vector<Crossbars*>& sets, int dimensions, Eigen::VectorXd& mean, Eigen::MatrixXf& basis) {
  const int dim = sets[0]->dimension;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(dim);
  Eigen::MatrixXd products = Eigen::MatrixXd::Zero(dim, dim);
  double count = 0;
  for (const Crossbars* set : sets)
    for (const std::vector<float>* vectors : {&set->rows, &set->columns})
      for (std::size_t i = 0; i < vectors->size(); i += dim) {
        const Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXf>(&(*vectors)[i], dim).cast<double>();
        sum += v;
        products.selfadjointView<Eigen::Upper>().rankUpdate(v);
        count += 1;
      }
  mean = sum / count;
  Eigen::MatrixXd covariance = products.selfadjointView<Eigen::Upper>();
  covariance = covariance / count - mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);
  const int kept = std::min(dimensions, dim);
  basis.resize(dim, kept);
  for (int i = 0; i < kept; ++i) {
    Eigen::VectorXd axis = solver.eigenvectors().col(dim - 1 - i);  // descending variance
    Eigen::Index largest;
    axis.cwiseAbs().maxCoeff(&largest);
    if (axis[largest] < 0) axis = -axis;  // fixed sign: reproducible trees
    basis.col(i) = axis.cast<float>();
  }
}

// L1 distance in 8 interleaved partial sums added in a fixed tree: vectorizes, and is the one
// definition of a crossbar sum (crossbarError below uses it too, so stored errors are exact).
float l1(const float* a, const float* b, int dimension) {
  float acc[8] = {};
  int i = 0;
  for (; i + 8 <= dimension; i += 8)
    for (int j = 0; j < 8; ++j) acc[j] += std::abs(a[i + j] - b[i + j]);
  for (int j = 0; i < dimension; ++i, ++j) acc[j] += std::abs(a[i] - b[i]);
  return ((acc[0] + acc[4]) + (acc[1] + acc[5])) + ((acc[2] + acc[6]) + (acc[3] + acc[7]));
}

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
std::vector<std::uint32_t> nearest(const KdTree& tree, const float* query, int k) {
  std::vector<std::uint32_t> indices(k);
  std::vector<float> dists(k);
  nanoflann::KNNResultSet<float, std::uint32_t> result(k);
  result.init(indices.data(), dists.data());
  tree.findNeighbors(result, query, nanoflann::SearchParams(0, kSearchEpsilon));
  indices.resize(result.size());
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
      if (!bars_[p]) bars_[p] = std::make_shared<Crossbars>(*images[p], spacing, options.neighborhoodSize);
    }
    std::vector<Crossbars*> distinct;
    for (int p = 0; p < 3; ++p)
      if (std::find(distinct.begin(), distinct.end(), bars_[p].get()) == distinct.end())
        distinct.push_back(bars_[p].get());
    Eigen::VectorXd mean;
    Eigen::MatrixXf basis;
    fitBasis(distinct, kSearchDimensions, mean, basis);
    for (Crossbars* set : distinct) set->index(mean, basis);
  }
  int pool() const { return pool_; }

  // The best pool() triples containing `pixel` as their `plane` coordinate, ascending.
  void search(int plane, std::int32_t pixel, std::vector<Partner>& next, std::vector<Partner>& prev,
              std::vector<Entry>& best) const {
    const int q = (plane + 1) % 3, s = (plane + 2) % 3;
    const Crossbars &self = *bars_[plane], &nextBars = *bars_[q], &prevBars = *bars_[s];
    const int dim = self.dimension;
    // Plane q's u-row meets our v-column (crossbar `plane`); plane s's v-column meets our u-row (crossbar s).
    shortlist(*nextBars.rowTree, nextBars.rows, self.columnReduced(pixel), self.column(pixel), dim, next);
    shortlist(*prevBars.columnTree, prevBars.columns, self.rowReduced(pixel), self.row(pixel), dim, prev);
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
        d[q] = l1(nextBars.column(pq.pixel), prevBars.row(ps.pixel), dim);
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
      d[j] = l1(bars_[j]->column(p[j]), bars_[(j + 1) % 3]->row(p[(j + 1) % 3]), bars_[j]->dimension);
    return combine(d);
  }

 private:
  // The k nearest by L2 in PCA space, re-ranked by the exact L1 crossbar sum.
  void shortlist(const KdTree& tree, const std::vector<float>& vectors, const float* reducedQuery, const float* query,
                 int dim, std::vector<Partner>& out) const {
    out.clear();
    for (std::uint32_t i : nearest(tree, reducedQuery, width_))
      out.push_back({l1(query, &vectors[std::size_t(i) * dim], dim), std::int32_t(i)});
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
        const Crossbars &before = *bars_[(j + 2) % 3], &after = *bars_[(j + 1) % 3], &self = *bars_[j];
        const int r = self.jointHalf;
        query.resize(2 * r);
        std::copy_n(before.columnReduced(component(seed, (j + 2) % 3)), r, query.begin());
        std::copy_n(after.rowReduced(component(seed, (j + 1) % 3)), r, query.begin() + r);
        for (std::uint32_t i : nearest(*self.jointTree, query.data(), refineWidth_)) {
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
  std::shared_ptr<Crossbars> bars_[3];
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
  for (int j = 0; j < 3; ++j) d[j] = l1(&columns[j * dimension], &rows[(j + 1) % 3 * dimension], dimension);
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
