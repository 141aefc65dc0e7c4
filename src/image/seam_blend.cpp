#include "texsynth/image/seam_blend.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "texsynth/core/error.h"
#include "texsynth/core/parallel.h"
#include "texsynth/core/wrap.h"

namespace texsynth {

Image seamBlendedColors(const Image& image, const SourceCoordinates& coords, int channels, float sigma) {
  if (!(sigma >= 0.0f && sigma <= kMaxSeamBlend))
    throw ParameterError("seamBlend",
                         "must be in [0, " + std::to_string(kMaxSeamBlend) + "], got " + std::to_string(sigma));
  // The crisp colors (lookupColors checks the image and channels); seam pixels are replaced below.
  Image out = lookupColors(image, coords, channels);
  const int radius = int(std::lround(1.5f * sigma));
  if (radius == 0) return out;
  channels = out.channels;
  // The window's offsets and Gaussian weights, once.
  struct Tap {
    int dx, dy;
    float weight;
  };
  std::vector<Tap> taps;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx)
      taps.push_back({dx, dy, std::exp(-float(dx * dx + dy * dy) / (2 * sigma * sigma))});
  const int w = coords.width, h = coords.height, mw = image.width, mh = image.height;
  // Every pixel's coordinates wrapped onto the map once; a tap's offset then wraps with one
  // compare (unless the map is narrower than the window).
  std::vector<std::int32_t> mapX(std::size_t(w) * h), mapY(mapX.size());
  for (std::size_t i = 0; i < mapX.size(); ++i)
    mapX[i] = wrapIndex(coords.xy[2 * i], mw), mapY[i] = wrapIndex(coords.xy[2 * i + 1], mh);
  auto wrap = [radius](int i, int n) { return radius < n ? wrapOnce(i, n) : wrapIndex(i, n); };
  parallelForChunks(0, h, 8, [&](std::int64_t begin, std::int64_t end) {
    std::vector<std::int32_t> proposals(taps.size() * 2);  // (x, y) on the map, wrapped; x = -1: outside the output
    std::vector<float> sum(static_cast<std::size_t>(channels));
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < w; ++x) {
        const int ownX = mapX[std::size_t(y) * w + x], ownY = mapY[std::size_t(y) * w + x];
        bool seam = false;
        for (std::size_t t = 0; t < taps.size(); ++t) {
          const int qx = x + taps[t].dx, qy = y + taps[t].dy;
          if (qx < 0 || qy < 0 || qx >= w || qy >= h) {
            proposals[2 * t] = -1;
            continue;
          }
          const std::size_t q = std::size_t(qy) * w + qx;
          proposals[2 * t] = wrap(mapX[q] - taps[t].dx, mw);
          proposals[2 * t + 1] = wrap(mapY[q] - taps[t].dy, mh);
          seam = seam || proposals[2 * t] != ownX || proposals[2 * t + 1] != ownY;
        }
        if (!seam) continue;
        float* to = out.pixel(x, y);
        std::fill(sum.begin(), sum.end(), 0.0f);
        float total = 0;
        for (std::size_t t = 0; t < taps.size(); ++t) {
          if (proposals[2 * t] < 0) continue;
          const float* color = image.pixel(proposals[2 * t], proposals[2 * t + 1]);
          for (int c = 0; c < channels; ++c) sum[std::size_t(c)] += taps[t].weight * color[c];
          total += taps[t].weight;
        }
        for (int c = 0; c < channels; ++c) to[c] = sum[std::size_t(c)] / total;
      }
  });
  return out;
}

}  // namespace texsynth
