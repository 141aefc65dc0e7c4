#pragma once
// Helpers shared by the image-module tests: a real GIMP exemplar and periodicity in the
// eval module's 0..255 units.
#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>

#include "texsynth/core/data_paths.h"
#include "texsynth/core/error.h"
#include "texsynth/core/image.h"
#include "texsynth/eval/patch_index.h"
#include "texsynth/eval/periodicity.h"
#include "texsynth/io/image_io.h"

namespace texsynth::test {

// The pattern as RGB, cropped to at most `side` x `side` from its top-left corner.
inline Image loadPatternRgb(const std::string& path, int side) {
  Image image = readImage(path).withChannels(3);
  return image.crop(0, 0, std::min(side, image.width), std::min(side, image.height));
}

// Periodicity as evaluateImage reports it (values scaled to 0..255, 7x7 patches), without the
// cost of coherence and completeness.
inline double periodicityOf(const Image& image, int samples = 500) {
  Image scaled = image;
  for (float& v : scaled.pixels) v *= 255.0f;
  return periodicity(PatchIndex(scaled, 7), PeriodicityOptions{.samples = samples});
}

}  // namespace texsynth::test
