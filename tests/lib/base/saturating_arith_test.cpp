// Saturating int32 add and subtract (interp_arith.hpp: QADD/QSUB on the Cortex-M4, the C form
// elsewhere) at and around the ends of the range.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "volcomp/base/interp_arith.hpp"

namespace volcomp {
namespace {

constexpr int32_t kMax = std::numeric_limits<int32_t>::max();
constexpr int32_t kMin = std::numeric_limits<int32_t>::min();

TEST(SaturatingArith, AddStopsAtTheEndsOfTheRange) {
  EXPECT_EQ(AddSat(2, 3), 5);
  EXPECT_EQ(AddSat(-7, 3), -4);
  EXPECT_EQ(AddSat(kMax - 1, 1), kMax);
  EXPECT_EQ(AddSat(kMax - 1, 2), kMax);
  EXPECT_EQ(AddSat(kMax, kMax), kMax);
  EXPECT_EQ(AddSat(kMin + 1, -1), kMin);
  EXPECT_EQ(AddSat(kMin + 1, -2), kMin);
  EXPECT_EQ(AddSat(kMin, kMin), kMin);
  EXPECT_EQ(AddSat(kMax, kMin), -1);
}

TEST(SaturatingArith, SubtractStopsAtTheEndsOfTheRange) {
  EXPECT_EQ(SubSat(2, 3), -1);
  EXPECT_EQ(SubSat(kMax, -1), kMax);
  EXPECT_EQ(SubSat(kMin, 1), kMin);
  EXPECT_EQ(SubSat(0, kMin), kMax);
  EXPECT_EQ(SubSat(-1, kMin), kMax);
  EXPECT_EQ(SubSat(kMin, kMin), 0);
}

}  // namespace
}  // namespace volcomp
