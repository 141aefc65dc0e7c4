// Crossbar vectors, their shared PCA basis and KD-trees (see crossbar_index.h).
#include "texsynth/exemplar/crossbar_index.h"

#include <Eigen/Dense>
#include <cmath>
#include <nanoflann.hpp>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"

namespace texsynth {
namespace {

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

}  // namespace

struct CrossbarIndex::Trees {
  Eigen::VectorXf center;
  Eigen::MatrixXf basis;
  Dataset rowData, columnData, jointData;
  std::unique_ptr<KdTree> rows, columns, joint;
};

CrossbarIndex::CrossbarIndex(const Image& image, int spacing, int size) : dimension_(size * image.channels) {
  if (image.empty() || size < 1 || spacing < 1)
    throw ParameterError("crossbars", "need an image, a size >= 1 and a spacing >= 1");
  const std::size_t pixels = image.pixelCount();
  rows_.resize(pixels * dimension_);
  columns_.resize(pixels * dimension_);
  parallelForChunks(0, std::int64_t(pixels), 256, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
      gatherCrossbars(image, int(p % image.width), int(p / image.width), spacing, size, &rows_[p * dimension_],
                      &columns_[p * dimension_]);
  });
}

CrossbarIndex::~CrossbarIndex() = default;

void CrossbarIndex::indexTogether(const std::vector<CrossbarIndex*>& indices, int dimensions, int jointHalf) {
  if (indices.empty()) throw ParameterError("crossbars", "nothing to index");
  const int dim = indices[0]->dimension_;
  for (const CrossbarIndex* index : indices)
    if (index->dimension_ != dim) throw ParameterError("crossbars", "indexed together with different sizes");
  // The principal axes of every row and column, accumulated in double, in pixel order.
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(dim);
  Eigen::MatrixXd products = Eigen::MatrixXd::Zero(dim, dim);
  double count = 0;
  for (const CrossbarIndex* index : indices)
    for (const std::vector<float>* vectors : {&index->rows_, &index->columns_})
      for (std::size_t i = 0; i < vectors->size(); i += dim) {
        const Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXf>(&(*vectors)[i], dim).cast<double>();
        sum += v;
        products.selfadjointView<Eigen::Upper>().rankUpdate(v);
        count += 1;
      }
  const Eigen::VectorXd mean = sum / count;
  Eigen::MatrixXd covariance = products.selfadjointView<Eigen::Upper>();
  covariance = covariance / count - mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);
  const int kept = std::min(dimensions, dim);
  Eigen::MatrixXf basis(dim, kept);
  for (int i = 0; i < kept; ++i) {
    Eigen::VectorXd axis = solver.eigenvectors().col(dim - 1 - i);  // descending variance
    Eigen::Index largest;
    axis.cwiseAbs().maxCoeff(&largest);
    if (axis[largest] < 0) axis = -axis;  // fixed sign: reproducible trees
    basis.col(i) = axis.cast<float>();
  }
  for (CrossbarIndex* index : indices) {
    auto trees = std::make_unique<Trees>();
    trees->center = mean.cast<float>();
    trees->basis = basis;
    index->trees_ = std::move(trees);
    index->reduced_ = kept;
    const std::int64_t pixels = std::int64_t(index->rows_.size()) / dim;
    index->rowsReduced_.resize(std::size_t(pixels) * kept);
    index->columnsReduced_.resize(std::size_t(pixels) * kept);
    parallelForChunks(0, pixels, 1024, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t p = begin; p < end; ++p) {
        index->project(index->row(std::int32_t(p)), &index->rowsReduced_[p * kept]);
        index->project(index->column(std::int32_t(p)), &index->columnsReduced_[p * kept]);
      }
    });
    const int half = std::min(kept, jointHalf);
    index->jointHalf_ = half;
    index->joint_.resize(std::size_t(pixels) * 2 * half);
    for (std::int64_t p = 0; p < pixels; ++p)
      for (int i = 0; i < 2 * half; ++i)
        index->joint_[p * 2 * half + i] =
            i < half ? index->rowsReduced_[p * kept + i] : index->columnsReduced_[p * kept + i - half];
    Trees& t = *index->trees_;
    t.rowData = {index->rowsReduced_.data(), std::size_t(pixels), kept};
    t.columnData = {index->columnsReduced_.data(), std::size_t(pixels), kept};
    t.jointData = {index->joint_.data(), std::size_t(pixels), 2 * half};
    const nanoflann::KDTreeSingleIndexAdaptorParams params(16);
    t.rows = std::make_unique<KdTree>(kept, t.rowData, params);
    t.columns = std::make_unique<KdTree>(kept, t.columnData, params);
    t.joint = std::make_unique<KdTree>(2 * half, t.jointData, params);
  }
}

void CrossbarIndex::project(const float* vector, float* reduced) const {
  TS_CHECK_MSG(trees_, "crossbar index used before indexTogether");
  Eigen::Map<Eigen::VectorXf>(reduced, reduced_) =
      trees_->basis.transpose() * (Eigen::Map<const Eigen::VectorXf>(vector, dimension_) - trees_->center);
}

void CrossbarIndex::nearest(Tree tree, const float* query, int k, float epsilon,
                            std::vector<std::uint32_t>& out) const {
  TS_CHECK_MSG(trees_, "crossbar index used before indexTogether");
  const KdTree& kd = tree == Tree::Rows ? *trees_->rows : tree == Tree::Columns ? *trees_->columns : *trees_->joint;
  out.resize(std::size_t(k));
  thread_local std::vector<float> distances;
  distances.resize(std::size_t(k));
  nanoflann::KNNResultSet<float, std::uint32_t> result{std::size_t(k)};
  result.init(out.data(), distances.data());
  kd.findNeighbors(result, query, nanoflann::SearchParams(0, epsilon));
  out.resize(result.size());
}

void gatherCrossbars(const Image& image, int x, int y, int spacing, int n, float* row, float* column) {
  const int w = image.width, h = image.height, c = image.channels;
  for (int k = 0; k < n; ++k) {
    const std::int64_t offset = std::int64_t(k - n / 2) * spacing;
    std::copy_n(image.pixel(wrapIndex(x + offset, w), y), c, row + k * c);
    std::copy_n(image.pixel(x, wrapIndex(y + offset, h)), c, column + k * c);
  }
}

float crossbarL1(const float* a, const float* b, int dimension) {
  float acc[8] = {};
  int i = 0;
  for (; i + 8 <= dimension; i += 8)
    for (int j = 0; j < 8; ++j) acc[j] += std::abs(a[i + j] - b[i + j]);
  for (int j = 0; i < dimension; ++i, ++j) acc[j] += std::abs(a[i] - b[i]);
  return ((acc[0] + acc[4]) + (acc[1] + acc[5])) + ((acc[2] + acc[6]) + (acc[3] + acc[7]));
}

}  // namespace texsynth
