// Board-local sensors on ADC inputs (docs/thermal.md "Board-local sensors"): the chain from the
// ADC's oversampled counts to a channel's reading, against the sensors' published R-T tables, and
// the path into the temperature channels (BoardThermal pulls readings from
// hal::TemperatureInputs every period) including the channels no input feeds.
//
// Counts are made from a table's resistance with the divider's definition (counts / 65536 =
// R / (R + R_ref)), independently of the code under test.
#include "volcomp/firmware/adc_temperature_inputs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "volcomp/config/board_settings.hpp"
#include "volcomp/control/compensator.hpp"
#include "volcomp/firmware/board_thermal.hpp"

namespace volcomp::firmware {
namespace {

using thermal::ChannelSource;
using thermal::ChannelState;

// The ideal ADC's counts (mean code x 16) for a sensor of `ohms` under the 10 k reference.
uint16_t CountsFor(double ohms) {
  return static_cast<uint16_t>(std::lround(65536.0 * ohms / (ohms + 10000.0)));
}

// Murata NCP18XH103F03RB (10 k, B25/50 3380 K), the maker's R-T table (kOhm): the beta model
// is an approximation of it; its error is the documented bound per temperature band.
TEST(AdcTemperatureInputs, NtcReadingsFollowTheMakersTable) {
  struct Point {
    double t_c, kohm, tolerance_k;
  };
  const Point table[] = {
      {0, 27.219, 0.85}, {10, 17.926, 0.45}, {20, 12.081, 0.15}, {25, 10.000, 0.02},
      {30, 8.315, 0.15}, {40, 5.834, 0.15},  {50, 4.161, 0.15},  {60, 3.014, 0.35},
      {70, 2.228, 0.60}, {85, 1.452, 1.25},
  };
  for (const Point& p : table) {
    const int16_t cC =
        AdcTemperatureInputs::Convert(CountsFor(p.kohm * 1000.0), ChannelSource::kBoardNtc);
    EXPECT_NEAR(cC / 100.0, p.t_c, p.tolerance_k) << p.t_c << " C";
  }
}

// PT1000 = IEC 60751's Pt100 table x 10 (ohm); 16-bit counts under 10 k resolve 0.05 K.
TEST(AdcTemperatureInputs, Pt1000ReadingsFollowIec60751) {
  struct Point {
    double t_c, pt100_ohm;
  };
  const Point table[] = {{-20, 92.16}, {-10, 96.09}, {0, 100.00},  {10, 103.90},
                         {20, 107.79}, {30, 111.67}, {40, 115.54}, {50, 119.40},
                         {60, 123.24}, {80, 130.90}, {100, 138.51}};
  for (const Point& p : table) {
    const int16_t cC =
        AdcTemperatureInputs::Convert(CountsFor(p.pt100_ohm * 10.0), ChannelSource::kBoardPt1000);
    EXPECT_NEAR(cC / 100.0, p.t_c, 0.05) << p.t_c << " C";
  }
}

TEST(AdcTemperatureInputs, OpenAndShortedInputsHaveNoReading) {
  // Open sensor: the node at VREF+ (full scale); shorted: at ground. Both rails, and 0.4 % from
  // them (inside the 0.5 % margin).
  for (uint32_t counts : {65535u, 65300u, 0u, 200u}) {
    EXPECT_EQ(AdcTemperatureInputs::Convert(counts, ChannelSource::kBoardNtc),
              thermal::kNoReading_cC)
        << counts;
    EXPECT_EQ(AdcTemperatureInputs::Convert(counts, ChannelSource::kBoardPt1000),
              thermal::kNoReading_cC)
        << counts;
  }
  EXPECT_EQ(AdcTemperatureInputs::Convert(32768, ChannelSource::kLinuxFile),
            thermal::kNoReading_cC);
}

TEST(AdcTemperatureInputs, OneReadingPerWindowAveragedPerInput) {
  AdcTemperatureInputs in;
  int16_t v = 0;
  // Input 0 alternates between two counts (a hum sampled twice a period): the mean is taken.
  uint16_t a[kAdcSensorInputs] = {30000, CountsFor(1077.9), 100, 65535};
  uint16_t b[kAdcSensorInputs] = {36000, CountsFor(1077.9), 100, 65535};
  for (int i = 0; i < kAdcScansPerReading - 1; ++i) in.AddScan(i % 2 == 0 ? a : b);
  EXPECT_FALSE(in.Take(0, ChannelSource::kBoardNtc, &v));  // the window is not complete
  in.AddScan(b);
  EXPECT_EQ(in.mean_counts(0), 33000u);
  ASSERT_TRUE(in.Take(0, ChannelSource::kBoardNtc, &v));
  for (int i = 0; i < 40; ++i) in.AddScan(a);  // the later inputs' first windows (staggered)
  ASSERT_TRUE(in.Take(1, ChannelSource::kBoardPt1000, &v));
  EXPECT_NEAR(v / 100.0, 20.0, 0.05);
  EXPECT_FALSE(in.Take(1, ChannelSource::kBoardPt1000, &v));  // once per window
  ASSERT_TRUE(in.Take(2, ChannelSource::kBoardNtc, &v));      // shorted input
  EXPECT_EQ(v, thermal::kNoReading_cC);
  // No file and no fifth input on this board: never a reading.
  EXPECT_FALSE(in.Take(3, ChannelSource::kLinuxFile, &v));
  EXPECT_FALSE(in.Take(4, ChannelSource::kBoardNtc, &v));
  EXPECT_FALSE(in.Take(7, ChannelSource::kBoardPt1000, &v));
}

// The inputs' windows end at least 12 scans (120 ms at 100 scans/s) apart: a thermal period
// (10 scans) converts at most one reading.
TEST(AdcTemperatureInputs, WindowsAreStaggered) {
  AdcTemperatureInputs in;
  const uint16_t counts[kAdcSensorInputs] = {30000, 30000, 30000, 30000};
  int last = -100, ended = 0;
  for (int scan = 1; scan <= 10 * kAdcScansPerReading; ++scan) {
    in.AddScan(counts);
    int16_t v;
    int fresh = 0;
    for (uint8_t ch = 0; ch < kAdcSensorInputs; ++ch)
      fresh += in.Take(ch, ChannelSource::kBoardNtc, &v);
    if (fresh == 0) continue;
    EXPECT_EQ(fresh, 1) << scan;
    EXPECT_GE(scan - last, 12) << scan;
    last = scan;
    ++ended;
  }
  EXPECT_GE(ended, 4 * 9);  // every input a reading every 50 scans
}

// BoardThermal takes the board's readings every period: channels on ADC inputs become valid with
// the sensors' temperatures at 2 readings per second; a channel whose source the board does not
// have (a Linux file on this board, an NTC on a fifth input) and every board-sensor channel of a
// board without sensors stay waiting, then go stale: flagged, never valid.
class BoardSensorPath : public ::testing::Test {
 protected:
  void Start() {
    BoardSettings s;
    s.temperature[0].source = ChannelSource::kBoardNtc;
    s.temperature[1].source = ChannelSource::kBoardPt1000;
    s.temperature[2].source = ChannelSource::kLinuxFile;
    s.temperature[5].source = ChannelSource::kBoardNtc;
    thermal_.Start(s, &compensator_, 0);
  }
  // `ms` of main loop: 100 scans per second into the inputs, a Poll() every 10 ms.
  void Run(uint32_t ms, hal::TemperatureInputs* sensors) {
    const uint16_t counts[kAdcSensorInputs] = {CountsFor(10000.0), CountsFor(1077.9), 0, 0};
    for (uint32_t t = 0; t < ms; t += 10) {
      now_ms_ += 10;
      inputs_.AddScan(counts);
      thermal_.Poll(now_ms_, sensors);
    }
  }
  Compensator compensator_;
  BoardThermal thermal_;
  AdcTemperatureInputs inputs_;
  uint32_t now_ms_ = 0;
};

TEST_F(BoardSensorPath, AdcChannelsBecomeValidAndChannelsWithoutAnInputGoStale) {
  Start();
  Run(400, &inputs_);  // the first window ends at 500 ms (input 1's at 620 ms)
  EXPECT_EQ(thermal_.channels().state(0), ChannelState::kWaiting);
  Run(300, &inputs_);
  EXPECT_EQ(thermal_.channels().state(0), ChannelState::kValid);
  EXPECT_EQ(thermal_.channels().value_cC(0), 2500);  // R25 of the NTC
  EXPECT_EQ(thermal_.channels().state(1), ChannelState::kValid);
  EXPECT_NEAR(thermal_.channels().value_cC(1) / 100.0, 20.0, 0.05);  // 1077.9 ohm
  EXPECT_EQ(thermal_.channels().state(2), ChannelState::kWaiting);
  EXPECT_EQ(thermal_.channels().state(5), ChannelState::kWaiting);
  Run(10000, &inputs_);  // 20 readings later: still valid (2 per second, timeout 1.5 s)
  EXPECT_EQ(thermal_.channels().state(0), ChannelState::kValid);
  EXPECT_EQ(thermal_.channels().state(1), ChannelState::kValid);
  EXPECT_EQ(thermal_.channels().state(2), ChannelState::kStale);
  EXPECT_EQ(thermal_.channels().state(5), ChannelState::kStale);
  EXPECT_EQ(thermal_.channels().state(3), ChannelState::kUnused);
}

TEST_F(BoardSensorPath, WithoutSensorsBoardChannelsGoStale) {
  Start();
  Run(1000, nullptr);
  EXPECT_EQ(thermal_.channels().state(0), ChannelState::kWaiting);
  Run(700, nullptr);  // past the 1.5 s timeout
  EXPECT_EQ(thermal_.channels().state(0), ChannelState::kStale);
  EXPECT_EQ(thermal_.channels().state(1), ChannelState::kStale);
  EXPECT_NE(thermal_.channel_fault_mask() & 0x03, 0);
}

TEST_F(BoardSensorPath, AnOpenSensorIsOutOfRange) {
  Start();
  Run(600, &inputs_);
  ASSERT_EQ(thermal_.channels().state(0), ChannelState::kValid);
  const uint16_t open[kAdcSensorInputs] = {65535, CountsFor(1077.9), 0, 0};
  for (int i = 0; i < 2 * kAdcScansPerReading; ++i) {  // a whole window of an open input
    now_ms_ += 10;
    inputs_.AddScan(open);
    thermal_.Poll(now_ms_, &inputs_);
  }
  EXPECT_EQ(thermal_.channels().state(0), ChannelState::kOutOfRange);
  EXPECT_EQ(thermal_.channels().value_cC(0), 2500);  // held
}

}  // namespace
}  // namespace volcomp::firmware
