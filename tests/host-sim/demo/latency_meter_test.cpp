// The latency meter on hand-made input and output sequences with known latencies.
#include "volcomp/sim/latency_meter.hpp"

#include <gtest/gtest.h>

namespace volcomp::sim {
namespace {

TEST(SimLatencyMeter, PairsInputAndOutputStepsInOrder) {
  LatencyMeter m(20000);
  m.OnInput(0, 1000, 1, 1);
  m.OnInput(0, 11000, 1, 2);
  m.OnInput(0, 19000, 1, 3);
  // Tick at 20 us: output pulses at 21, 28, 35 us (drive position 1..3, correction 0).
  m.OnOutput(0, 21000, 1);
  m.OnOutput(0, 28000, 2);
  m.OnOutput(0, 35000, 3);
  m.EndOfTick(0, 20000, 3);
  const LatencySummary s = m.Summarize();
  EXPECT_EQ(s.samples, 3u);
  EXPECT_DOUBLE_EQ(s.max_ticks, 20000.0 / 20000);  // 1000 -> 21000
  EXPECT_NEAR(s.mean_ticks, (20000.0 + 17000 + 16000) / 3 / 20000, 1e-12);
  EXPECT_EQ(s.over_2_ticks, 0u);
  EXPECT_EQ(s.unmatched, 0u);
}

TEST(SimLatencyMeter, CorrectionShiftsWhatAnOutputServesAndNegativeSteps) {
  LatencyMeter m(20000);
  // Axis 1 moves down: commanded 0 -> -1 -> -2; the board adds a correction of +5 steps.
  m.OnInput(1, 100, -1, -1);
  m.OnInput(1, 200, -1, -2);
  // The world passes served = drive position - correction: 4 - 5 = -1, then 3 - 5 = -2.
  m.OnOutput(1, 20500, 4 - 5);
  m.OnOutput(1, 60000, 3 - 5);  // two ticks later: 59.8 us = 2.99 ticks
  m.EndOfTick(1, 60000, 3 - 5);
  const LatencySummary s = m.Summarize();
  EXPECT_EQ(s.samples, 2u);
  EXPECT_NEAR(s.max_ticks, 59800.0 / 20000, 1e-12);
  EXPECT_EQ(s.over_2_ticks, 1u);
}

TEST(SimLatencyMeter, AbsorbedStepsAndStaleSteps) {
  LatencyMeter m(20000);
  m.OnInput(2, 5000, 1, 1);
  // The correction dropped by one step in the same tick: no pulse, served = 1 at the tick.
  m.EndOfTick(2, 20000, 1);
  m.OnInput(2, 30000, 1, 2);  // never served
  m.EndOfTick(2, 40000, 1);
  m.EndOfTick(2, 30000 + 1001 * 20000, 1);
  const LatencySummary s = m.Summarize();
  EXPECT_EQ(s.samples, 1u);
  EXPECT_NEAR(s.max_ticks, 15000.0 / 20000, 1e-12);
  EXPECT_EQ(s.unmatched, 1u);
}

TEST(SimLatencyMeter, PercentilesFromTheHistogram) {
  LatencyMeter m(10000);
  // 1000 steps with latencies 0.1, 0.2, ... in ticks cycling over 10 values (0.1 .. 1.0 tick).
  for (int i = 0; i < 1000; ++i) {
    const uint64_t t_in = static_cast<uint64_t>(i) * 100000;
    const uint64_t lat = static_cast<uint64_t>(i % 10 + 1) * 1000;
    m.OnInput(0, t_in, 1, i + 1);
    m.OnOutput(0, t_in + lat, i + 1);
  }
  const LatencySummary s = m.Summarize();
  EXPECT_EQ(s.samples, 1000u);
  EXPECT_NEAR(s.p50_ticks, 0.51, 0.011);  // the 500th value is 0.5 tick, reported bin's upper edge
  EXPECT_NEAR(s.p90_ticks, 0.91, 0.011);
  EXPECT_DOUBLE_EQ(s.max_ticks, 1.0);
  EXPECT_NEAR(s.mean_ticks, 0.55, 1e-12);
}

}  // namespace
}  // namespace volcomp::sim
