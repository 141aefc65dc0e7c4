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

// i mod n for i within one period of [0, n) (-n <= i < 2n): one compare instead of a division,
// for neighborhood offsets smaller than the side they wrap around.
constexpr int wrapOnce(int i, int n) {
  return i < 0 ? i + n : (i >= n ? i - n : i);
}

// i mod n, without a division for the usual i within one period of [0, n).
constexpr int wrapNear(int i, int n) {
  return i >= -n && i < 2 * n ? wrapOnce(i, n) : wrapIndex(i, n);
}

// std::lround (halves away from zero) for |x| < 2^23, where x minus its truncation is exact,
// without the library call: the surface solvers round every member they look up (lroundf was a
// tenth of a surface E+M step).
constexpr int roundHalfAway(float x) {
  const int r = int(x);
  const float part = x - float(r);
  return r + int(part >= 0.5f) - int(part <= -0.5f);
}

// Exact quotient of non-negative ints below 2^24 by a fixed divisor through a multiply and a
// shift (a division costs tens of cycles; the solvers split every exemplar pixel index into x
// and y): with M = floor(2^40 / d) + 1, floor(n M / 2^40) = floor(n / d) for n < 2^24.
class FixedDivisor {
 public:
  FixedDivisor() = default;
  explicit constexpr FixedDivisor(int divisor) : multiplier_((std::uint64_t(1) << 40) / std::uint64_t(divisor) + 1) {}
  // n in [0, 2^24).
  constexpr int divide(std::int32_t n) const { return int((std::uint64_t(n) * multiplier_) >> 40); }
  static constexpr std::int32_t kLimit = 1 << 24;

 private:
  std::uint64_t multiplier_ = (std::uint64_t(1) << 40) + 1;
};

}  // namespace texsynth
