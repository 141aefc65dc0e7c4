#pragma once
// Small image-arrangement helpers for the CLI's pictures (demo report, comparisons).
#include <vector>

#include "texsynth/core/image.h"

namespace texsynth::cli {

// Copies src into dst with its top-left corner at (x, y); parts outside dst are dropped.
void pasteImage(Image& dst, const Image& src, int x, int y);
// Nearest-neighbour enlargement by an integer factor (for showing small exemplars).
Image enlarge(const Image& src, int factor);

}  // namespace texsynth::cli
