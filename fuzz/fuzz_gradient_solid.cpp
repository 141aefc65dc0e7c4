// Gradient solid (.tsgs) reader: header, boundary mask, quantization parameters, 8-bit payload and
// CRC-32. Bad input must raise InputError; anything else escaping, or a sanitizer report, is a bug.
// Random bytes almost never carry a right CRC-32, so each input is also decoded with its last four
// bytes replaced by the CRC of the rest: the checks after the checksum get fuzzed too.
#include <zlib.h>

#include <string>

#include "one_thread.h"
#include "texsynth/core/error.h"
#include "texsynth/gradient/gradient_solid_file.h"

namespace {

void decode(const std::string& bytes) {
  try {
    texsynth::decodeGradientSolid(bytes, "fuzz input");
  } catch (const texsynth::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  decode(bytes);
  if (size >= 4) {
    const uLong crc = crc32(crc32(0L, nullptr, 0), data, uInt(size - 4));
    for (int b = 0; b < 4; ++b) bytes[size - 4 + std::size_t(b)] = char((crc >> (8 * b)) & 0xff);
    decode(bytes);
  }
  return 0;
}
