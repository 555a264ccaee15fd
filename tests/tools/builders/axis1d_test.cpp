// AXIS1D tables from positioning tests: closed-form cases worked out by hand in the comments.
#include "volcomp/builders/axis1d.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "expected_value.hpp"

namespace volcomp::builders {
namespace {

using model::PositioningData;
using testing::ValueOf;

TEST(builders_axis1d, ScaleAndOffsetErrorInvertsExactly) {
  // dev(p) = 10 µm + 50 µm/m · p, linear in p, so the test points need not be dense. The command
  // q reaching t solves q + (10 + 0.05·q)·1e-3 = t: q = (t − 0.01)/1.00005, correction q − t.
  PositioningData d;
  d.position = {0, 50, 100, 200};
  for (double p : d.position) d.dev_forward.push_back(10 + 0.05 * p);
  Axis1dOptions o;
  o.spacing = 25;
  const Axis1dTable t = ValueOf(BuildAxis1d(d, o));
  ASSERT_EQ(t.forward.size(), 9u);
  EXPECT_TRUE(t.reverse.empty());
  // At t = 0 the command would be −0.01 mm, below the first test position, where the deviation is
  // held at dev(0) = 10 µm: correction −10 µm exactly.
  EXPECT_NEAR(t.forward[0], -10.0, 1e-12);
  for (std::size_t i = 1; i < t.forward.size(); ++i) {
    const double target = 25.0 * static_cast<double>(i);
    const double expected_um = ((target - 0.01) / 1.00005 - target) * 1e3;
    EXPECT_NEAR(t.forward[i], expected_um, 1e-9) << target;
  }
  EXPECT_NEAR(t.forward[4], -14.99925, 1e-5);  // t = 100 mm
  EXPECT_LT(t.max_residual, 1e-6);
}

TEST(builders_axis1d, ReverseModes) {
  PositioningData d;
  d.position = {0, 10, 30};  // irregular: spacing defaults to the smallest gap, 10 mm
  d.dev_forward = {2, 4, 6};
  d.dev_reverse = {-1, 0, 5};
  // Reversal B_j = x̄↑ − x̄↓ = 3, 4, 1 µm; mean B̄ = 8/3 µm.
  Axis1dOptions o;
  o.reverse = ReverseMode::kBacklash;
  Axis1dTable t = ValueOf(BuildAxis1d(d, o));
  EXPECT_NEAR(t.backlash, 8.0 / 3.0, 1e-12);
  EXPECT_EQ(t.forward.size(), 4u);  // 0, 10, 20, 30
  EXPECT_TRUE(t.reverse.empty());
  o.reverse = ReverseMode::kTables;
  t = ValueOf(BuildAxis1d(d, o));
  EXPECT_EQ(t.backlash, 0.0);
  ASSERT_EQ(t.reverse.size(), 4u);
  EXPECT_NEAR(t.forward[0], -2.0, 1e-9);  // dev constant-ish near 0: q ≈ t − 2 µm
  EXPECT_NEAR(t.reverse[0], 1.0, 1e-4);   // dev −1 → +1 µm (plus the tiny slope effect)
  o.reverse = ReverseMode::kMean;
  t = ValueOf(BuildAxis1d(d, o));
  // Mean deviations 0.5, 2, 5.5 µm at 0, 10, 30 mm; near 30: dev(q) = 0.25 + 0.175·q µm, so
  // q = (30 − 0.00025)/1.000175.
  EXPECT_NEAR(t.forward[3], ((30 - 0.00025) / 1.000175 - 30) * 1e3, 1e-9);
  d.dev_reverse.clear();
  const auto refused = BuildAxis1d(d, o);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kInvalidArgument);
  EXPECT_EQ(refused.error().message, "backlash or mean tables need reverse deviations");
}

TEST(builders_axis1d, RotaryUnitsAndStepSnapping) {
  PositioningData d;
  d.rotary = true;
  d.position = {0, 90, 180, 270, 360};
  d.dev_forward = {0, 36, 0, -36, 0};  // arcsec
  Axis1dOptions o;
  o.unit_per_step = 0.001;  // 1 millidegree per step
  const Axis1dTable t = ValueOf(BuildAxis1d(d, o));
  EXPECT_EQ(t.forward.size(), 5u);
  // At 90°: q + 36"·(q/90°) = 90° near there... solve q + 0.01°·(q/90) = 90 → q = 90/(1+1/9000).
  EXPECT_NEAR(t.forward[1], (90.0 / (1.0 + 0.01 / 90.0) - 90.0) * 3600.0, 1e-6);
  o.unit_per_step = 0.7;
  d.position = {0.5, 90, 180};
  d.dev_forward = {0, 0, 0};
  const auto refused = BuildAxis1d(d, o);  // 0.5° is not a whole step of 0.7°
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kInvalidArgument);
  EXPECT_EQ(refused.error().message, "the first test position is not a whole number of steps");
}

}  // namespace
}  // namespace volcomp::builders
