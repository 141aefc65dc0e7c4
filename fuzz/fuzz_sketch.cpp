// Sketch JSON reader. Bad input must raise InputError; anything else escaping (a raw JSON
// exception, a sanitizer report) is a bug.
#include <string_view>

#include "one_thread.h"
#include "texsynth/core/error.h"
#include "texsynth/field/sketch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    texsynth::parseSketch(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz input");
  } catch (const texsynth::InputError&) {
  }
  return 0;
}
