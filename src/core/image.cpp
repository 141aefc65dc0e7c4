#include "texsynth/core/image.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "texsynth/core/color.h"
#include "texsynth/core/wrap.h"

namespace texsynth {

Image::Image(int w, int h, int c, float fill) : width(w), height(h), channels(c) {
  if (w < 0 || h < 0 || c < 0) throw ParameterError("image size", "negative dimension");
  pixels.assign(std::size_t(w) * h * c, fill);
}

float Image::wrapped(int x, int y, int c) const {
  return at(wrapIndex(x, width), wrapIndex(y, height), c);
}

Image Image::crop(int x0, int y0, int w, int h) const {
  if (w <= 0 || h <= 0 || x0 < 0 || y0 < 0 || x0 + w > width || y0 + h > height)
    throw ParameterError("crop", "window " + std::to_string(w) + "x" + std::to_string(h) + " at (" +
                                     std::to_string(x0) + "," + std::to_string(y0) + ") does not fit a " +
                                     std::to_string(width) + "x" + std::to_string(height) + " image");
  Image out(w, h, channels);
  for (int y = 0; y < h; ++y) std::copy_n(pixel(x0, y0 + y), std::size_t(w) * channels, out.pixel(0, y));
  return out;
}

Image Image::tiled(int w, int h) const {
  TS_CHECK(!empty());
  Image out(w, h, channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) std::copy_n(pixel(x % width, y % height), channels, out.pixel(x, y));
  return out;
}

Image Image::channelRange(int first, int count) const {
  TS_CHECK(first >= 0 && count >= 0 && first + count <= channels);
  Image out(width, height, count);
  for (std::size_t p = 0; p < pixelCount(); ++p)
    for (int c = 0; c < count; ++c) out.pixels[p * count + c] = pixels[p * channels + first + c];
  return out;
}

Image Image::withChannels(int count) const {
  if (count == channels) return *this;
  TS_CHECK(count >= 1 && count <= 4);
  Image out(width, height, count);
  for (std::size_t p = 0; p < pixelCount(); ++p) {
    const float* src = &pixels[p * channels];
    float* dst = &out.pixels[p * count];
    float gray = luminance(src, channels);
    bool srcAlpha = channels == 2 || channels == 4;
    float alpha = srcAlpha ? src[channels - 1] : 1.0f;
    int colorIn = srcAlpha ? channels - 1 : channels;
    if (count <= 2) {
      dst[0] = colorIn >= 3 ? gray : src[0];
      if (count == 2) dst[1] = alpha;
    } else {
      for (int c = 0; c < 3; ++c) dst[c] = colorIn >= 3 ? src[c] : src[0];
      if (count == 4) dst[3] = alpha;
    }
  }
  return out;
}

}  // namespace texsynth
