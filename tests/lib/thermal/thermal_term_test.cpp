// The applied thermal terms in the compensation run's units (thermal_term.hpp), against
// hand-worked conversions: um -> Q24.8 steps, um/mm -> Q0.32 steps per step, mm -> steps.
#include "volcomp/thermal/thermal_term.hpp"

#include <gtest/gtest.h>

namespace volcomp::thermal {
namespace {

// A correction whose applied terms have reached the model at a constant temperature rise
// (slew 1000 um/s: at most 200 s of updates settle it).
class ThermalTermTest : public ::testing::Test {
 protected:
  void Settle(float offset_um_per_K, float slope_um_per_K_m, float p0_mm, int16_t t_cC) {
    ThermalModel m;
    m.axis_count = 1;
    m.channel_mask = 0x01;
    m.reference_cC[0] = 2000;
    m.calibrated_low_cC[0] = -2000;
    m.calibrated_high_cC[0] = 9000;
    m.axis[0].offset_um_per_K[0] = offset_um_per_K;
    m.axis[0].slope_um_per_K_m[0] = slope_um_per_K_m;
    m.axis[0].p0_mm = p0_mm;
    m.axis[0].reach_mm = 500.0f;
    m.slew_um_s = 1000.0f;
    ChannelConfig c;
    c.source = ChannelSource::kCanObject;
    c.timeout_ms = 60000;
    c.max_rate_cC_s = 30000;
    ASSERT_TRUE(channels_.Configure(0, c, 0).ok());
    ASSERT_TRUE(correction_.Configure(m, 100).ok());
    for (uint32_t now = 100; now <= 200000; now += 100) {  // 70 mm at 1000 um/s: 70 s
      ASSERT_TRUE(channels_.Reading(0, t_cC, now).ok());
      correction_.Update(channels_);
    }
    ASSERT_FALSE(correction_.status().slewing);
  }
  TemperatureChannels channels_;
  ThermalCorrection correction_;
};

TEST_F(ThermalTermTest, OffsetSlopeAndZeroInTheRunsUnits) {
  // 2 K rise: offset 2 um/K -> 4 um; ISO 1's steel against a scale, -11.5 um/(K m) -> -0.023 um/mm;
  // p0 120 mm. At 500 nm per step: 8 steps = 2048 Q8; -0.023e-3 * 2^32 = -98784.2; 240 000 steps.
  Settle(2.0f, -11.5f, 120.0f, 2200);
  ThermalTermSteps t;
  ASSERT_TRUE(ToSteps(correction_, 0, 500000, &t));
  EXPECT_NEAR(t.offset_q8, 2048, 1);
  EXPECT_NEAR(t.slope_q32, -98784, 2);
  EXPECT_EQ(t.p0_steps, 240000);
  // 1 um per step: half the steps.
  ASSERT_TRUE(ToSteps(correction_, 0, 1000000, &t));
  EXPECT_NEAR(t.offset_q8, 1024, 1);
  EXPECT_NEAR(t.slope_q32, -98784, 2);  // steps per step: the resolution cancels
  EXPECT_EQ(t.p0_steps, 120000);
}

TEST_F(ThermalTermTest, WhatDoesNotFitSaturatesAndSaysSo) {
  // 1000 um/K at +70 K: 70 mm, at 1 nm per step 7e7 steps: beyond 2^29 / 256 = 2 097 152 steps.
  Settle(1000.0f, 0.0f, 0.0f, 9000);
  ThermalTermSteps t;
  EXPECT_FALSE(ToSteps(correction_, 0, 1000, &t));
  EXPECT_EQ(t.offset_q8, kMaxThermalOffset_q8);
  // The same at 10 um per step fits (7000 steps).
  EXPECT_TRUE(ToSteps(correction_, 0, 10000000, &t));
  EXPECT_NEAR(t.offset_q8, 7000 * 256, 2);
  // A resolution of zero is refused whole.
  EXPECT_FALSE(ToSteps(correction_, 0, 0, &t));
}

TEST_F(ThermalTermTest, ASlopeSteeperThanTheRunTakesSaturatesAndSaysSo) {
  // 1000 um/(K m) at +10 K: 0.01 steps per step, above 2^-9 = 0.00195.
  Settle(0.0f, 1000.0f, 0.0f, 3000);
  ThermalTermSteps t;
  EXPECT_FALSE(ToSteps(correction_, 0, 1000000, &t));
  EXPECT_EQ(t.slope_q32, kMaxThermalSlope_q32);
  // 100 um/(K m) at +10 K: 0.001 fits (the resolution cancels: at any resolution).
  Settle(0.0f, 100.0f, 0.0f, 3000);
  EXPECT_TRUE(ToSteps(correction_, 0, 1000, &t));
  EXPECT_NEAR(t.slope_q32, 4294967, 2);
}

TEST_F(ThermalTermTest, AFarP0SaturatesAndSaysSo) {
  Settle(0.0f, 1.0f, -2000.0f, 2100);  // p0 -2 m, at 1 nm per step -2e9 steps
  ThermalTermSteps t;
  EXPECT_FALSE(ToSteps(correction_, 0, 1000, &t));
  EXPECT_EQ(t.p0_steps, -kMaxThermalP0_steps);
  EXPECT_TRUE(ToSteps(correction_, 0, 10000, &t));  // at 10 nm per step: -2e8 steps
  EXPECT_EQ(t.p0_steps, -200000000);
}

}  // namespace
}  // namespace volcomp::thermal
