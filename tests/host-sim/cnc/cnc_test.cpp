// The simulated CNC: step emission (counts, times, rates), linear interpolation, homing, dwells,
// programs. References are closed-form kinematics (trapezoid_reference.hpp).
#include "volcomp/sim/cnc.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "trapezoid_reference.hpp"
#include "volcomp/sim/trapezoid.hpp"

namespace volcomp::sim {
namespace {

struct Recorded {
  int axis;
  uint64_t t_ns;
  int dir;
};

class Recorder : public StepSink {
 public:
  void OnStep(int axis, uint64_t t_ns, int dir) override { steps.push_back({axis, t_ns, dir}); }
  std::vector<Recorded> steps;
  std::vector<uint64_t> Times(int axis) const {
    std::vector<uint64_t> t;
    for (const Recorded& r : steps) {
      if (r.axis == axis) t.push_back(r.t_ns);
    }
    return t;
  }
};

void RunAll(Cnc& cnc, uint64_t step_ns = 20000, uint64_t limit_ns = 100000000000ull) {
  for (uint64_t t = 0; !cnc.idle() && t < limit_ns; t += step_ns) cnc.AdvanceTo(t);
}

TEST(SimCnc, RapidMoveEmitsEveryStepAtTheKinematicTimesWithinOneMegahertz) {
  Recorder rec;
  CncConfig c;
  c.accel_mm_s2 = 10000;
  Cnc cnc(c, &rec, [](int) { return false; });
  cnc.QueueRapid({300000, 0, 0});  // 300 mm at 1 um/step: reaches 1000 mm/s = 1 MHz
  RunAll(cnc);
  const std::vector<uint64_t> t = rec.Times(0);
  ASSERT_EQ(t.size(), 300000u);
  EXPECT_EQ(cnc.count(0), 300000);
  // Step k happens when the ideal path position reaches k um (to 1 ns of time).
  for (size_t k = 0; k < t.size(); k += 997) {
    const double s = testing::TrapezoidPosition(300, 1000, 10000, static_cast<double>(t[k]) * 1e-9);
    const double s_before =
        testing::TrapezoidPosition(300, 1000, 10000, static_cast<double>(t[k] - 1) * 1e-9);
    EXPECT_GE(s, (static_cast<double>(k) + 1) * 1e-3 - 1e-9) << k;
    EXPECT_LT(s_before, (static_cast<double>(k) + 1) * 1e-3 + 1e-9) << k;
  }
  uint64_t min_gap = UINT64_MAX;
  for (size_t k = 1; k < t.size(); ++k) {
    ASSERT_GE(t[k], t[k - 1]);
    min_gap = std::min(min_gap, t[k] - t[k - 1]);
  }
  EXPECT_GE(min_gap, 999u);   // 1 MHz, to the ns rounding
  EXPECT_LE(min_gap, 1001u);  // and it does get there
  EXPECT_NEAR(cnc.peak_step_rate_hz(), 1e6, 1);
}

TEST(SimCnc, CounterSemanticsStepsUpToTheAdvanceTime) {
  Recorder rec;
  Cnc cnc(CncConfig(), &rec, [](int) { return false; });
  cnc.QueueRapid({20000, -7000, 3000});
  uint64_t t = 0;
  size_t seen = 0;
  while (!cnc.idle()) {
    t += 20000;
    cnc.AdvanceTo(t);
    for (size_t i = seen; i < rec.steps.size(); ++i) {
      ASSERT_LE(rec.steps[i].t_ns, t);          // nothing from the future
      ASSERT_GT(rec.steps[i].t_ns, t - 20000);  // nothing late
    }
    seen = rec.steps.size();
  }
  EXPECT_EQ(cnc.count(0), 20000);
  EXPECT_EQ(cnc.count(1), -7000);
  EXPECT_EQ(cnc.count(2), 3000);
}

TEST(SimCnc, LinearInterpolationKeepsTheAxesOnTheLine) {
  Recorder rec;
  Cnc cnc(CncConfig(), &rec, [](int) { return false; });
  cnc.QueueLinear({40000, 25000, -10000}, 200);  // 200 mm/s feed
  RunAll(cnc);
  std::array<int64_t, 3> pos = {0, 0, 0};
  const std::array<double, 3> n = {40000, 25000, 10000};
  std::sort(rec.steps.begin(), rec.steps.end(),
            [](const Recorded& a, const Recorded& b) { return a.t_ns < b.t_ns; });
  for (const Recorded& r : rec.steps) {
    pos[static_cast<size_t>(r.axis)] += r.dir;
    // Fractions of the path done by each axis agree within one step.
    const double fx = std::fabs(static_cast<double>(pos[0])) / n[0];
    for (size_t a = 1; a < 3; ++a) {
      ASSERT_NEAR(std::fabs(static_cast<double>(pos[a])) / n[a], fx, 1.0 / n[a] + 1.0 / n[0]);
    }
  }
  // Feed 200 mm/s along a 48.2 mm path: X runs at 200 * 40 / 48.2 mm/s at most.
  const double length = std::sqrt(40.0 * 40 + 25.0 * 25 + 10.0 * 10);
  EXPECT_NEAR(cnc.peak_step_rate_hz(), 200 * 40 / length * 1000, 1);
}

TEST(SimCnc, DwellEndsOnTimeAndMovesChainWithoutGaps) {
  Recorder rec;
  Cnc cnc(CncConfig(), &rec, [](int) { return false; });
  std::vector<uint64_t> ends;
  cnc.set_dwell_handler([&](uint64_t t) { ends.push_back(t); });
  cnc.QueueRapid({1000, 0, 0});
  cnc.QueueDwell(0.25);
  cnc.QueueRapid({0, 0, 0});
  RunAll(cnc, 50000);
  ASSERT_EQ(ends.size(), 1u);
  const TrapezoidProfile p(1.0, 1000, 10000);
  const uint64_t move_end = static_cast<uint64_t>(std::ceil(p.duration_s() * 1e9));
  EXPECT_EQ(ends[0], move_end + 250000000u);
  const std::vector<uint64_t> t = rec.Times(0);
  ASSERT_EQ(t.size(), 2000u);
  EXPECT_EQ(t[999], move_end);  // the last step ends the move
  EXPECT_GT(t[1000], ends[0]);  // the next move starts at the dwell's end
  EXPECT_EQ(cnc.count(0), 0);
}

TEST(SimCnc, HomingStopsOnTheStepThatClosesTheSwitch) {
  // The switch of axis a closes at count <= -3000 - 100 a (a drive that follows at once).
  Recorder rec;
  CncConfig c;
  c.home_position_steps = {-5000, -6000, -7000};
  Cnc* self = nullptr;
  Cnc cnc(c, &rec, [&](int a) { return self->count(a) <= -3000 - 100 * a; });
  self = &cnc;
  cnc.QueueRapid({1000, 2000, 500});
  cnc.QueueHome(7);
  RunAll(cnc, 20000, 60000000000ull);
  ASSERT_TRUE(cnc.idle());
  for (int a = 0; a < 3; ++a) {
    EXPECT_TRUE(cnc.homed(a));
    EXPECT_EQ(cnc.count(a), -3000 - 100 * a) << a;  // stopped exactly where it closed
    EXPECT_EQ(cnc.position(a), c.home_position_steps[static_cast<size_t>(a)]) << a;
  }
}

TEST(SimCnc, HomingLeavesAClosedSwitchFirst) {
  Recorder rec;
  Cnc* self = nullptr;
  Cnc cnc(CncConfig(), &rec, [&](int a) { return self->count(a) <= 50; });
  self = &cnc;
  cnc.QueueHome(1);  // starts on the switch (count 0)
  RunAll(cnc, 20000, 60000000000ull);
  ASSERT_TRUE(cnc.idle());
  EXPECT_EQ(cnc.count(0), 50);
  EXPECT_TRUE(cnc.homed(0));
  EXPECT_FALSE(cnc.homed(1));
}

TEST(SimCnc, ProgramCoordinatesAreMillimetresInTheHomedFrame) {
  Recorder rec;
  CncConfig c;
  c.home_position_steps = {-5000, -5000, -5000};
  Cnc* self = nullptr;
  Cnc cnc(c, &rec, [&](int a) { return self->count(a) <= -2000; });
  self = &cnc;
  cnc.QueueHome(7);
  const Expected<Program> program = ParseGcode("G90 G0 X10 Y-1.5\nG91 G1 Z2.25 F600\n");
  ASSERT_TRUE(program.ok()) << program.error().message;
  cnc.QueueProgram(*program);
  RunAll(cnc, 20000, 60000000000ull);
  EXPECT_EQ(cnc.position(0), 10000);
  EXPECT_EQ(cnc.position(1), -1500);
  EXPECT_EQ(cnc.position(2), -5000 + 2250);
  EXPECT_EQ(cnc.count(0), -2000 + 15000);
}

}  // namespace
}  // namespace volcomp::sim
