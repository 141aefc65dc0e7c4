// Fitting the influence of an edit (eq. 4): RBF centres drawn from the stroke voxels and their
// non-negative weights from an L1 linear program over (a subsample of) the stroke voxels.
#include "texsynth/gradient/edit_influence.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "edit_lp.h"
#include "texsynth/core/error.h"
#include "texsynth/core/random.h"

namespace texsynth {
namespace {

constexpr std::uint64_t kCentreDraw = 1, kRowDraw = 2;

// The first `count` of a deterministic shuffle of 0..n-1 (partial Fisher-Yates keyed by hashKey).
std::vector<int> drawDistinct(int n, int count, std::uint64_t seed, std::uint64_t purpose) {
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  for (int i = 0; i < count; ++i) {
    const int j = i + int(uniformBelow(hashKey(seed, std::uint64_t(i), purpose), std::uint32_t(n - i)));
    std::swap(order[std::size_t(i)], order[std::size_t(j)]);
  }
  order.resize(std::size_t(count));
  return order;
}

void checkOptions(const EditOptions& options) {
  if (options.centres < 1 || options.centres > 1000)
    throw ParameterError("centres", "must be in [1, 1000], got " + std::to_string(options.centres));
  if (!(std::isfinite(options.alpha) && options.alpha > 0)) throw ParameterError("alpha", "must be positive");
  if (!(std::isfinite(options.beta) && options.beta >= 0)) throw ParameterError("beta", "must be >= 0");
}

}  // namespace

double EditInfluence::term(std::size_t k, const Vec3f& point, const float* color) const {
  double position = 0, colour = 0;
  for (int a = 0; a < 3; ++a) position += double(point[a] - centres[k][a]) * double(point[a] - centres[k][a]);
  for (int c = 0; c < colorChannels; ++c) {
    const double d = 255.0 * double(color[c]) - double(centreColors[k][std::size_t(c)]);
    colour += d * d;
  }
  return std::exp(-double(alpha) * (double(beta) * position + colour));
}

double EditInfluence::operator()(const Vec3f& point, const float* color) const {
  double h = 0;
  for (std::size_t k = 0; k < centres.size(); ++k)
    if (weights[k] > 0) h += weights[k] * term(k, point, color);
  return h;
}

EditInfluence fitEditInfluence(const StrokeVoxels& voxels, const std::vector<float>& colors, int colorChannels,
                               const EditOptions& options) {
  checkOptions(options);
  const int n = voxels.size();
  TS_CHECK(n >= 1 && (colorChannels == 1 || colorChannels == 3));
  TS_CHECK(colors.size() == std::size_t(n) * std::size_t(colorChannels));
  EditInfluence influence;
  influence.alpha = options.alpha;
  influence.beta = options.beta;
  influence.colorChannels = colorChannels;
  // Centres come from the voxels to be edited: a centre on a protect stroke (strength 0) could only
  // raise h where it must stay 0, and would crowd out the centres the edit needs.
  std::vector<int> edited;
  for (int j = 0; j < n; ++j)
    if (voxels.strengths[std::size_t(j)] > 0) edited.push_back(j);
  if (edited.empty()) edited.push_back(0);  // nothing to edit: one centre, which the program weighs 0
  const int m = std::min(options.centres, int(edited.size()));
  for (int draw : drawDistinct(int(edited.size()), m, options.seed, kCentreDraw)) {
    const int j = edited[std::size_t(draw)];
    influence.centres.push_back(voxels.positions[std::size_t(j)].cast<float>());
    std::array<float, 3> colour{0, 0, 0};
    for (int c = 0; c < colorChannels; ++c)
      colour[std::size_t(c)] = 255.0f * colors[std::size_t(j) * colorChannels + c];
    influence.centreColors.push_back(colour);
  }

  // Rows: every stroke voxel, or a sorted deterministic subsample when there are many.
  std::vector<int> rows;
  if (n > kEditLpRows) {
    rows = drawDistinct(n, kEditLpRows, options.seed, kRowDraw);
    std::sort(rows.begin(), rows.end());
  } else {
    rows.resize(std::size_t(n));
    std::iota(rows.begin(), rows.end(), 0);
  }
  influence.lpRows = int(rows.size());
  std::vector<double> a(rows.size() * std::size_t(m)), s(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::size_t j = std::size_t(rows[r]);
    s[r] = voxels.strengths[j];
    const Vec3f p = voxels.positions[j].cast<float>();
    for (int k = 0; k < m; ++k)
      a[r * std::size_t(m) + std::size_t(k)] =
          influence.term(std::size_t(k), p, &colors[j * std::size_t(colorChannels)]);
  }
  influence.weights = solveNonNegativeL1(a, s, m);
  double deviation = 0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    double h = 0;
    for (int k = 0; k < m; ++k) h += influence.weights[std::size_t(k)] * a[r * std::size_t(m) + std::size_t(k)];
    deviation += std::abs(std::min(h, 1.0) - s[r]);
  }
  influence.deviation = deviation / double(rows.size());
  return influence;
}

}  // namespace texsynth
