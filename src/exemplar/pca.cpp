#include "texsynth/exemplar/pca.h"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

// Pixels gathered and multiplied at once: big enough for an efficient GEMM, small enough
// to stay in cache (chunk x dimension floats).
constexpr std::int64_t kGatherChunk = 256;
// The covariance is summed in this many fixed pixel ranges, then added in range order.
constexpr std::int64_t kCovarianceBlocks = 16;

// Per-channel means, as sums over fixed row ranges added in row order.
std::vector<double> channelMeans(const Image& level) {
  std::vector<double> rowSums(std::size_t(level.height) * level.channels, 0.0);
  parallelFor(0, level.height, [&](std::int64_t y) {
    const float* row = level.pixel(0, int(y));
    double* sums = &rowSums[std::size_t(y) * level.channels];
    for (int x = 0; x < level.width; ++x)
      for (int c = 0; c < level.channels; ++c) sums[c] += row[std::size_t(x) * level.channels + c];
  });
  std::vector<double> means(level.channels, 0.0);
  for (int y = 0; y < level.height; ++y)
    for (int c = 0; c < level.channels; ++c) means[c] += rowSums[std::size_t(y) * level.channels + c];
  for (double& m : means) m /= double(level.pixelCount());
  return means;
}

Eigen::MatrixXd neighborhoodCovariance(const Image& level, const NeighborhoodShape& shape,
                                       const std::vector<float>& mean) {
  const int dimension = shape.dimension();
  const std::int64_t pixels = std::int64_t(level.pixelCount());
  const std::int64_t blockSize = (pixels + kCovarianceBlocks - 1) / kCovarianceBlocks;
  std::vector<Eigen::MatrixXd> partial(kCovarianceBlocks, Eigen::MatrixXd::Zero(dimension, dimension));
  Eigen::Map<const Eigen::VectorXf> meanVector(mean.data(), dimension);
  parallelFor(0, kCovarianceBlocks, [&](std::int64_t block) {
    std::int64_t begin = block * blockSize, end = std::min(pixels, begin + blockSize);
    Eigen::MatrixXf samples(dimension, kGatherChunk);
    Eigen::MatrixXf product(dimension, dimension);
    for (std::int64_t first = begin; first < end; first += kGatherChunk) {
      std::int64_t count = std::min(kGatherChunk, end - first);
      gatherNeighborhoods(level, first, count, shape, samples.data());
      auto centered = samples.leftCols(count);
      centered.colwise() -= meanVector;
      product.noalias() = centered * centered.transpose();
      partial[block] += product.cast<double>();
    }
  });
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(dimension, dimension);
  for (const auto& p : partial) covariance += p;
  return covariance / double(pixels);
}

}  // namespace

// The hottest loop of synthesis: an AVX2 copy is picked at run time where the CPU has it
// (without FMA, so every machine computes the same bits).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void PcaBasis::project(const float* neighborhood, float* out) const {
  // Sums in a local block so they stay in registers (`out` might alias the inputs, which
  // would force a load and store per term); each output still sums its terms in input order.
  constexpr int kBlock = 32;
  const int outputs = outputDimension;
  for (int first = 0; first < outputs; first += kBlock) {
    const int count = std::min(kBlock, outputs - first);
    float sums[kBlock] = {};
    const float* row = basis.data() + first;
    for (int j = 0; j < inputDimension; ++j, row += outputs) {
      const float centered = neighborhood[j] - mean[j];
      for (int i = 0; i < count; ++i) sums[i] += row[i] * centered;
    }
    std::copy(sums, sums + count, out + first);
  }
}

void PcaBasis::projectMany(const float* neighborhoods, std::int64_t count, float* out) const {
  for (std::int64_t k = 0; k < count; ++k) project(neighborhoods + k * inputDimension, out + k * outputDimension);
}

PcaBasis fitNeighborhoodPca(const Image& level, const NeighborhoodShape& shape, int maxDimensions) {
  TS_CHECK(!level.empty() && shape.channels == level.channels);
  if (maxDimensions < 1)
    throw ParameterError("pcaDimensions", "must be at least 1, got " + std::to_string(maxDimensions));
  const int dimension = shape.dimension();
  PcaBasis pca;
  pca.inputDimension = dimension;
  pca.outputDimension = std::min(maxDimensions, dimension);

  // Toroidal sampling visits every pixel once per window offset, so the mean neighborhood
  // is the per-channel mean repeated over the window.
  std::vector<double> means = channelMeans(level);
  pca.mean.resize(dimension);
  for (int j = 0; j < dimension; ++j) pca.mean[j] = float(means[j % shape.channels]);

  Eigen::MatrixXd covariance = neighborhoodCovariance(level, shape, pca.mean);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);
  TS_CHECK_MSG(solver.info() == Eigen::Success, "PCA eigen decomposition failed");
  const Eigen::VectorXd& values = solver.eigenvalues();  // ascending
  const Eigen::MatrixXd& vectors = solver.eigenvectors();

  pca.totalVariance = 0;
  for (int j = 0; j < dimension; ++j) pca.totalVariance += std::max(0.0, values[j]);
  pca.basis.assign(std::size_t(dimension) * pca.outputDimension, 0.0f);
  pca.variances.resize(pca.outputDimension);
  double kept = 0;
  for (int i = 0; i < pca.outputDimension; ++i) {
    const int source = dimension - 1 - i;  // largest eigenvalue first
    pca.variances[i] = float(std::max(0.0, values[source]));
    kept += std::max(0.0, values[source]);
    Eigen::Index largest = 0;
    vectors.col(source).cwiseAbs().maxCoeff(&largest);
    const double sign = vectors(largest, source) < 0 ? -1.0 : 1.0;
    for (int j = 0; j < dimension; ++j)
      pca.basis[std::size_t(j) * pca.outputDimension + i] = float(sign * vectors(j, source));
  }
  pca.keptEnergy = pca.totalVariance > 0 ? std::min(1.0, kept / pca.totalVariance) : 1.0;
  return pca;
}

std::vector<float> projectAllNeighborhoods(const Image& level, const NeighborhoodShape& shape, const PcaBasis& basis) {
  TS_CHECK(basis.inputDimension == shape.dimension());
  const std::int64_t pixels = std::int64_t(level.pixelCount());
  std::vector<float> projected(std::size_t(pixels) * basis.outputDimension);
  parallelForChunks(0, pixels, kGatherChunk, [&](std::int64_t begin, std::int64_t end) {
    std::vector<float> gathered(std::size_t(end - begin) * basis.inputDimension);
    gatherNeighborhoods(level, begin, end - begin, shape, gathered.data());
    basis.projectMany(gathered.data(), end - begin, &projected[std::size_t(begin) * basis.outputDimension]);
  });
  return projected;
}

}  // namespace texsynth
