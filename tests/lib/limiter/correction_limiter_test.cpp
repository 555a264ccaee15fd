// The correction limiter keeps velocity and acceleration within bounds and lands on the target.
#include "volcomp/limiter/correction_limiter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "volcomp/config/board_config.hpp"

namespace volcomp {
namespace {

constexpr double kQ32 = 4294967296.0;

// Runs `ticks` ticks toward target(t) and checks the limits from the positions alone.
struct Trace {
  double max_v = 0, max_a = 0;  // steps/tick, steps/tick^2
  int64_t final_pos = 0;
  int settle_tick = -1;
  double max_overshoot = 0;
};

template <class Target>
Trace RunLimiter(CorrectionLimiter& lim, int ticks, Target target) {
  Trace tr;
  int64_t prev = lim.position_q32();
  double prev_v = 0;
  for (int t = 0; t < ticks; ++t) {
    const int64_t goal = target(t);
    const int64_t p = lim.Step(goal);
    const double v = double(p - prev) / kQ32;
    tr.max_v = std::max(tr.max_v, std::fabs(v));
    tr.max_a = std::max(tr.max_a, std::fabs(v - prev_v));
    prev_v = v;
    prev = p;
    if (p == goal && tr.settle_tick < 0 && lim.at_rest()) tr.settle_tick = t;
  }
  tr.final_pos = prev;
  return tr;
}

TEST(CorrectionLimiter, MakeParamsConvertsUnits) {
  const auto p = CorrectionLimiter::MakeParams(50000, 2000, 200000);
  ASSERT_TRUE(p.ok());
  // a = 200000 / 50000^2 steps/tick^2 = 8e-5; k_max = v/a = (2000/50000)/8e-5 = 500.
  EXPECT_NEAR(p->accel_q32 / kQ32, 8e-5, 1e-9);
  EXPECT_EQ(p->max_k, 500u);
  EXPECT_EQ(CorrectionLimiter::MakeParams(50000, 0, 1).error(), Error::kConfigInvalid);
  EXPECT_EQ(CorrectionLimiter::MakeParams(200000, 1, 1).error(), Error::kConfigInvalid);  // a -> 0
  EXPECT_EQ(CorrectionLimiter::MakeParams(1000, 1, 1000000).error(), Error::kConfigInvalid);
}

// A limiter stepped every n ticks of f is a limiter at f / n: the same parameters, bit for bit,
// where f / n is a whole rate (its conversion computed the old way), and the factory limits
// (2000 steps/s, 200000 steps/s^2) valid at every tick rate a board accepts.
TEST(CorrectionLimiter, MakeParamsForEveryNthTickEqualsTheLowerRate) {
  for (uint32_t n : {1u, 2u, 3u, 7u, 10u}) {
    for (uint32_t f_low : {1000u, 16000u, 20000u}) {
      for (uint32_t rate : {1u, 2000u, 20000u, 4000000000u}) {
        for (uint32_t accel : {1u, 200000u, 2000000u, 399999999u}) {
          const auto every_nth = CorrectionLimiter::MakeParams(f_low * n, rate, accel, n);
          const auto low = CorrectionLimiter::MakeParams(f_low, rate, accel);
          ASSERT_EQ(every_nth.ok(), low.ok()) << n << " " << f_low << " " << rate << " " << accel;
          if (!low.ok()) continue;
          EXPECT_EQ(every_nth->accel_q32, low->accel_q32) << n << " " << f_low << " " << accel;
          EXPECT_EQ(every_nth->max_k, low->max_k) << n << " " << f_low << " " << rate;
        }
      }
    }
  }
  for (uint32_t tick_hz = kMinTickHz; tick_hz <= kMaxTickHz; tick_hz += 1000) {
    EXPECT_TRUE(
        CorrectionLimiter::MakeParams(tick_hz, 2000, 200000, CompensationDivider(tick_hz)).ok())
        << tick_hz;
  }
  EXPECT_EQ(CorrectionLimiter::MakeParams(50000, 2000, 200000, 0).error(), Error::kConfigInvalid);
}

TEST(CorrectionLimiter, StepChangeIsSpreadWithinLimitsAndLandsExactly) {
  const uint32_t tick_hz = 50000, rate = 2000, accel = 200000;
  const auto p = CorrectionLimiter::MakeParams(tick_hz, rate, accel);
  ASSERT_TRUE(p.ok());
  for (double jump_steps : {0.3, 1.0, 7.5, -40.0, 500.0}) {
    CorrectionLimiter lim(*p);
    const int64_t goal = static_cast<int64_t>(jump_steps * kQ32);
    const Trace tr = RunLimiter(lim, 200000, [&](int) { return goal; });
    EXPECT_EQ(tr.final_pos, goal) << jump_steps;
    EXPECT_LE(tr.max_v, double(rate) / tick_hz + 1e-12) << jump_steps;
    EXPECT_LE(tr.max_a, double(accel) / tick_hz / tick_hz + 1e-12) << jump_steps;
    ASSERT_GE(tr.settle_tick, 0);
    // Time-optimal bound: a triangle/trapezoid profile; allow 5 % + 2 ticks over the ideal.
    const double d = std::fabs(jump_steps), vmax = double(rate) / tick_hz,
                 a = double(accel) / tick_hz / tick_hz;
    const double ideal = d > vmax * vmax / a ? d / vmax + vmax / a : 2 * std::sqrt(d / a);
    EXPECT_LE(tr.settle_tick, ideal * 1.05 + 2) << jump_steps;
  }
}

TEST(CorrectionLimiter, NoOvershootOnAFixedTarget) {
  const auto p = CorrectionLimiter::MakeParams(50000, 5000, 1000000);
  CorrectionLimiter lim(*p);
  const int64_t goal = static_cast<int64_t>(123.456 * kQ32);
  for (int t = 0; t < 100000; ++t) {
    ASSERT_LE(lim.Step(goal), goal) << t;
  }
  EXPECT_EQ(lim.position_q32(), goal);
}

TEST(CorrectionLimiter, TracksAMovingTargetWithinLimits) {
  const uint32_t tick_hz = 50000, rate = 3000, accel = 300000;
  const auto p = CorrectionLimiter::MakeParams(tick_hz, rate, accel);
  CorrectionLimiter lim(*p);
  std::mt19937_64 rng(9);
  std::vector<double> goals;
  double g = 0;
  for (int i = 0; i < 400000; ++i) {
    if (i % 5000 == 0) g = std::uniform_real_distribution<double>(-100, 100)(rng);
    goals.push_back(g + 20 * std::sin(i * 1e-3));
  }
  const Trace tr = RunLimiter(lim, static_cast<int>(goals.size()),
                              [&](int t) { return static_cast<int64_t>(goals[t] * kQ32); });
  EXPECT_LE(tr.max_v, double(rate) / tick_hz + 1e-12);
  EXPECT_LE(tr.max_a, double(accel) / tick_hz / tick_hz + 1e-12);
}

}  // namespace
}  // namespace volcomp
