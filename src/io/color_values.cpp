#include "texsynth/io/color_values.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include "texsynth/core/error.h"
#include "texsynth/io/image_io.h"

namespace texsynth {
namespace {

// Index of the first sample that cannot be a colour, if any.
std::optional<std::size_t> firstBadSample(const std::vector<float>& values) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!(std::abs(values[i]) <= kMaxColorMagnitude)) return i;  // NaN fails every comparison
  return std::nullopt;
}

std::string describeValue(float value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "infinity" : "-infinity";
  char text[32];
  std::snprintf(text, sizeof text, "%g", double(value));
  return text;
}

std::string problem(const std::string& where, int channel, float value) {
  const bool finite = std::isfinite(value);
  return where + " channel " + std::to_string(channel) + " holds " + describeValue(value) + ", which is " +
         (finite ? "absurd" : "not a finite number") +
         " for a colour (colour values must be finite with |v| <= 1e6; colours are 0..1)";
}

}  // namespace

void checkColorValues(const std::string& path, const Volume& volume) {
  const auto bad = firstBadSample(volume.voxels);
  if (!bad) return;
  const std::size_t voxel = *bad / std::size_t(volume.channels);
  const std::size_t x = voxel % std::size_t(volume.nx), y = voxel / std::size_t(volume.nx) % std::size_t(volume.ny),
                    z = voxel / (std::size_t(volume.nx) * std::size_t(volume.ny));
  throw InputError(path,
                   problem("voxel (" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + ")",
                           int(*bad % std::size_t(volume.channels)), volume.voxels[*bad]));
}

void checkColorValues(const std::string& path, const Image& image) {
  const auto bad = firstBadSample(image.pixels);
  if (!bad) return;
  const std::size_t pixel = *bad / std::size_t(image.channels);
  throw InputError(path, problem("pixel (" + std::to_string(pixel % std::size_t(image.width)) + ", " +
                                     std::to_string(pixel / std::size_t(image.width)) + ")",
                                 int(*bad % std::size_t(image.channels)), image.pixels[*bad]));
}

Image readColorImage(const std::string& path) {
  Image image = readImage(path);
  checkColorValues(path, image);
  return image;
}

}  // namespace texsynth
