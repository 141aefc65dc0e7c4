#include "image_layout.h"

#include <algorithm>

namespace texsynth::cli {

void pasteImage(Image& dst, const Image& src, int x0, int y0) {
  Image converted = src.withChannels(dst.channels);
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < src.width; ++x) {
      int tx = x0 + x, ty = y0 + y;
      if (tx < 0 || ty < 0 || tx >= dst.width || ty >= dst.height) continue;
      std::copy_n(converted.pixel(x, y), dst.channels, dst.pixel(tx, ty));
    }
}

Image enlarge(const Image& src, int factor) {
  Image out(src.width * factor, src.height * factor, src.channels);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) std::copy_n(src.pixel(x / factor, y / factor), src.channels, out.pixel(x, y));
  return out;
}

}  // namespace texsynth::cli
