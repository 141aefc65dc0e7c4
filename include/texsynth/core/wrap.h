#pragma once
// Toroidal indexing: exemplars and noise lattices wrap around, so indices are taken modulo
// their size with a non-negative result even for negative inputs.
#include <cstdint>

namespace texsynth {

// i mod n in [0, n), for n > 0 and any i.
constexpr int wrapIndex(std::int64_t i, int n) {
  std::int64_t r = i % n;
  return int(r < 0 ? r + n : r);
}

}  // namespace texsynth
