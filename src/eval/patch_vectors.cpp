#include "patch_vectors.h"

#include <Eigen/Dense>
#include <algorithm>

namespace texsynth::eval_detail {
namespace {

// Enough patches for a stable covariance; more only costs time (the basis needs to be
// orthonormal for exactness, and good only for speed).
constexpr std::size_t kMaxCovarianceSamples = 20000;
// Eigen's eigendecomposition of a D x D covariance costs as much time as ~6 D^3 multiply-adds of
// a matrix product (measured for D = 600..1000; more for larger D), so count 10 D^3.
constexpr double kEigenCostPerCube = 10;

using RowMajorF = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void copyPatch(const Image& image, int patchSize, int x, int y, float* out) {
  const std::size_t rowValues = std::size_t(patchSize) * image.channels;
  for (int dy = 0; dy < patchSize; ++dy) std::copy_n(image.pixel(x, y + dy), rowValues, out + dy * rowValues);
}

// Centred values of the patch at (x, y) with zero padding to the stride: its raw coordinates.
void copyCentred(const Image& image, const PatchBasis& basis, int x, int y, float* out) {
  copyPatch(image, basis.patchSize, x, y, out);
  for (int k = 0; k < basis.dimensions; ++k) out[k] -= basis.mean[k];
  std::fill(out + basis.dimensions, out + basis.stride, 0.0f);
}

}  // namespace

bool pcaPaysOff(std::size_t patches, int dimensions) {
  const double n = double(patches), d = double(dimensions);
  const double samples = std::min(n, double(kMaxCovarianceSamples));
  // Covariance, eigendecomposition and rotating every indexed patch, against a brute-force
  // search of every patch for as many queries as there are patches (which the tree, once
  // built, beats by far).
  const double pca = samples * d * d + kEigenCostPerCube * d * d * d + n * d * d;
  return pca < n * n * d;
}

PatchBasis computePatchBasis(const Image& image, int patchSize) {
  PatchBasis basis;
  basis.patchSize = patchSize;
  basis.dimensions = patchSize * patchSize * image.channels;
  basis.stride = (basis.dimensions + kLaneWidth - 1) / kLaneWidth * kLaneWidth;
  const int columns = image.width - patchSize + 1, rows = image.height - patchSize + 1;
  const std::size_t count = std::size_t(columns) * rows;
  const std::size_t step = std::max<std::size_t>(1, count / kMaxCovarianceSamples);
  const int dims = basis.dimensions;
  if (!pcaPaysOff(count, dims)) {
    basis.mean.assign(dims, 0.0f);  // raw coordinates; distances do not need centring
    return basis;
  }

  Eigen::MatrixXd samples((count + step - 1) / step, dims);
  std::vector<float> patch(dims);
  Eigen::Index row = 0;
  for (std::size_t i = 0; i < count; i += step, ++row) {
    copyPatch(image, patchSize, int(i % columns), int(i / columns), patch.data());
    for (int k = 0; k < dims; ++k) samples(row, k) = patch[k];
  }
  Eigen::RowVectorXd mean = samples.colwise().mean();
  samples.rowwise() -= mean;
  Eigen::MatrixXd covariance = samples.transpose() * samples;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);

  basis.mean.assign(mean.data(), mean.data() + dims);
  basis.rotation.assign(std::size_t(dims) * basis.stride, 0.0f);
  // Eigen sorts eigenvalues ascending: column j of the rotation is eigenvector dims-1-j.
  for (int j = 0; j < dims; ++j)
    for (int k = 0; k < dims; ++k)
      basis.rotation[std::size_t(k) * basis.stride + j] = float(solver.eigenvectors()(k, dims - 1 - j));
  return basis;
}

void rotatePatchRows(const Image& image, const PatchBasis& basis, int firstRow, int rowCount, float* out) {
  const int columns = image.width - basis.patchSize + 1;
  if (basis.identity()) {
    for (int r = 0; r < rowCount; ++r)
      for (int x = 0; x < columns; ++x)
        copyCentred(image, basis, x, firstRow + r, out + (std::size_t(r) * columns + x) * basis.stride);
    return;
  }
  const Eigen::Index count = Eigen::Index(columns) * rowCount;
  RowMajorF centred(count, basis.dimensions);
  for (int r = 0; r < rowCount; ++r)
    for (int x = 0; x < columns; ++x) {
      float* row = centred.row(Eigen::Index(r) * columns + x).data();
      copyPatch(image, basis.patchSize, x, firstRow + r, row);
      for (int k = 0; k < basis.dimensions; ++k) row[k] -= basis.mean[k];
    }
  Eigen::Map<const RowMajorF> rotation(basis.rotation.data(), basis.dimensions, basis.stride);
  Eigen::Map<RowMajorF> result(out, count, basis.stride);
  result.noalias() = centred * rotation;
}

void rotatePatch(const Image& image, const PatchBasis& basis, int x, int y, float* out) {
  if (basis.identity()) return copyCentred(image, basis, x, y, out);
  std::vector<float> centred(basis.dimensions);
  copyPatch(image, basis.patchSize, x, y, centred.data());
  for (int k = 0; k < basis.dimensions; ++k) centred[k] -= basis.mean[k];
  Eigen::Map<const RowMajorF> rotation(basis.rotation.data(), basis.dimensions, basis.stride);
  Eigen::Map<Eigen::RowVectorXf> result(out, basis.stride);
  result.noalias() = Eigen::Map<const Eigen::RowVectorXf>(centred.data(), basis.dimensions) * rotation;
}

void rotateVectors(const float* values, std::size_t count, const PatchBasis& basis, float* out) {
  if (basis.identity()) {
    for (std::size_t i = 0; i < count; ++i) {
      float* row = out + i * basis.stride;
      for (int k = 0; k < basis.dimensions; ++k) row[k] = values[i * basis.dimensions + k] - basis.mean[k];
      std::fill(row + basis.dimensions, row + basis.stride, 0.0f);
    }
    return;
  }
  RowMajorF centred = Eigen::Map<const RowMajorF>(values, Eigen::Index(count), basis.dimensions);
  for (Eigen::Index i = 0; i < centred.rows(); ++i)
    for (int k = 0; k < basis.dimensions; ++k) centred(i, k) -= basis.mean[k];
  Eigen::Map<const RowMajorF> rotation(basis.rotation.data(), basis.dimensions, basis.stride);
  Eigen::Map<RowMajorF> result(out, Eigen::Index(count), basis.stride);
  result.noalias() = centred * rotation;
}

}  // namespace texsynth::eval_detail
