// StepGenerator: the drive timing in pulse-clock units, pulse plans worked by hand, and a long
// random run checked edge by edge by the drive-side timing checker (hal/mock DriveModel).
#include "volcomp/output/step_generator.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "volcomp/hal/mock/drive_model.hpp"

namespace volcomp {
namespace {

// At a 1 MHz pulse clock one unit is 1 us: width 2 us + space 3 us = 5, 100 kHz = 10 units a step,
// setup 4, hold 6; a 1 kHz tick is 1000 units and carries 100 pulses.
AxisConfig HandAxis() {
  AxisConfig ax;
  ax.output_format = PulseFormat::kStepDir;
  ax.drive = {2000, 3000, 4000, 6000, 100000};  // width, space, setup, hold (ns), max rate (Hz)
  return ax;
}
constexpr uint32_t kTickHz = 1000;
constexpr uint32_t kClockHz = 1000000;

TEST(PulseTiming, ConvertsTheDriveTimingToClockUnits) {
  const Result<PulseTiming> t = PulseTiming::FromDrive(HandAxis(), kTickHz, kClockHz);
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(t->tick, 1000u);
  EXPECT_EQ(t->width, 2u);
  EXPECT_EQ(t->setup, 4u);
  EXPECT_EQ(t->hold, 6u);
  EXPECT_EQ(t->min_period, 10u);  // max(2 + 3, 1e6 / 1e5)
  EXPECT_EQ(t->max_per_tick, 100u);

  AxisConfig ax = HandAxis();
  ax.drive = {1500, 100, 10, 0, 400000};  // rounded up: 2, 1, 1, 0; width + space 3 = rate 3
  const Result<PulseTiming> up = PulseTiming::FromDrive(ax, kTickHz, kClockHz);
  ASSERT_TRUE(up.ok());
  EXPECT_EQ(up->width, 2u);
  EXPECT_EQ(up->setup, 1u);
  EXPECT_EQ(up->hold, 0u);
  EXPECT_EQ(up->min_period, 3u);
  EXPECT_EQ(up->max_per_tick, 256u);  // 333 fit, capped at kMaxPulsesPerTick

  ax.output_format = PulseFormat::kQuadrature;  // a step is one edge: no width, no space
  const Result<PulseTiming> q = PulseTiming::FromDrive(ax, kTickHz, kClockHz);
  ASSERT_TRUE(q.ok());
  EXPECT_EQ(q->width, 0u);
  EXPECT_EQ(q->min_period, 3u);  // ceil(1e6 / 4e5)
}

TEST(PulseTiming, RefusesWhatTheArithmeticCannotCarry) {
  AxisConfig ax = HandAxis();
  EXPECT_EQ(PulseTiming::FromDrive(ax, 0, kClockHz).error(), Error::kConfigInvalid);
  EXPECT_EQ(PulseTiming::FromDrive(ax, kClockHz + 1, kClockHz).error(), Error::kConfigInvalid);
  ax.drive.max_rate_hz = 0;
  EXPECT_EQ(PulseTiming::FromDrive(ax, kTickHz, kClockHz).error(), Error::kConfigInvalid);
  ax.drive.max_rate_hz = 999;  // a step period of 1002 units: the 1000-unit tick carries none
  EXPECT_EQ(PulseTiming::FromDrive(ax, kTickHz, kClockHz).error(), Error::kConfigInvalid);
  // Times of 2^29 pulse-clock units or more (here 1 GHz: 2^29 ns) do not fit the int32 times.
  ax = HandAxis();
  ax.drive.dir_setup_ns = (1u << 29) - 1;
  EXPECT_TRUE(PulseTiming::FromDrive(ax, kTickHz, 1000000000).ok());
  ax.drive.dir_setup_ns = 1u << 29;
  EXPECT_EQ(PulseTiming::FromDrive(ax, kTickHz, 1000000000).error(), Error::kConfigInvalid);
  ax = HandAxis();
  ax.drive.dir_hold_ns = 1u << 29;
  EXPECT_EQ(PulseTiming::FromDrive(ax, kTickHz, 1000000000).error(), Error::kConfigInvalid);
  StepGenerator gen;
  EXPECT_EQ(gen.Configure(ax, kTickHz, 1000000000).error(), Error::kConfigInvalid);
}

// n pulses spread evenly over the free window: period = floor(window * floor((2^32 - 1) / n) /
// 2^32), at least the minimum period.
TEST(StepGenerator, PlansWorkedByHand) {
  StepGenerator gen;
  ASSERT_TRUE(gen.Configure(HandAxis(), kTickHz, kClockHz).ok());
  EXPECT_EQ(gen.max_pulses_per_tick(), 100u);

  // 3 steps forward in the 1000-unit window: 333 apart (1000 / 3 = 333.3), from 0.
  PulsePlan p = gen.Plan(3);
  EXPECT_EQ(p.count, 3u);
  EXPECT_FALSE(p.negative);
  EXPECT_FALSE(p.dir_change);
  EXPECT_EQ(p.first_rise, 0u);
  EXPECT_EQ(p.period, 333u);
  EXPECT_EQ(p.width, 2u);
  EXPECT_EQ(gen.position(), 3);

  // Back to -1: 4 steps reverse. The last pulse fell at 668 (-332 now); the direction may change
  // 6 later, i.e. at once (0), and the first pulse follows the setup time: 4. Window 996 / 4 = 249
  // minus the truncations: 248.
  p = gen.Plan(-1);
  EXPECT_EQ(p.count, 4u);
  EXPECT_TRUE(p.negative);
  EXPECT_TRUE(p.dir_change);
  EXPECT_EQ(p.dir_edge, 0u);
  EXPECT_EQ(p.first_rise, 4u);
  EXPECT_EQ(p.period, 248u);
  EXPECT_EQ(gen.position(), -1);
  EXPECT_EQ(gen.backlog(-1), 0);

  // Nothing owed: no pulses.
  p = gen.Plan(-1);
  EXPECT_EQ(p.count, 0u);
  EXPECT_FALSE(p.dir_change);

  // 250 owed: a tick carries 100 (1000 / 10), at the minimum period (the even spread, 9.99,
  // would be faster than the drive allows); the rest stays owed.
  StepGenerator fast;
  ASSERT_TRUE(fast.Configure(HandAxis(), kTickHz, kClockHz).ok());
  uint32_t left = 0;
  PulsePlan q;
  left = fast.PlanTick(250, &q);
  EXPECT_EQ(q.count, 100u);
  EXPECT_EQ(q.period, 10u);
  EXPECT_EQ(left, 150u);
  EXPECT_EQ(fast.backlog(250), 150);
  left = fast.PlanTick(250, &q);
  EXPECT_EQ(q.first_rise, 0u);  // last rise at 990: the next may come at 1000 = 0 of this tick
  EXPECT_EQ(q.count, 100u);
  EXPECT_EQ(left, 50u);
  left = fast.PlanTick(250, &q);
  EXPECT_EQ(q.count, 50u);
  EXPECT_EQ(q.period, 19u);  // 1000 / 50 = 20 minus the truncations
  EXPECT_EQ(left, 0u);
  EXPECT_EQ(fast.position(), 250);
}

// A direction hold longer than the rest of the tick: the reversal and its pulses wait a tick.
TEST(StepGenerator, DirectionChangeWaitsForTheHoldTime) {
  AxisConfig ax = HandAxis();
  ax.drive.dir_hold_ns = 1500000;  // 1500 units
  StepGenerator gen;
  ASSERT_TRUE(gen.Configure(ax, kTickHz, kClockHz).ok());
  PulsePlan p = gen.Plan(5);  // rises 0, 199, 398, 597, 796 (1000 / 5 minus truncation), fall 798
  EXPECT_EQ(p.count, 5u);
  EXPECT_EQ(p.period, 199u);
  p = gen.Plan(4);  // the hold ends at 798 + 1500 = 2298 = 1298 of this tick: nothing fits
  EXPECT_EQ(p.count, 0u);
  EXPECT_FALSE(p.dir_change);
  EXPECT_EQ(gen.backlog(4), -1);
  p = gen.Plan(4);  // 298 of this tick: direction edge there, the pulse 4 (setup) later
  EXPECT_TRUE(p.dir_change);
  EXPECT_EQ(p.dir_edge, 298u);
  EXPECT_EQ(p.count, 1u);
  EXPECT_TRUE(p.negative);
  EXPECT_EQ(p.first_rise, 302u);
  EXPECT_EQ(gen.position(), 4);
}

TEST(StepGenerator, RespectsSlowDriveTimingAcrossDirectionChanges) {
  // A slow drive (Leadshine-like: 2.5 us width/space, 5 us setup, 10 us hold, 200 kHz): the
  // direction change does not fit one 20 us tick with pulses, so it waits.
  AxisConfig ax;
  ax.drive = {2500, 2500, 5000, 10000, 200000};
  StepGenerator gen;
  ASSERT_TRUE(gen.Configure(ax, 50000, 1000000000).ok());
  DriveTiming timing = ax.drive;
  hal::mock::DriveModel drive(PulseFormat::kStepDir, timing);
  bool dir_level = true;
  uint64_t t0 = 0;
  std::mt19937_64 rng(8);
  int32_t target = 0;
  for (int tick = 0; tick < 200000; ++tick, t0 += 20000) {
    if (tick % 7 == 0) target += static_cast<int32_t>(rng() % 9) - 4;
    const PulsePlan p = gen.Plan(target);
    if (p.dir_change) {
      dir_level = !p.negative;
      drive.OnEdge(t0 + p.dir_edge, true, dir_level);
    }
    for (uint32_t j = 0; j < p.count; ++j) {
      drive.OnEdge(t0 + p.first_rise + uint64_t{j} * p.period, false, true);
      drive.OnEdge(t0 + p.first_rise + uint64_t{j} * p.period + p.width, false, false);
    }
  }
  for (const auto& v : drive.violation_log()) ADD_FAILURE() << v;
  EXPECT_EQ(drive.violations(), 0u);
  EXPECT_EQ(drive.position() + gen.backlog(target), target);
  EXPECT_LE(std::abs(gen.backlog(target)), 8);
}

}  // namespace
}  // namespace volcomp
