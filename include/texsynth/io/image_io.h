#pragma once
// Image files: read PNG, JPEG, BMP, TGA (stb), OpenEXR and GIMP .pat patterns into a float
// Image with nominal range [0,1]; write PNG (8/16 bit), JPEG, BMP, TGA, OpenEXR and .pat.
//
// Readers recognise the format by the file's content (its signature) and fall back to the
// extension only for TGA, which has none. Any missing, empty, truncated, malformed or absurd
// file (a side over 65536 pixels, over 2^31 values, more pixels than the file could hold)
// raises one InputError naming the file and the problem; nothing is allocated for absurd
// sizes. Writers go through writeAtomically: a failed write never leaves a partial file.
#include <string>

#include "texsynth/core/image.h"

namespace texsynth {

struct ImageFileInfo {
  int width = 0, height = 0, channels = 0;
  int bitsPerChannel = 0;  // 8, 16 (16-bit PNG, half EXR) or 32 (float EXR)
  std::string format;      // "png", "jpg", "bmp", "tga", "exr" or "pat"
};

// Reads any supported image. Integer samples are divided by their maximum (255 or 65535);
// EXR samples are returned as stored (HDR values above 1 are kept).
// Channels: 1 gray, 2 gray+alpha, 3 RGB, 4 RGBA, as stored in the file.
Image readImage(const std::string& path);

// Size, channels and bit depth from the file's header, without decoding the pixels.
ImageFileInfo readImageInfo(const std::string& path);

struct ImageWriteOptions {
  int bitsPerChannel = 8;  // 8 or 16; 16 is honoured by PNG only (other formats ignore it)
  int jpegQuality = 95;    // 1..100, JPEG only
};

// Writes an image with 1..4 channels; the format comes from the extension:
//   .png        8 or 16 bit, 1..4 channels as given
//   .jpg .jpeg  8 bit RGB: alpha is dropped and gray is stored as color (stb's encoder always
//               writes three components), so gray images come back as RGB with R = G = B
//   .bmp        8 bit RGB (gray is expanded; 2 channels become RGBA, 4 stay RGBA)
//   .tga        8 bit, 1..4 channels as given
//   .exr        32-bit float, lossless ZIP compression; channels Y, YA, RGB or RGBA
//   .pat        GIMP pattern, 8 bit, 1..4 channels; the pattern name is the file stem
// Values outside [0,1] are clipped only where the format stores integers (NaN becomes 0).
// Throws ParameterError for an unknown extension, an empty image, a bad channel count or bad
// options; OutputError if the file cannot be written.
void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options = {});

}  // namespace texsynth
