// Color histogram matching term (color_histogram_cost.h).
#include "texsynth/image/color_histogram_cost.h"

#include <algorithm>

#include "texsynth/core/error.h"

namespace texsynth::detail {

ColorHistogramCost::ColorHistogramCost(const Image& image, int colorChannels, std::span<const std::int32_t> sources) {
  const int channels = std::min({3, colorChannels, image.channels});
  const std::size_t pixels = image.pixelCount();
  if (channels <= 0 || pixels == 0 || sources.empty()) return;
  // Every pixel's bin in every channel; the exemplar's and the output's share of each bin.
  std::vector<std::uint8_t> bins(pixels * std::size_t(channels));
  std::vector<double> exemplarShare(std::size_t(channels) * kBins, 0.0), outputShare(exemplarShare.size(), 0.0);
  for (int c = 0; c < channels; ++c) {
    float low = image.pixels[std::size_t(c)], high = low;
    for (std::size_t p = 0; p < pixels; ++p) {
      const float v = image.pixels[p * std::size_t(image.channels) + std::size_t(c)];
      low = std::min(low, v), high = std::max(high, v);
    }
    const float perBin = high > low ? float(kBins) / (high - low) : 0.0f;
    for (std::size_t p = 0; p < pixels; ++p) {
      const float v = image.pixels[p * std::size_t(image.channels) + std::size_t(c)];
      const int bin = std::clamp(int((v - low) * perBin), 0, kBins - 1);
      bins[p * std::size_t(channels) + std::size_t(c)] = std::uint8_t(bin);
      exemplarShare[std::size_t(c * kBins + bin)] += 1.0 / double(pixels);
    }
  }
  for (std::int32_t source : sources) {
    if (source < 0 || std::size_t(source) >= pixels)
      throw ParameterError("sources", "pixel " + std::to_string(source) + " lies outside the exemplar");
    for (int c = 0; c < channels; ++c)
      outputShare[std::size_t(c * kBins + bins[std::size_t(source) * std::size_t(channels) + std::size_t(c)])] +=
          1.0 / double(sources.size());
  }
  // A small floor keeps the ratio finite for bins nearly empty in the exemplar.
  constexpr double kFloor = 1e-3;
  std::vector<float> binCost(exemplarShare.size());
  for (std::size_t b = 0; b < binCost.size(); ++b)
    binCost[b] = std::clamp(float((outputShare[b] + kFloor) / (exemplarShare[b] + kFloor) - 1.0), -1.0f, 2.0f);
  cost_.assign(pixels, 0.0f);
  for (std::size_t p = 0; p < pixels; ++p) {
    float sum = 0;
    for (int c = 0; c < channels; ++c)
      sum += binCost[std::size_t(c * kBins + bins[p * std::size_t(channels) + std::size_t(c)])];
    cost_[p] = sum / float(channels);
  }
}

}  // namespace texsynth::detail
