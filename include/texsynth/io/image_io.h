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
#include <vector>

#include "texsynth/core/atomic_file.h"
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
// readImage of each path, in order.
std::vector<Image> readImages(const std::vector<std::string>& paths);

// Size, channels and bit depth from the file's header, without decoding the pixels.
ImageFileInfo readImageInfo(const std::string& path);

struct ImageWriteOptions {
  int bitsPerChannel = 8;  // 8 or 16; 16 is honoured by PNG only (other formats ignore it)
  int jpegQuality = 95;    // 1..100, JPEG only
  // EXR: half floats even for values between 8-bit levels, for data made from 8-bit sources
  // (half's 11-bit mantissa keeps more than they have); half the size and much faster to
  // compress. Off: lossless (see writeImage). Never for coordinates.
  bool exrHalf = false;
  // Inside an OutputBatch: with the run (default), or at once (scratch files the run reads back
  // itself, such as a video's frames).
  Staging staging = Staging::WithRun;
};

// Options that keep an input's precision where the output format can: 16 bits per channel
// (PNG) for an input with more than 8 (a 16-bit PNG, a half or float EXR), else 8; half-float
// EXR for an input of at most 8 bits.
ImageWriteOptions writeOptionsKeeping(const ImageFileInfo& input);

// Writes an image with 1..4 channels; the format comes from the extension:
//   .png        8 or 16 bit, 1..4 channels as given; deflated on all threads (--threads),
//               the bytes independent of the thread count
//   .jpg .jpeg  8 bit RGB (libjpeg-turbo): alpha is dropped and gray is stored as color, so
//               gray images come back as RGB with R = G = B
//   .bmp        8 bit RGB (gray is expanded; 2 channels become RGBA, 4 stay RGBA)
//   .tga        8 bit, 1..4 channels as given
//   .exr        lossless: half floats if every value is an 8-bit level k/255 (read back
//               exactly by readImage), else 32-bit floats (half with options.exrHalf);
//               PIZ-compressed on all threads; channels Y, YA, RGB or RGBA
//   .pat        GIMP pattern, 8 bit, 1..4 channels; the pattern name is the file stem
// Values outside [0,1] are clipped only where the format stores integers (NaN becomes 0).
// Throws ParameterError for an unknown extension, an empty image, a bad channel count or bad
// options; OutputError if the file cannot be written.
void writeImage(const std::string& path, const Image& image, const ImageWriteOptions& options = {});

// The bytes of an 8-bit PNG of the image (1-4 channels), as writeImage would store them.
std::string encodePngBytes(const Image& image);

}  // namespace texsynth
