// Image readers (PNG, JPEG, BMP, TGA, OpenEXR, GIMP .pat). The file is named .tga: the readers
// pick the format by signature and fall back to the extension only for TGA, which has none,
// so one name reaches every decoder. Bad input must raise InputError; anything else escaping
// (another exception, a sanitizer report) is a bug.
#include "fuzz_input_file.h"
#include "one_thread.h"
#include "texsynth/core/error.h"
#include "texsynth/io/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  texsynth::fuzz::InputFile file(data, size, "tga");
  try {
    texsynth::readImageInfo(file.path());
  } catch (const texsynth::InputError&) {
  }
  try {
    texsynth::readImage(file.path());
  } catch (const texsynth::InputError&) {
  }
  return 0;
}
