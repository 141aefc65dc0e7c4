#include "texsynth/exemplar/feature_distance.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"

namespace texsynth {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Felzenszwalb-Huttenlocher lower envelope of parabolas, on a ring of n samples:
// out[i] = min_j f[j] + ringDistance(i, j)^2. The ring is unrolled into three copies
// (offsets -n, 0, +n), which holds every site within ring distance n/2 of [0, n).
class RingDistanceTransform {
 public:
  explicit RingDistanceTransform(int n) : n_(n), sites_(3 * n), siteValues_(3 * n), bounds_(3 * n + 1) {}

  void run(const double* f, double* out) {
    int k = -1;
    for (int copy = -1; copy <= 1; ++copy)
      for (int j = 0; j < n_; ++j) {
        if (f[j] == kInfinity) continue;
        double q = double(j) + double(copy) * n_;
        double fq = f[j];
        double s = -kInfinity;
        while (k >= 0) {
          s = intersection(sites_[k], siteValues_[k], q, fq);
          if (s > bounds_[k]) break;
          --k;
        }
        ++k;
        sites_[k] = q;
        siteValues_[k] = fq;
        bounds_[k] = k == 0 ? -kInfinity : s;
      }
    if (k < 0) {
      for (int i = 0; i < n_; ++i) out[i] = kInfinity;
      return;
    }
    bounds_[k + 1] = kInfinity;
    int segment = 0;
    for (int i = 0; i < n_; ++i) {
      while (bounds_[segment + 1] < i) ++segment;
      double d = i - sites_[segment];
      out[i] = d * d + siteValues_[segment];
    }
  }

 private:
  // Where the parabolas rooted at (p, fp) and (q, fq), p < q, cross.
  static double intersection(double p, double fp, double q, double fq) {
    return ((fq + q * q) - (fp + p * p)) / (2.0 * (q - p));
  }

  int n_;
  std::vector<double> sites_, siteValues_, bounds_;
};

// Squared toroidal distance from every pixel to the nearest pixel where isSite is true.
std::vector<double> squaredDistanceToSites(const std::vector<bool>& isSite, int width, int height) {
  std::vector<double> columnPass(std::size_t(width) * height);
  parallelForChunks(0, width, 32, [&](std::int64_t begin, std::int64_t end) {
    RingDistanceTransform transform(height);
    std::vector<double> in(height), out(height);
    for (std::int64_t x = begin; x < end; ++x) {
      for (int y = 0; y < height; ++y) in[y] = isSite[std::size_t(y) * width + x] ? 0.0 : kInfinity;
      transform.run(in.data(), out.data());
      for (int y = 0; y < height; ++y) columnPass[std::size_t(y) * width + x] = out[y];
    }
  });
  std::vector<double> result(std::size_t(width) * height);
  parallelForChunks(0, height, 32, [&](std::int64_t begin, std::int64_t end) {
    RingDistanceTransform transform(width);
    for (std::int64_t y = begin; y < end; ++y)
      transform.run(&columnPass[std::size_t(y) * width], &result[std::size_t(y) * width]);
  });
  return result;
}

}  // namespace

Image signedDistanceToFeature(const Image& mask) {
  if (mask.empty()) throw ParameterError("featureMask", "mask image is empty");
  const int width = mask.width, height = mask.height;
  std::vector<bool> feature(mask.pixelCount()), background(mask.pixelCount());
  std::size_t featureCount = 0;
  for (std::size_t p = 0; p < mask.pixelCount(); ++p) {
    bool on = false;
    for (int c = 0; c < mask.channels; ++c) on = on || mask.pixels[p * mask.channels + c] != 0.0f;
    feature[p] = on;
    background[p] = !on;
    featureCount += on;
  }
  if (featureCount == 0) throw ParameterError("featureMask", "has no feature (nonzero) pixel");
  if (featureCount == mask.pixelCount()) throw ParameterError("featureMask", "has no background (zero) pixel");
  std::vector<double> toFeature = squaredDistanceToSites(feature, width, height);
  std::vector<double> toBackground = squaredDistanceToSites(background, width, height);
  Image sdf(width, height, 1);
  for (std::size_t p = 0; p < sdf.pixelCount(); ++p)
    sdf.pixels[p] = feature[p] ? -float(std::sqrt(toBackground[p])) : float(std::sqrt(toFeature[p]));
  return sdf;
}

Image featureChannelFromMask(const Image& mask, float weight) {
  if (!std::isfinite(weight) || weight < 0.0f)
    throw ParameterError("featureWeight", "must be a finite value >= 0, got " + std::to_string(weight));
  Image channel = signedDistanceToFeature(mask);
  float largest = 0.0f;
  for (float d : channel.pixels) largest = std::max(largest, std::fabs(d));
  // largest >= 1 because the mask has both kinds of pixel.
  const float scale = weight / largest;
  for (float& d : channel.pixels) d *= scale;
  return channel;
}

Image appendChannel(const Image& image, const Image& extra) {
  if (extra.width != image.width || extra.height != image.height)
    throw ParameterError("featureMask", "size " + std::to_string(extra.width) + "x" + std::to_string(extra.height) +
                                            " differs from the exemplar's " + std::to_string(image.width) + "x" +
                                            std::to_string(image.height));
  if (extra.channels != 1) throw ParameterError("featureMask", "feature channel must have exactly one channel");
  Image out(image.width, image.height, image.channels + 1);
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    const float* src = &image.pixels[p * image.channels];
    float* dst = &out.pixels[p * out.channels];
    for (int c = 0; c < image.channels; ++c) dst[c] = src[c];
    dst[image.channels] = extra.pixels[p];
  }
  return out;
}

}  // namespace texsynth
