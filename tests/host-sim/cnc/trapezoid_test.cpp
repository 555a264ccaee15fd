// The trapezoidal velocity profile against its closed form.
#include "volcomp/sim/trapezoid.hpp"

#include <gtest/gtest.h>

#include "trapezoid_reference.hpp"

namespace volcomp::sim {
namespace {

TEST(SimTrapezoid, TrapezoidAndTriangleMatchClosedForm) {
  // L = 100 mm, v = 50 mm/s, a = 100 mm/s^2: 0.5 s ramps over 12.5 mm, 1.5 s cruise: 2.5 s.
  const TrapezoidProfile p(100, 50, 100);
  EXPECT_NEAR(p.duration_s(), 2.5, 1e-12);
  EXPECT_NEAR(p.peak_speed_mm_s(), 50, 1e-12);
  // L = 4 mm with the same limits: triangle, v_peak = sqrt(a L) = 20 mm/s, 0.2 s + 0.2 s.
  const TrapezoidProfile q(4, 50, 100);
  EXPECT_NEAR(q.duration_s(), 0.4, 1e-12);
  EXPECT_NEAR(q.peak_speed_mm_s(), 20, 1e-12);
  for (double t = 0; t <= 2.5; t += 0.01) {
    EXPECT_NEAR(p.PositionAt(t), testing::TrapezoidPosition(100, 50, 100, t), 1e-9) << t;
    EXPECT_NEAR(p.TimeAt(testing::TrapezoidPosition(100, 50, 100, t)), t, 1e-6) << t;
  }
  for (double t = 0; t <= 0.4; t += 0.005) {
    EXPECT_NEAR(q.PositionAt(t), testing::TrapezoidPosition(4, 50, 100, t), 1e-9) << t;
  }
}

}  // namespace
}  // namespace volcomp::sim
