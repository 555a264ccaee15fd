// The thermal correction against hand-worked cases (thermal_model.hpp, docs/thermal.md): the
// model's offset and slope from the temperature rises, the slew limit anywhere on the travel, the
// hold and fade-out on a channel fault, the calibrated range.
#include "volcomp/thermal/thermal_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace volcomp::thermal {
namespace {

constexpr uint32_t kPeriodMs = 100;

// X: 2 um/K offset and -11.5 um/(K m) slope on channel 0 (reference 20 C, calibrated 15..30 C),
// p0 = 0, travel +-500 mm.
ThermalModel OneChannelModel() {
  ThermalModel m;
  m.axis_count = 1;
  m.channel_mask = 0x01;
  m.reference_cC[0] = 2000;
  m.calibrated_low_cC[0] = 1500;
  m.calibrated_high_cC[0] = 3000;
  m.axis[0].offset_um_per_K[0] = 2.0f;
  m.axis[0].slope_um_per_K_m[0] = -11.5f;
  m.axis[0].reach_mm = 500.0f;
  return m;
}

class ThermalTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ChannelConfig c;
    c.source = ChannelSource::kCanObject;
    c.timeout_ms = 60000;     // the tests drive the channel states by readings
    c.max_rate_cC_s = 10000;  // 100 K/s: the tests step temperatures from one period to the next
    for (uint8_t j = 0; j < 2; ++j) ASSERT_TRUE(channels_.Configure(j, c, 0).ok());
  }
  // Readings of channels 0 and 1 at now_, then one Update().
  void Step(int16_t t0_cC, int16_t t1_cC = 2000) {
    now_ += kPeriodMs;
    ASSERT_TRUE(channels_.Reading(0, t0_cC, now_).ok());
    ASSERT_TRUE(channels_.Reading(1, t1_cC, now_).ok());
    thermal_.Update(channels_);
  }
  // Largest change of the applied correction anywhere on +-reach over `updates` Update()s.
  float WorstChange(int updates, int16_t t0_cC, float reach_mm = 500) {
    float worst = 0;
    for (int i = 0; i < updates; ++i) {
      const float lo = thermal_.CorrectionAt_um(0, -reach_mm);
      const float hi = thermal_.CorrectionAt_um(0, reach_mm);
      Step(t0_cC);
      worst = std::max({worst, std::fabs(thermal_.CorrectionAt_um(0, -reach_mm) - lo),
                        std::fabs(thermal_.CorrectionAt_um(0, reach_mm) - hi)});
    }
    return worst;
  }
  TemperatureChannels channels_;
  ThermalCorrection thermal_;
  uint32_t now_ = 0;
};

TEST(ThermalModelTest, ValidationRefusesWhatCannotBeApplied) {
  EXPECT_TRUE(ValidateThermalModel(OneChannelModel()).ok());
  auto refused = [](auto change) {
    ThermalModel m = OneChannelModel();
    change(m);
    return ValidateThermalModel(m).error();
  };
  EXPECT_EQ(refused([](ThermalModel& m) { m.axis_count = 0; }), Error::kThermalBadAxisCount);
  EXPECT_EQ(refused([](ThermalModel& m) { m.axis_count = 7; }), Error::kThermalBadAxisCount);
  constexpr Error kBad = Error::kThermalBadModel;
  EXPECT_EQ(refused([](ThermalModel& m) { m.axis[0].offset_um_per_K[1] = 1; }), kBad);  // mask
  EXPECT_EQ(refused([](ThermalModel& m) { m.axis[1].offset_um_per_K[0] = 1; }), kBad);  // axis 2
  EXPECT_EQ(refused([](ThermalModel& m) { m.axis[0].slope_um_per_K_m[0] = NAN; }), kBad);
  EXPECT_EQ(refused([](ThermalModel& m) { m.axis[0].offset_um_per_K[0] = INFINITY; }), kBad);
  EXPECT_EQ(refused([](ThermalModel& m) { m.axis[0].offset_um_per_K[0] = 1000.1f; }), kBad);
  EXPECT_EQ(refused([](ThermalModel& m) { m.axis[0].offset_um_per_K[0] = -1000; }), Error::kOk);
  EXPECT_EQ(refused([](ThermalModel& m) { m.calibrated_low_cC[3] = 1; }), kBad);  // low > high
  EXPECT_EQ(refused([](ThermalModel& m) { m.slew_um_s = 0; }), kBad);
  EXPECT_EQ(refused([](ThermalModel& m) { m.slew_um_s = 1000; }), Error::kOk);
  EXPECT_EQ(refused([](ThermalModel& m) { m.slew_um_s = 1001; }), kBad);
  EXPECT_EQ(refused([](ThermalModel& m) { m.hold_ms = 3600001; }), kBad);
  EXPECT_EQ(refused([](ThermalModel& m) { m.axis[0].reach_mm = -1; }), kBad);
  EXPECT_EQ(refused([](ThermalModel& m) { m.axis[5].p0_mm = 2e6f; }), kBad);
  ThermalCorrection t;
  EXPECT_EQ(t.Configure(OneChannelModel(), 0).error(), Error::kInvalidArgument);
  EXPECT_EQ(t.Configure(OneChannelModel(), 1001).error(), Error::kInvalidArgument);
  EXPECT_FALSE(t.status().active);
}

TEST_F(ThermalTest, OffsetAndSlopeFromTheRise) {
  ThermalModel m = OneChannelModel();
  m.slew_um_s = 1000;  // 100 um per update: the applied terms reach the model at once
  ASSERT_TRUE(thermal_.Configure(m, kPeriodMs).ok());
  Step(2500);                                                           // 5 K above the reference
  EXPECT_FLOAT_EQ(thermal_.model_offset_um(0), 10.0f);                  // 2 um/K * 5 K
  EXPECT_FLOAT_EQ(thermal_.model_slope_um_per_mm(0), -0.0575f);         // -11.5 um/(K m) * 5 K
  EXPECT_NEAR(thermal_.CorrectionAt_um(0, 400.0f), 10.0 - 23.0, 1e-4);  // -57.5 um/m * 0.4 m
  EXPECT_FALSE(thermal_.status().slewing);
}

TEST_F(ThermalTest, TwoChannelsTwoAxesAddUp) {
  ThermalModel m;
  m.axis_count = 2;
  m.channel_mask = 0x03;
  m.reference_cC[0] = 2000;
  m.reference_cC[1] = 2200;
  for (int j = 0; j < 2; ++j) {
    m.calibrated_low_cC[j] = -1000;
    m.calibrated_high_cC[j] = 6000;
  }
  m.axis[0].offset_um_per_K[0] = 1.5f;
  m.axis[0].offset_um_per_K[1] = -0.5f;
  m.axis[1].slope_um_per_K_m[1] = 20.0f;
  m.axis[1].p0_mm = 100.0f;
  m.slew_um_s = 1000;  // 100 um per period: the model at once
  ASSERT_TRUE(thermal_.Configure(m, kPeriodMs).ok());
  Step(2400, 3200);                                                      // rises 4 K and 10 K
  EXPECT_FLOAT_EQ(thermal_.applied_offset_um(0), 1.5f * 4 - 0.5f * 10);  // 1 um
  EXPECT_FLOAT_EQ(thermal_.applied_slope_um_per_mm(0), 0.0f);
  EXPECT_FLOAT_EQ(thermal_.applied_offset_um(1), 0.0f);
  EXPECT_FLOAT_EQ(thermal_.applied_slope_um_per_mm(1), 0.2f);         // 200 um/m
  EXPECT_NEAR(thermal_.CorrectionAt_um(1, 350.0f), 0.2 * 250, 1e-4);  // 250 mm past p0
}

TEST_F(ThermalTest, NeverFasterThanTheSlewLimitAnywhereOnTheTravel) {
  ASSERT_TRUE(thermal_.Configure(OneChannelModel(), kPeriodMs).ok());  // 1 um/s: 0.1 um a period
  Step(2500);
  EXPECT_TRUE(thermal_.status().slewing);
  // Worst point at the end of the travel: |10| + |0.0575| * 500 = 38.75 um to go at 0.1 um per
  // period: 388 periods.
  EXPECT_LE(WorstChange(386, 2500), 0.1f + 1e-5f);
  EXPECT_TRUE(thermal_.status().slewing);
  EXPECT_LE(WorstChange(2, 2500), 0.1f + 1e-5f);
  EXPECT_FALSE(thermal_.status().slewing);
  EXPECT_NEAR(thermal_.applied_offset_um(0), 10.0, 1e-3);
  EXPECT_NEAR(thermal_.applied_slope_um_per_mm(0), -0.0575, 1e-6);
}

TEST_F(ThermalTest, AChannelFaultHoldsThenFadesOutAtTheSlewLimit) {
  ThermalModel m = OneChannelModel();
  m.axis[0].slope_um_per_K_m[0] = 0;  // offset only: 10 um at 25 C, 100 periods to reach it
  m.hold_ms = 5000;
  ASSERT_TRUE(thermal_.Configure(m, kPeriodMs).ok());
  for (int i = 0; i < 100; ++i) Step(2500);
  ASSERT_NEAR(thermal_.applied_offset_um(0), 10.0, 1e-3);
  // The sensor opens: out of range from the next reading on.
  Step(kNoReading_cC);
  EXPECT_TRUE(thermal_.status().holding);
  EXPECT_EQ(thermal_.status().fault_mask, 0x01);
  EXPECT_NEAR(thermal_.applied_offset_um(0), 10.0, 1e-3);
  for (int i = 1; i < 50; ++i) Step(kNoReading_cC);  // 5 s of hold in all
  EXPECT_TRUE(thermal_.status().holding);
  EXPECT_NEAR(thermal_.applied_offset_um(0), 10.0, 1e-3);
  EXPECT_LE(WorstChange(1, kNoReading_cC), 0.1f + 1e-5f);  // the hold time is over: fading
  EXPECT_TRUE(thermal_.status().fading);
  EXPECT_NEAR(thermal_.applied_offset_um(0), 9.9, 1e-3);
  EXPECT_LE(WorstChange(99, kNoReading_cC), 0.1f + 1e-5f);
  EXPECT_NEAR(thermal_.applied_offset_um(0), 0.0, 1e-3);
  // The sensor is back: three good readings, then the correction returns at the slew limit.
  EXPECT_LE(WorstChange(3, 2500), 0.1f + 1e-5f);
  EXPECT_FALSE(thermal_.status().holding);
  EXPECT_FALSE(thermal_.status().fading);
  EXPECT_NEAR(thermal_.applied_offset_um(0), 0.1, 1e-3);
}

TEST_F(ThermalTest, BeforeTheFirstReadingTheCorrectionStaysAtZero) {
  ASSERT_TRUE(thermal_.Configure(OneChannelModel(), kPeriodMs).ok());
  thermal_.Update(channels_);  // channels waiting
  EXPECT_TRUE(thermal_.status().holding);
  EXPECT_EQ(thermal_.status().fault_mask, 0);  // waiting is not a fault
  EXPECT_EQ(thermal_.applied_offset_um(0), 0.0f);
}

TEST_F(ThermalTest, OutsideTheCalibratedRangeTheModelStopsAtItsEdge) {
  ThermalModel m = OneChannelModel();
  m.slew_um_s = 1000;  // 100 um per period: the model at once
  ASSERT_TRUE(thermal_.Configure(m, kPeriodMs).ok());
  Step(3000);  // the edge: 10 K, 20 um
  EXPECT_EQ(thermal_.status().outside_mask, 0);
  EXPECT_FLOAT_EQ(thermal_.applied_offset_um(0), 20.0f);
  Step(3050);  // 0.5 K above the calibrated range: held at the edge, flagged
  EXPECT_EQ(thermal_.status().outside_mask, 0x01);
  EXPECT_FLOAT_EQ(thermal_.applied_offset_um(0), 20.0f);
  Step(2990);
  EXPECT_EQ(thermal_.status().outside_mask, 0);
  EXPECT_NEAR(thermal_.applied_offset_um(0), 19.8, 1e-4);
}

TEST_F(ThermalTest, ClearFadesOutAndANewModelNeverJumps) {
  ThermalModel m = OneChannelModel();
  m.slew_um_s = 1000;  // 100 um per period: the model at once
  ASSERT_TRUE(thermal_.Configure(m, kPeriodMs).ok());
  Step(2500);
  const float at_300 = thermal_.CorrectionAt_um(0, 300);
  // A new model with another p0: the applied correction is the same everywhere until it slews.
  ThermalModel moved = m;
  moved.axis[0].p0_mm = -200;
  moved.axis[0].reach_mm = 700;  // the travel +-500 seen from p0
  moved.slew_um_s = 1.0f;
  ASSERT_TRUE(thermal_.Configure(moved, kPeriodMs).ok());
  EXPECT_NEAR(thermal_.CorrectionAt_um(0, 300), at_300, 1e-4);
  EXPECT_NEAR(thermal_.CorrectionAt_um(0, -450), 10 - 0.0575 * -450, 1e-3);
  thermal_.Clear();
  EXPECT_FALSE(thermal_.status().active);
  EXPECT_LE(WorstChange(50, 2500), 0.1f + 1e-5f);
  EXPECT_GT(std::fabs(thermal_.applied_offset_um(0)), 0.1f);  // still on its way out
  WorstChange(1000, 2500);
  EXPECT_NEAR(thermal_.CorrectionAt_um(0, 500), 0.0, 1e-3);
  EXPECT_NEAR(thermal_.CorrectionAt_um(0, -500), 0.0, 1e-3);
}

}  // namespace
}  // namespace volcomp::thermal
