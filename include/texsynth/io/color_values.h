#pragma once
// Colour values read from float files. Float NRRD and OpenVDB volumes and EXR images are
// returned as stored (colours nominally 0..1, HDR above), so a file can hold NaN, infinities or
// values like 1e30 that no colour is; every metric and fit computed from them is then
// meaningless (an RMS error of 1e24). These checks refuse such files with an InputError naming
// the file and the first bad sample.
#include <string>

#include "texsynth/core/image.h"
#include "texsynth/core/volume.h"

namespace texsynth {

// The largest magnitude accepted as a colour value: colours are 0..1 (HDR a few hundred at
// most); 1e6 leaves room for any real data (even 0..255 or 0..65535 stored as float) while
// keeping squared differences summed over millions of samples far from overflow.
inline constexpr float kMaxColorMagnitude = 1e6f;

// Throws InputError(path, ...) naming the first voxel (x, y, z) or pixel (x, y), its channel and
// its value when a sample is NaN, infinite or larger in magnitude than kMaxColorMagnitude.
void checkColorValues(const std::string& path, const Volume& volume);
void checkColorValues(const std::string& path, const Image& image);

// readImage for images whose values are colours (exemplars, outputs to evaluate), checked by
// checkColorValues. Not for data images (flow velocities, coordinates), which check their own.
Image readColorImage(const std::string& path);

}  // namespace texsynth
