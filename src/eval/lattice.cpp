#include "texsynth/eval/lattice.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "texsynth/core/color.h"
#include "texsynth/core/error.h"

namespace texsynth {
namespace {

using Complex = std::complex<double>;

// Detail whose RMS (0..255 units) is below this counts as none: a flat image's high-pass is
// rounding noise, and normalizing it by its own variance would make up a lattice.
constexpr double kMinimumDetailRms = 1e-3;
// Offsets this close to the origin (in x and in y) never count.
constexpr int kExcludedRadius = 2;

// The smallest multiple of 4 that is >= n and has no prime factor above 5 (Eigen's FFT takes
// its fast real path for multiples of 4 and is fastest on small primes).
int fftSize(int n) {
  for (int m = std::max(4, (n + 3) / 4 * 4);; m += 4) {
    int rest = m;
    for (int p : {2, 3, 5})
      while (rest % p == 0) rest /= p;
    if (rest == 1) return m;
  }
}

// Y of every pixel, in double.
std::vector<double> luminanceOf(const Image& image) {
  std::vector<double> y(image.pixelCount());
  for (std::size_t i = 0; i < y.size(); ++i) {
    const float* p = &image.pixels[i * std::size_t(image.channels)];
    for (int c = 0; c < image.channels; ++c)
      if (!std::isfinite(p[c])) throw ParameterError("image", "contains non-finite values (NaN or infinity)");
    y[i] = double(luminance(p, image.channels));
  }
  return y;
}

// `values` (w x h) blurred by a normalized Gaussian of `sigma`, separably, borders clamped.
std::vector<double> gaussianBlur(const std::vector<double>& values, int w, int h, double sigma) {
  const int radius = int(std::ceil(3 * sigma));
  std::vector<double> kernel(2 * radius + 1);
  double sum = 0;
  for (int i = -radius; i <= radius; ++i) sum += kernel[i + radius] = std::exp(-0.5 * i * i / (sigma * sigma));
  for (double& k : kernel) k /= sum;
  // Rows, through a copy of each row extended by `radius` clamped values on either side.
  std::vector<double> rows(values.size()), padded(std::size_t(w) + 2 * radius);
  for (int y = 0; y < h; ++y) {
    const double* in = &values[std::size_t(y) * w];
    for (int x = -radius; x < w + radius; ++x) padded[x + radius] = in[std::clamp(x, 0, w - 1)];
    double* out = &rows[std::size_t(y) * w];
    for (int x = 0; x < w; ++x) {
      double acc = 0;
      for (int i = 0; i <= 2 * radius; ++i) acc += kernel[i] * padded[x + i];
      out[x] = acc;
    }
  }
  // Columns, a whole row of accumulators at a time.
  std::vector<double> out(values.size(), 0.0);
  for (int y = 0; y < h; ++y) {
    double* acc = &out[std::size_t(y) * w];
    for (int i = -radius; i <= radius; ++i) {
      const double k = kernel[i + radius];
      const double* in = &rows[std::size_t(std::clamp(y + i, 0, h - 1)) * w];
      for (int x = 0; x < w; ++x) acc[x] += k * in[x];
    }
  }
  return out;
}

// S(dx, dy) = sum_p d(p) d(p + (dx, dy)) over pixels inside the w x h image, for |dx| <= maxDx
// and |dy| <= maxDy, as a (2 maxDx + 1) x (2 maxDy + 1) grid centred on the origin. Zero-padded
// to nx >= w + maxDx and ny >= h + maxDy, so the circular correlation of the FFT does not wrap.
std::vector<double> autocorrelation(const std::vector<double>& d, int w, int h, int maxDx, int maxDy) {
  const int nx = fftSize(w + maxDx), ny = fftSize(h + maxDy), bins = nx / 2 + 1;
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  // Rows: real to half spectrum; rows at and below h are zero and stay implicit.
  std::vector<Complex> spectrum(std::size_t(h) * bins);
  std::vector<double> row(nx, 0.0);
  for (int y = 0; y < h; ++y) {
    std::copy_n(&d[std::size_t(y) * w], w, row.begin());
    fft.fwd(&spectrum[std::size_t(y) * bins], row.data(), nx);
  }
  // Columns: forward, power, inverse; keep the rows of dy = -maxDy..maxDy.
  const int gridW = 2 * maxDx + 1, gridH = 2 * maxDy + 1;
  std::vector<Complex> kept(std::size_t(gridH) * bins);
  std::vector<Complex> column(ny), transformed(ny);
  for (int k = 0; k < bins; ++k) {
    std::fill(column.begin(), column.end(), Complex(0));
    for (int y = 0; y < h; ++y) column[y] = spectrum[std::size_t(y) * bins + k];
    fft.fwd(transformed.data(), column.data(), ny);
    for (Complex& c : transformed) c = std::norm(c);
    fft.inv(column.data(), transformed.data(), ny);
    for (int dy = -maxDy; dy <= maxDy; ++dy) kept[std::size_t(dy + maxDy) * bins + k] = column[(dy + ny) % ny];
  }
  // Rows: half spectrum to real; keep dx = -maxDx..maxDx.
  std::vector<double> grid(std::size_t(gridW) * gridH);
  for (int j = 0; j < gridH; ++j) {
    fft.inv(row.data(), &kept[std::size_t(j) * bins], nx);
    for (int dx = -maxDx; dx <= maxDx; ++dx) grid[std::size_t(j) * gridW + dx + maxDx] = row[(dx + nx) % nx];
  }
  return grid;
}

}  // namespace

LatticePeak latticePeak(const Image& rgb255, const LatticeOptions& options) {
  if (!(options.highPassSigma >= 0) || !std::isfinite(options.highPassSigma))
    throw ParameterError("highPassSigma", "must be a finite value >= 0, got " + std::to_string(options.highPassSigma));
  if (!(options.lobeThreshold >= 0 && options.lobeThreshold <= 1))
    throw ParameterError("lobeThreshold", "must be in 0..1, got " + std::to_string(options.lobeThreshold));
  LatticePeak peak;
  if (rgb255.empty()) return peak;
  const int w = rgb255.width, h = rgb255.height, maxDx = w / 2, maxDy = h / 2;
  std::vector<double> detail = luminanceOf(rgb255);
  if (maxDx <= kExcludedRadius && maxDy <= kExcludedRadius) return peak;  // no offset could count

  if (options.highPassSigma > 0) {
    const std::vector<double> blurred = gaussianBlur(detail, w, h, options.highPassSigma);
    for (std::size_t i = 0; i < detail.size(); ++i) detail[i] -= blurred[i];
  }
  double mean = 0;
  for (double v : detail) mean += v;
  mean /= double(detail.size());
  double energy = 0;
  for (double& v : detail) {
    v -= mean;
    energy += v * v;
  }
  const double variance = energy / double(detail.size());
  if (!(variance >= kMinimumDetailRms * kMinimumDetailRms)) return peak;

  const int gridW = 2 * maxDx + 1;
  std::vector<double> r = autocorrelation(detail, w, h, maxDx, maxDy);
  auto at = [&](int dx, int dy) -> double& { return r[std::size_t(dy + maxDy) * gridW + dx + maxDx]; };
  for (int dy = -maxDy; dy <= maxDy; ++dy)
    for (int dx = -maxDx; dx <= maxDx; ++dx)
      at(dx, dy) /= double(w - std::abs(dx)) * double(h - std::abs(dy)) * variance;
  // R(d) and R(-d) are equal but for rounding: make them equal exactly.
  for (std::size_t i = 0, j = r.size() - 1; i < j; ++i, --j) r[i] = r[j] = 0.5 * (r[i] + r[j]);
  at(0, 0) = 1;

  // The central lobe, flood-filled from the origin through R > lobeThreshold.
  std::vector<unsigned char> lobe(r.size(), 0);
  std::vector<std::pair<int, int>> stack = {{0, 0}};
  lobe[std::size_t(maxDy) * gridW + maxDx] = 1;
  while (!stack.empty()) {
    const auto [x, y] = stack.back();
    stack.pop_back();
    const int next[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
    for (const auto& n : next) {
      if (std::abs(n[0]) > maxDx || std::abs(n[1]) > maxDy) continue;
      unsigned char& inLobe = lobe[std::size_t(n[1] + maxDy) * gridW + n[0] + maxDx];
      if (inLobe || !(at(n[0], n[1]) > options.lobeThreshold)) continue;
      inLobe = 1;
      stack.push_back({n[0], n[1]});
    }
  }
  // The largest local maximum of R elsewhere (a repeat is a peak; the lobe's flanks, where R
  // falls from the lobe towards 0, are not), on the half plane dy > 0 or (dy == 0, dx > 0).
  auto isLocalMaximum = [&](int dx, int dy) {
    for (int ny = std::max(dy - 1, -maxDy); ny <= std::min(dy + 1, maxDy); ++ny)
      for (int nx = std::max(dx - 1, -maxDx); nx <= std::min(dx + 1, maxDx); ++nx)
        if (at(nx, ny) > at(dx, dy)) return false;
    return true;
  };
  for (int dy = 0; dy <= maxDy; ++dy)
    for (int dx = dy == 0 ? 1 : -maxDx; dx <= maxDx; ++dx) {
      if (std::abs(dx) <= kExcludedRadius && dy <= kExcludedRadius) continue;
      if (lobe[std::size_t(dy + maxDy) * gridW + dx + maxDx]) continue;
      if (at(dx, dy) > peak.strength && isLocalMaximum(dx, dy)) peak = {at(dx, dy), dx, dy};
    }
  // A repeat that holds more than its share of the detail can pass 1 a little: a copy is 1.
  peak.strength = std::min(peak.strength, 1.0);
  return peak;
}

double latticeStrength(const Image& rgb255, const LatticeOptions& options) {
  return latticePeak(rgb255, options).strength;
}

}  // namespace texsynth
