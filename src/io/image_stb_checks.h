#pragma once
// Internal to the io module: completeness checks for files that stb decodes. stb pads a
// truncated PNG, BMP or TGA with zeros and decodes a JPEG without its end marker, so these
// walk the container structure and reject files that end early.
#include <string>
#include <string_view>

#include "image_codecs.h"

namespace texsynth::image_codec {

// Checks the size a PNG, BMP or TGA header declares before stb sees it, so an absurd size
// gets a clear message (stb only says "unknown image type" when it refuses one).
void checkDeclaredSize(const std::string& path, std::string_view bytes, Format format);

// Throws InputError(path, "truncated: ...") if the file cannot hold the whole image.
void checkStbStructure(const std::string& path, std::string_view bytes, Format format, int width, int height,
                       int channels);

}  // namespace texsynth::image_codec
