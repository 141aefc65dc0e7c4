#pragma once
// Eq. 2 of gradient-solid-textures: a control point's values and gradients as the least-squares
// first-order Taylor expansion through samples around it. Shared by vectorization (voxels as samples)
// and synthesis (bucket averages as samples).
#include <Eigen/Dense>

namespace texsynth {

class FirstOrderFit {
 public:
  static constexpr int kMaxChannels = 4;
  explicit FirstOrderFit(int channels) : channels_(channels) {}

  // A sample at offset (du, dv, dw) from the control point, in cube edges.
  void add(double du, double dv, double dw, const float* values, double weight = 1.0) {
    const Eigen::Vector4d basis(1.0, du, dv, dw);
    normal_.noalias() += weight * basis * basis.transpose();
    for (int c = 0; c < channels_; ++c) rhs_.col(c) += weight * basis * double(values[c]);
  }
  double weight() const { return normal_(0, 0); }

  // Writes the set: channels values, then d/du, d/dv, d/dw of every channel. Gradients are damped by
  // 1e-3 of the total weight, so a bucket one voxel thin still gives a well-posed system.
  void solve(float* set) const {
    Eigen::Matrix4d normal = normal_;
    for (int a = 1; a < 4; ++a) normal(a, a) += kGradientDamping * normal_(0, 0);
    const Eigen::LDLT<Eigen::Matrix4d> solver(normal);
    for (int c = 0; c < channels_; ++c) {
      const Eigen::Vector4d solution = solver.solve(rhs_.col(c));
      for (int slot = 0; slot < 4; ++slot) set[slot * channels_ + c] = float(solution[slot]);
    }
  }

 private:
  static constexpr double kGradientDamping = 1e-3;
  int channels_;
  Eigen::Matrix4d normal_ = Eigen::Matrix4d::Zero();
  Eigen::Matrix<double, 4, kMaxChannels> rhs_ = Eigen::Matrix<double, 4, kMaxChannels>::Zero();
};

}  // namespace texsynth
