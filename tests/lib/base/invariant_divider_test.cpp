// InvariantDivider: division by a constant without a divide, against the exact quotient.
#include "volcomp/base/invariant_divider.hpp"

#include <gtest/gtest.h>

#include <random>

namespace volcomp {
namespace {

// Worked by hand: r = floor((2^32 - 1) / 3) = 0x55555555; for n = 2^32 - 1 the estimate
// (n * r) >> 32 = 0x55555554 is one low, and the remainder check corrects it.
TEST(InvariantDivider, CorrectsAnEstimateOneLow) {
  InvariantDivider div;
  div.Init(3);
  const auto qr = div.Divide(0xFFFFFFFFu);
  EXPECT_EQ(qr.quotient, 0x55555555u);
  EXPECT_EQ(qr.remainder, 0u);
  EXPECT_EQ(div.divisor(), 3u);
  div.Init(7);
  EXPECT_EQ(div.Divide(100).quotient, 14u);
  EXPECT_EQ(div.Divide(100).remainder, 2u);
  EXPECT_EQ(div.Divide(6).quotient, 0u);
  EXPECT_EQ(div.Divide(6).remainder, 6u);
}

TEST(InvariantDivider, ExactForRandomAndEdgeOperands) {
  std::mt19937_64 rng(1);
  const uint32_t divisors[] = {
      1, 2, 3, 7, 10, 1000, 65535, 65536, 99991, 0x7FFFFFFF, 0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
  const uint32_t edges[] = {0, 1, 2, 0x7FFFFFFF, 0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
  for (uint32_t d : divisors) {
    InvariantDivider div;
    div.Init(d);
    for (uint32_t n : edges) {
      const auto qr = div.Divide(n);
      ASSERT_EQ(qr.quotient, n / d) << n << "/" << d;
      ASSERT_EQ(qr.remainder, n % d) << n << "/" << d;
    }
  }
  for (int i = 0; i < 200000; ++i) {
    const uint32_t d = static_cast<uint32_t>(rng() >> (32 + rng() % 32)) | 1u;
    const uint32_t n = static_cast<uint32_t>(rng());
    InvariantDivider div;
    div.Init(d);
    const auto qr = div.Divide(n);
    ASSERT_EQ(qr.quotient, n / d) << n << "/" << d;
    ASSERT_EQ(qr.remainder, n % d);
    // Multiples and their neighbours, where an estimate one low would show.
    const uint32_t m = (n / d) * d;
    ASSERT_EQ(div.Divide(m).quotient, m / d);
    if (m != 0) {
      ASSERT_EQ(div.Divide(m - 1).quotient, (m - 1) / d);
    }
  }
}

}  // namespace
}  // namespace volcomp
