#include "texsynth/core/hash.h"

#include <cstdio>

namespace texsynth {

Hasher& Hasher::bytes(const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::size_t i = 0;
  // Eight bytes at a time through the mixer; FNV on the tail.
  for (; i + 8 <= size; i += 8) {
    std::uint64_t word = 0;
    for (int b = 0; b < 8; ++b) word |= std::uint64_t(p[i + b]) << (8 * b);
    state_ = mix64(state_ ^ word);
  }
  for (; i < size; ++i) state_ = (state_ ^ p[i]) * 0x100000001b3ull;
  return *this;
}

std::string Hasher::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(digest()));
  return text;
}

}  // namespace texsynth
