#include "texsynth/render/slice_montage.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "texsynth/core/error.h"

namespace texsynth {

namespace {

void validate(const Volume& volume, const MontageOptions& options) {
  if (volume.empty()) throw ParameterError("volume", "is empty");
  if (volume.channels != 1 && volume.channels != 3 && volume.channels != 4)
    throw ParameterError("volume", "has " + std::to_string(volume.channels) +
                                       " channels; slices show 1 (gray), 3 (RGB) or 4 (RGBA, alpha ignored)");
  if (options.fractions.empty()) throw ParameterError("fractions", "needs at least one slice position");
  for (float f : options.fractions)
    if (!(f >= 0 && f <= 1)) throw ParameterError("fractions", "must lie in [0, 1], got " + std::to_string(f));
  if (options.border < 0 || options.border > 1024)
    throw ParameterError("border", "must be in [0, 1024], got " + std::to_string(options.border));
  if (options.scale < 1 || options.scale > 64)
    throw ParameterError("scale", "must be in [1, 64], got " + std::to_string(options.scale));
  if (!options.background.allFinite()) throw ParameterError("background", "must be a finite colour");
}

int sliceIndex(float fraction, int count) {
  return std::min(count - 1, int(std::floor(fraction * float(count))));
}

}  // namespace

Image sliceMontage(const Volume& volume, const MontageOptions& options) {
  validate(volume, options);
  const int dims[3] = {volume.nx, volume.ny, volume.nz};
  const int cellWidth = std::max(volume.nx, volume.ny) * options.scale;
  const int cellHeight = std::max(volume.ny, volume.nz) * options.scale;
  const std::int64_t columns = std::int64_t(options.fractions.size());
  const std::int64_t width = options.border + columns * (cellWidth + options.border);
  const std::int64_t height = options.border + 3 * std::int64_t(cellHeight + options.border);
  if (width > 65536 || height > 65536)
    throw ParameterError("scale", "the montage would be " + std::to_string(width) + " x " + std::to_string(height) +
                                      " pixels, larger than 65536 on a side");

  Image image(int(width), int(height), 3);
  for (std::size_t p = 0; p < image.pixelCount(); ++p)
    for (int c = 0; c < 3; ++c) image.pixels[p * 3 + c] = options.background[c];

  for (int normalAxis = 0; normalAxis < 3; ++normalAxis) {
    // The remaining axes in increasing order: image x follows the first, image y the second.
    const int axisU = normalAxis == 0 ? 1 : 0, axisV = normalAxis == 2 ? 1 : 2;
    for (std::int64_t column = 0; column < columns; ++column) {
      const int slice = sliceIndex(options.fractions[column], dims[normalAxis]);
      const int originX = options.border + int(column) * (cellWidth + options.border);
      const int originY = options.border + normalAxis * (cellHeight + options.border);
      for (int py = 0; py < dims[axisV] * options.scale; ++py)
        for (int px = 0; px < dims[axisU] * options.scale; ++px) {
          int voxel[3];
          voxel[normalAxis] = slice;
          voxel[axisU] = px / options.scale;
          voxel[axisV] = py / options.scale;
          const float* value = volume.voxel(voxel[0], voxel[1], voxel[2]);
          float* out = image.pixel(originX + px, originY + py);
          for (int c = 0; c < 3; ++c) out[c] = value[volume.channels == 1 ? 0 : c];
        }
    }
  }
  return image;
}

}  // namespace texsynth
