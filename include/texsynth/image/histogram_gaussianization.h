#pragma once
// Per-channel 1D Gaussianization of an exemplar (Deliot & Heitz 2019, "Procedural
// stochastic textures by tiling and blending"), the histogram transform behind tile-blend.
//
// T maps each channel's values to a standard Gaussian through the empirical CDF: the pixel of
// rank r among n (ties broken by pixel index, so the result is exactly Gaussian-distributed
// and deterministic) gets Φ⁻¹((r + 0.5) / n). T⁻¹ is a lookup table per channel sampled
// uniformly in Gaussian space over [-range, range]: entry i holds the exemplar quantile at
// Φ(g_i), so mapping a Gaussian value back to the exemplar's histogram is one linear
// interpolation (values outside the range clamp to the extreme quantiles). Sampling in Gaussian
// space rather than in Φ(g) avoids an erf per lookup in the hot path.
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth {

struct GaussianizationOptions {
  int lutSize = 1024;          // T⁻¹ entries per channel (>= 2)
  float gaussianRange = 4.0f;  // T⁻¹ covers Gaussian values in [-range, range] (finite, > 0)
};

// T⁻¹: Gaussian value -> exemplar value, per channel.
class InverseLut {
 public:
  InverseLut() = default;
  // `entries` holds channels * size values, channel-major.
  InverseLut(int channels, int size, float range, std::vector<float> entries);

  int channels() const { return channels_; }
  int size() const { return size_; }
  float range() const { return range_; }

  // Exemplar value of channel c for Gaussian value g.
  float lookup(int c, float g) const {
    float t = (g + range_) * scale_;
    t = t < 0.0f ? 0.0f : (t > float(size_ - 1) ? float(size_ - 1) : t);
    int i = int(t);
    if (i >= size_ - 1) i = size_ - 2;
    float f = t - float(i);
    const float* row = &entries_[std::size_t(c) * size_ + i];
    return row[0] + (row[1] - row[0]) * f;
  }
  // All channels at once: gaussian[c] -> color[c].
  void lookup(const float* gaussian, float* color) const {
    for (int c = 0; c < channels_; ++c) color[c] = lookup(c, gaussian[c]);
  }

 private:
  int channels_ = 0, size_ = 0;
  float range_ = 0, scale_ = 0;  // scale_ = (size - 1) / (2 range)
  std::vector<float> entries_;
};

// An exemplar in Gaussian space plus the table that maps back to its colors.
struct GaussianizedExemplar {
  Image gaussian;  // T(exemplar): same size and channels, each channel ~ N(0, 1)
  InverseLut lut;  // T⁻¹

  // One point: Gaussian values (one per channel) -> exemplar-histogram color.
  void toColor(const float* g, float* color) const { lut.lookup(g, color); }
  // A whole image in Gaussian space -> colors (same size and channels).
  Image toColor(const Image& gaussianImage) const;
};

// Throws ParameterError("exemplar", ...) for an empty image, ("lutSize" / "gaussianRange", ...)
// for bad options.
GaussianizedExemplar gaussianize(const Image& exemplar, const GaussianizationOptions& options = {});

// Φ⁻¹: standard normal quantile for u in (0, 1), accurate to ~1e-12 (used by gaussianize;
// exposed for 3D analogues and tests).
double inverseNormalCdf(double u);

}  // namespace texsynth
