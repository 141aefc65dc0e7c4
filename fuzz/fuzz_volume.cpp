// Volume reader (NRRD: raw or gzip, any sample type and endianness). Bad input must raise
// InputError; anything else escaping (another exception, a sanitizer report) is a bug.
#include "fuzz_input_file.h"
#include "one_thread.h"
#include "texsynth/core/error.h"
#include "texsynth/io/volume_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  texsynth::fuzz::InputFile file(data, size, "nrrd");
  try {
    texsynth::readVolume(file.path());
  } catch (const texsynth::InputError&) {
  }
  return 0;
}
