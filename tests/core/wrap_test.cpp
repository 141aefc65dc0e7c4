// Toroidal indexing helpers: wrapOnce agrees with wrapIndex within one period, wrapNear
// everywhere, roundHalfAway with std::lround, FixedDivisor divides exactly below its limit.
#include "texsynth/core/wrap.h"

#include <gtest/gtest.h>

#include <cmath>

#include "texsynth/core/random.h"

namespace texsynth {
namespace {

TEST(Wrap, WrapOnceAgreesWithWrapIndexWithinOnePeriod) {
  for (int n : {1, 2, 7, 64, 1000})
    for (int i = -n; i < 2 * n; ++i) EXPECT_EQ(wrapOnce(i, n), wrapIndex(i, n)) << i << " mod " << n;
}

TEST(Wrap, WrapNearAgreesWithWrapIndexEverywhere) {
  for (int n : {1, 2, 7, 64})
    for (int i = -5 * n - 3; i < 5 * n + 3; ++i) EXPECT_EQ(wrapNear(i, n), wrapIndex(i, n)) << i << " mod " << n;
}

TEST(Wrap, RoundHalfAwayAgreesWithLround) {
  // Halves, their float neighbours and random values, both signs.
  for (int i = -300; i <= 300; ++i) {
    const float half = float(i) + 0.5f;
    for (float x : {float(i), half, std::nextafter(half, -1e9f), std::nextafter(half, 1e9f), -half})
      EXPECT_EQ(roundHalfAway(x), int(std::lround(x))) << x;
  }
  for (std::uint64_t k = 0; k < 20000; ++k) {
    const float x = (float(uniform01(hashKey(7, k))) - 0.5f) * 4096.0f;
    ASSERT_EQ(roundHalfAway(x), int(std::lround(x))) << x;
  }
}

TEST(Wrap, FixedDivisorIsExactBelowItsLimit) {
  for (int d : {1, 2, 3, 7, 48, 127, 128, 1000, 4095, 65535, 65536}) {
    const FixedDivisor divisor(d);
    for (std::int32_t n : {0, 1, d - 1, d, d + 1, FixedDivisor::kLimit - 1}) EXPECT_EQ(divisor.divide(n), n / d) << n;
    // Around every multiple of d near the top of the range, and random values.
    for (std::int32_t q = (FixedDivisor::kLimit - 1) / d; q > (FixedDivisor::kLimit - 1) / d - 50 && q > 0; --q)
      for (std::int32_t n : {q * d - 1, q * d, q * d + d - 1}) EXPECT_EQ(divisor.divide(n), n / d) << n;
    for (std::uint64_t k = 0; k < 20000; ++k) {
      const auto n = std::int32_t(uniformBelow(hashKey(std::uint64_t(d), k), std::uint32_t(FixedDivisor::kLimit)));
      ASSERT_EQ(divisor.divide(n), n / d) << n << " / " << d;
    }
  }
}

}  // namespace
}  // namespace texsynth
