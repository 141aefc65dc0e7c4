// Eq. 3: control points that minimize the exact tricubic error over all samples. The normal matrix is
// never assembled: each cube adds W^T W (32 x 32) of its samples, and W^T W factors into the three
// axes' 4 x 4 Gram matrices of the Hermite functions, the same for every full cube.
#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "texsynth/core/parallel.h"
#include "texsynth/gradient/tricubic_basis.h"
#include "vectorize_layout.h"

namespace texsynth::vectorize_detail {
namespace {

using Matrix32 = Eigen::Matrix<float, 32, 32>;

// The Hermite functions of one axis at the samples of each cube, and their Gram matrix.
struct AxisSamples {
  std::vector<std::vector<std::array<float, 4>>> basis;  // per cube, per voxel
  std::vector<Eigen::Matrix4d> gram;                     // per cube
};

AxisSamples axisSamples(const ControlGrid& grid, int axis) {
  AxisSamples samples;
  for (int c = 0; c < grid.cubes(axis); ++c) {
    std::vector<std::array<float, 4>> basis;
    Eigen::Matrix4d gram = Eigen::Matrix4d::Zero();
    for (int x = grid.cubeBegin(axis, c); x < grid.cubeEnd(axis, c); ++x) {
      basis.push_back(hermiteBasis(float(x - c * grid.spacing) / float(grid.spacing)));
      const Eigen::Vector4d h(basis.back()[0], basis.back()[1], basis.back()[2], basis.back()[3]);
      gram += h * h.transpose();
    }
    samples.basis.push_back(std::move(basis));
    samples.gram.push_back(gram);
  }
  return samples;
}

// Which Hermite function of `axis` weight 4p + s uses: the corner's value or slope function.
int axisFunction(int weight, int axis) {
  const int p = weight / 4, s = weight % 4;
  return ((p >> axis) & 1) + (s == axis + 1 ? 2 : 0);
}

// Channels is the channel count when known at compile time (1, 3), else 0.
template <int Channels>
class Refiner {
 public:
  Refiner(const FitLayout& layout, const FitTargets& targets) : layout_(layout), targets_(targets) {
    for (int a = 0; a < 3; ++a) axes_[a] = axisSamples(layout.grid, a);
    for (int pattern = 0; pattern < 8; ++pattern) gram_[pattern] = cubeGram(pattern);
  }

  void solve(int iterations, std::vector<float>& x) {
    const std::size_t rows = std::size_t(layout_.slots()) * 4, channels = std::size_t(layout_.channels);
    std::vector<float> diagonal(rows, 0.0f), b(rows * channels, 0.0f), r(rows * channels), z(rows * channels),
        p(rows * channels), q(rows * channels);
    rightHandSide(b);
    forEachCubeLayer([&](const std::int64_t* slots, int pattern, int sign, int i, int j, int k) {
      if (sign == 0) {
        for (int w = 0; w < 32; ++w) diagonal[std::size_t(slots[w / 4]) * 4 + w % 4] += gram_[pattern](w, w);
        return;
      }
      forEachSample(i, j, k, sign, [&](const float* weights, float weight, int, int, int) {
        for (int w = 0; w < 32; ++w)
          diagonal[std::size_t(slots[w / 4]) * 4 + w % 4] += weight * weights[w] * weights[w];
      });
    });
    for (float& d : diagonal) d = d > 0 ? 1.0f / d : 0.0f;
    apply(x, q);
    for (std::size_t n = 0; n < r.size(); ++n) r[n] = b[n] - q[n];
    precondition(diagonal, r, z);
    p = z;
    std::vector<double> rz = dots(r, z);
    for (int iteration = 0; iteration < iterations; ++iteration) {
      apply(p, q);
      const std::vector<double> pq = dots(p, q);
      std::vector<float> alpha(channels);
      for (std::size_t c = 0; c < channels; ++c) alpha[c] = pq[c] > 0 ? float(rz[c] / pq[c]) : 0.0f;
      for (std::size_t n = 0; n < r.size(); ++n) {
        x[n] += alpha[n % channels] * p[n];
        r[n] -= alpha[n % channels] * q[n];
      }
      precondition(diagonal, r, z);
      const std::vector<double> next = dots(r, z);
      for (std::size_t n = 0; n < p.size(); ++n) {
        const std::size_t c = n % channels;
        p[n] = z[n] + (rz[c] > 0 ? float(next[c] / rz[c]) : 0.0f) * p[n];
      }
      rz = next;
    }
  }

 private:
  // W^T W of a cube whose axes are full (bit clear) or the last, partial cube (bit set).
  Matrix32 cubeGram(int pattern) const {
    Matrix32 gram;
    Eigen::Matrix4d axis[3];
    for (int a = 0; a < 3; ++a) {
      const int cubes = layout_.grid.cubes(a);
      axis[a] = axes_[a].gram[std::size_t((pattern >> a) & 1 ? cubes - 1 : 0)];
    }
    for (int u = 0; u < 32; ++u)
      for (int v = 0; v < 32; ++v) {
        double product = 1;
        for (int a = 0; a < 3; ++a) product *= axis[a](axisFunction(u, a), axisFunction(v, a));
        gram(u, v) = float(product);
      }
    return gram;
  }

  // Calls f(slots of the 8 corners, gram pattern, sign, cube i, j, k) for every cube and each side it
  // fits, one parity class of cubes at a time so that concurrent calls never share a control point.
  template <typename F>
  void forEachCubeLayer(F f) const {
    const ControlGrid& grid = layout_.grid;
    for (int parity = 0; parity < 8; ++parity) {
      const int px = parity & 1, py = (parity >> 1) & 1, pz = (parity >> 2) & 1;
      const int layersZ = (grid.cubes(2) - pz + 1) / 2;
      parallelFor(0, layersZ, [&](std::int64_t layer) {
        const int k = pz + 2 * int(layer);
        for (int j = py; j < grid.cubes(1); j += 2)
          for (int i = px; i < grid.cubes(0); i += 2) {
            const int pattern =
                (i == grid.cubes(0) - 1 ? 1 : 0) | (j == grid.cubes(1) - 1 ? 2 : 0) | (k == grid.cubes(2) - 1 ? 4 : 0);
            const CubeSides sides = layout_.sides(grid.cubeIndex(i, j, k));
            for (int sign : {1, -1}) {
              if ((sign > 0 && sides == CubeSides::Negative) ||
                  (sign < 0 && sides != CubeSides::Negative && sides != CubeSides::Both))
                continue;
              std::int64_t slots[8];
              for (int c = 0; c < 8; ++c)
                slots[c] = layout_.slot(grid.controlIndex(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)), sign);
              f(slots, pattern, sides == CubeSides::Both ? sign : 0, i, j, k);
            }
          }
      });
    }
  }

  // Calls f(32 weights, sample weight, x, y, z) for every voxel of cube (i,j,k). On a side of a cube the
  // boundary crosses (sign != 0), the voxels evaluation puts on that side weigh 1 and the values carried
  // over from the other side (dilation) only kExtendedWeight: they keep the set defined where the side
  // has few voxels, without pulling it away from the voxels it really colours.
  template <typename F>
  void forEachSample(int i, int j, int k, int sign, F f) const {
    const ControlGrid& grid = layout_.grid;
    const auto &bx = axes_[0].basis[std::size_t(i)], &by = axes_[1].basis[std::size_t(j)],
               &bz = axes_[2].basis[std::size_t(k)];
    float weights[32];
    for (std::size_t z = 0; z < bz.size(); ++z)
      for (std::size_t y = 0; y < by.size(); ++y)
        for (std::size_t x = 0; x < bx.size(); ++x) {
          tricubicWeights(bx[x], by[y], bz[z], weights);
          const int vx = grid.cubeBegin(0, i) + int(x), vy = grid.cubeBegin(1, j) + int(y),
                    vz = grid.cubeBegin(2, k) + int(z);
          float weight = 1.0f;
          if (sign != 0 && (targets_.sides->at(vx, vy, vz, 0) > 0.5f) != (sign > 0)) weight = kExtendedWeight;
          f(weights, weight, vx, vy, vz);
        }
  }

  // b = W^T y over every cube and side.
  void rightHandSide(std::vector<float>& b) const {
    const int channels = Channels ? Channels : layout_.channels;
    forEachCubeLayer([&](const std::int64_t* slots, int, int sign, int i, int j, int k) {
      const Volume& samples = sign == 0 ? *targets_.original : targets_.forSide(sign);
      float local[32 * 4] = {};
      forEachSample(i, j, k, sign, [&](const float* weights, float weight, int x, int y, int z) {
        const float* value = samples.voxel(x, y, z);
        for (int w = 0; w < 32; ++w)
          for (int c = 0; c < channels; ++c) local[w * channels + c] += weight * weights[w] * value[c];
      });
      for (int w = 0; w < 32; ++w)
        for (int c = 0; c < channels; ++c)
          b[(std::size_t(slots[w / 4]) * 4 + std::size_t(w % 4)) * channels + std::size_t(c)] +=
              local[w * channels + c];
    });
  }

  // out = K in, K = sum over cubes and sides of S^T (W^T W) S.
  void apply(const std::vector<float>& in, std::vector<float>& out) const {
    const int channels = Channels ? Channels : layout_.channels;
    using Block = Eigen::Matrix<float, 32, Channels ? Channels : Eigen::Dynamic,
                                Channels == 1 ? Eigen::ColMajor : Eigen::RowMajor, 32, Channels ? Channels : 4>;
    std::fill(out.begin(), out.end(), 0.0f);
    forEachCubeLayer([&](const std::int64_t* slots, int pattern, int sign, int i, int j, int k) {
      Block gathered(32, channels), product(32, channels);
      for (int w = 0; w < 32; ++w)
        for (int c = 0; c < channels; ++c)
          gathered(w, c) = in[(std::size_t(slots[w / 4]) * 4 + std::size_t(w % 4)) * channels + std::size_t(c)];
      if (sign == 0) {
        product.noalias() = gram_[pattern].lazyProduct(gathered);
      } else {  // weighted samples: W^T diag(weight) W, voxel by voxel
        product.setZero();
        forEachSample(i, j, k, sign, [&](const float* weights, float weight, int, int, int) {
          float value[4] = {0, 0, 0, 0};
          for (int w = 0; w < 32; ++w)
            for (int c = 0; c < channels; ++c) value[c] += weights[w] * gathered(w, c);
          for (int w = 0; w < 32; ++w)
            for (int c = 0; c < channels; ++c) product(w, c) += weight * weights[w] * value[c];
        });
      }
      for (int w = 0; w < 32; ++w)
        for (int c = 0; c < channels; ++c)
          out[(std::size_t(slots[w / 4]) * 4 + std::size_t(w % 4)) * channels + std::size_t(c)] += product(w, c);
    });
  }

  void precondition(const std::vector<float>& diagonal, const std::vector<float>& r, std::vector<float>& z) const {
    const std::size_t channels = std::size_t(layout_.channels);
    for (std::size_t n = 0; n < r.size(); ++n) z[n] = diagonal[n / channels] * r[n];
  }

  // Per-channel dot products, summed in fixed chunks so the result never depends on the thread count.
  std::vector<double> dots(const std::vector<float>& a, const std::vector<float>& b) const {
    const std::size_t channels = std::size_t(layout_.channels), chunk = 1 << 16;
    const std::size_t chunks = (a.size() + chunk - 1) / chunk;
    std::vector<double> partial(chunks * channels, 0.0);
    parallelFor(0, std::int64_t(chunks), [&](std::int64_t index) {
      const std::size_t begin = std::size_t(index) * chunk, end = std::min(a.size(), begin + chunk);
      for (std::size_t n = begin; n < end; ++n)
        partial[std::size_t(index) * channels + n % channels] += double(a[n]) * b[n];
    });
    std::vector<double> sum(channels, 0.0);
    for (std::size_t n = 0; n < partial.size(); ++n) sum[n % channels] += partial[n];
    return sum;
  }

  const FitLayout& layout_;
  const FitTargets& targets_;
  AxisSamples axes_[3];
  Matrix32 gram_[8];
};

}  // namespace

void refineControlPoints(const FitLayout& layout, const FitTargets& targets, int iterations,
                         std::vector<float>& unknowns) {
  if (layout.channels == 1)
    Refiner<1>(layout, targets).solve(iterations, unknowns);
  else if (layout.channels == 3)
    Refiner<3>(layout, targets).solve(iterations, unknowns);
  else
    Refiner<0>(layout, targets).solve(iterations, unknowns);
}

}  // namespace texsynth::vectorize_detail
