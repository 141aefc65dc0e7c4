// Toroidal indexing helpers: wrapOnce agrees with wrapIndex within one period, FixedDivisor
// divides exactly below its limit.
#include "texsynth/core/wrap.h"

#include <gtest/gtest.h>

#include "texsynth/core/random.h"

namespace texsynth {
namespace {

TEST(Wrap, WrapOnceAgreesWithWrapIndexWithinOnePeriod) {
  for (int n : {1, 2, 7, 64, 1000})
    for (int i = -n; i < 2 * n; ++i) EXPECT_EQ(wrapOnce(i, n), wrapIndex(i, n)) << i << " mod " << n;
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
