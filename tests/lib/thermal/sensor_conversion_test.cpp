// ADC sensor conversions against outside truths: the IEC 60751 Pt100 reference table (resistance
// at each temperature as the standard prints it, 0.01 ohm), the NTC beta model evaluated forward
// with libm's exp (the code inverts it with its own logarithm), libm's log for Ln().
#include "volcomp/thermal/sensor_conversion.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace volcomp::thermal {
namespace {

TEST(LnTest, MatchesLibmFromMilliOhmsToMegaOhms) {
  double worst = 0;
  for (double x = 1e-3; x < 1e7; x *= 1.0137) {
    const float xf = static_cast<float>(x);
    const double want = std::log(static_cast<double>(xf));
    worst = std::max(worst, std::fabs(Ln(xf) - want));
  }
  EXPECT_LT(worst, 2e-6);  // float: ln(1e7) = 16.1, 2e-6 is ~1.5 ulp there
  EXPECT_FLOAT_EQ(Ln(1.0f), 0.0f);
  EXPECT_LT(Ln(0.0f), -1e29f);
  EXPECT_LT(Ln(-5.0f), -1e29f);
}

// IEC 60751, Pt100 reference table (ohm at degrees C); a PT1000 is ten times these.
struct TableRow {
  double celsius;
  double pt100_ohm;
};
constexpr TableRow kIec60751[] = {
    {-50, 80.31}, {-40, 84.27}, {-30, 88.22}, {-20, 92.16},  {-10, 96.09},  {0, 100.00},
    {10, 103.90}, {20, 107.79}, {30, 111.67}, {40, 115.54},  {50, 119.40},  {60, 123.24},
    {70, 127.08}, {80, 130.90}, {90, 134.71}, {100, 138.51}, {150, 157.33}, {200, 175.86},
};

TEST(PlatinumTest, ReadsTheIec60751Table) {
  for (const TableRow& row : kIec60751) {
    SCOPED_TRACE(row.celsius);
    // The table's 0.005 ohm rounding is 0.013 K at 0.385 ohm/K; 2 cC covers it and our rounding.
    EXPECT_NEAR(PlatinumCelsius_cC(static_cast<float>(row.pt100_ohm * 10), Pt1000Params()),
                row.celsius * 100, 2);
    Pt1000Params pt100;
    pt100.r0_ohm = 100;
    EXPECT_NEAR(PlatinumCelsius_cC(static_cast<float>(row.pt100_ohm), pt100), row.celsius * 100, 2);
  }
}

TEST(PlatinumTest, OutsideTheStandardsRangeOrInt16IsNoReading) {
  EXPECT_EQ(PlatinumCelsius_cC(0.0f, Pt1000Params()), kNoReading_cC);
  EXPECT_EQ(PlatinumCelsius_cC(-1.0f, Pt1000Params()), kNoReading_cC);
  EXPECT_EQ(PlatinumCelsius_cC(150.0f, Pt1000Params()), kNoReading_cC);   // below -200 C
  EXPECT_EQ(PlatinumCelsius_cC(3000.0f, Pt1000Params()), kNoReading_cC);  // ~+560 C > 327 C
}

double NtcOhmsAt(double celsius, const NtcParams& p) {  // the beta model, forward
  return p.r0_ohm * std::exp(p.beta_k * (1.0 / (celsius + 273.15) - 1.0 / (p.t0_c + 273.15)));
}

TEST(NtcTest, InvertsTheBetaModelOverAMachinesRange) {
  for (const NtcParams& p :
       {NtcParams(), NtcParams{10000.0f, 3435.0f, 25.0f}, NtcParams{100000.0f, 4250.0f, 25.0f}}) {
    for (double c = -20; c <= 90; c += 0.37) {
      SCOPED_TRACE(c);
      EXPECT_NEAR(NtcCelsius_cC(static_cast<float>(NtcOhmsAt(c, p)), p), c * 100, 1.0);
    }
  }
  EXPECT_EQ(NtcCelsius_cC(10000.0f, NtcParams()), 2500);  // R0 is t0 exactly
  EXPECT_EQ(NtcCelsius_cC(0.0f, NtcParams()), kNoReading_cC);
  EXPECT_EQ(NtcCelsius_cC(1.0f, NtcParams()), kNoReading_cC);  // shorted: ~ +600 C
}

TEST(DividerTest, ResistanceFromCountsAndTheRails) {
  const DividerInput d;  // 16-bit, 10 kOhm reference
  // 1 kOhm sensor: counts = 65536 * 1000 / 11000 = 5957.8
  EXPECT_NEAR(SensorOhms(5958, d), 1000.0, 0.5);
  // margin 65536 * 5 / 1000 = 327 counts at either end
  EXPECT_LT(SensorOhms(327, d), 0.0f);
  EXPECT_GT(SensorOhms(328, d), 0.0f);
  EXPECT_LT(SensorOhms(65209, d), 0.0f);
  EXPECT_GT(SensorOhms(65208, d), 0.0f);
  EXPECT_LT(SensorOhms(70000, d), 0.0f);
}

TEST(DividerTest, AnOpenNtcIsNoReadingEndToEnd) {
  const DividerInput d;
  EXPECT_EQ(NtcCelsius_cC(SensorOhms(65535, d), NtcParams()), kNoReading_cC);  // open
  EXPECT_EQ(NtcCelsius_cC(SensorOhms(0, d), NtcParams()), kNoReading_cC);      // shorted
}

TEST(DividerTest, APt1000ResolvesAboutFiveHundredthsOfAKelvinPerCount) {
  // 20 C: 1077.9 ohm -> 65536 * 1077.9 / 11077.9 = 6376.8 counts. One count there is
  // 10000 * 65536 / (65536 - 6377)^2 = 0.187 ohm, and the PT1000 changes by 3.885 ohm/K at 20 C:
  // 0.048 K per count.
  const DividerInput d;
  const int16_t a = PlatinumCelsius_cC(SensorOhms(6377, d), Pt1000Params());
  const int16_t b = PlatinumCelsius_cC(SensorOhms(6378, d), Pt1000Params());
  EXPECT_NEAR(a, 2000, 5);
  EXPECT_GE(b - a, 4);
  EXPECT_LE(b - a, 6);
}

TEST(AdcAveragerTest, OneMeanPerWindowRounded) {
  AdcAverager avg(4);
  uint32_t mean = 0;
  EXPECT_FALSE(avg.Add(10, &mean));
  EXPECT_FALSE(avg.Add(11, &mean));
  EXPECT_FALSE(avg.Add(11, &mean));
  EXPECT_TRUE(avg.Add(11, &mean));
  EXPECT_EQ(mean, 11u);  // 43 / 4 = 10.75
  EXPECT_FALSE(avg.Add(1, &mean));
  EXPECT_EQ(mean, 11u);  // untouched until the next window completes
  avg.Add(2, &mean);
  avg.Add(2, &mean);
  EXPECT_TRUE(avg.Add(2, &mean));
  EXPECT_EQ(mean, 2u);  // 7 / 4 = 1.75
  AdcAverager one(0);   // 0 is taken as 1
  EXPECT_TRUE(one.Add(7, &mean));
  EXPECT_EQ(mean, 7u);
}

}  // namespace
}  // namespace volcomp::thermal
