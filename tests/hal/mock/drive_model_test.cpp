// DriveModel, the drive-side checker the output tests rely on: it must count steps and flag each
// timing rule it is written to enforce. Edge sequences written by hand, one rule broken at a time
// (drive timing: width 1000 ns, space 1000 ns, setup 500 ns, hold 700 ns, 250 kHz = 4000 ns).
#include "volcomp/hal/mock/drive_model.hpp"

#include <gtest/gtest.h>

namespace volcomp::hal::mock {
namespace {

constexpr DriveTiming kTiming{1000, 1000, 500, 700, 250000};
constexpr bool kStep = false;  // line A
constexpr bool kDir = true;    // line B

// A STEP pulse rising at `t`, `width` ns high.
void Pulse(DriveModel& d, uint64_t t, uint64_t width = 1000, bool line = kStep) {
  d.OnEdge(t, line, true);
  d.OnEdge(t + width, line, false);
}

TEST(DriveModelStepDir, CountsLegalStepsBothWays) {
  DriveModel d(PulseFormat::kStepDir, kTiming);
  Pulse(d, 10000);
  Pulse(d, 14000);               // exactly 1/max_rate after the first rise
  d.OnEdge(15700, kDir, false);  // hold 700 after the fall at 15000
  Pulse(d, 18000);               // 1/max_rate after the last rise, well after the setup
  EXPECT_EQ(d.violations(), 0u) << (d.violation_log().empty() ? "" : d.violation_log()[0]);
  EXPECT_EQ(d.steps(), 3u);
  EXPECT_EQ(d.position(), 1);  // +1 +1 -1
  EXPECT_EQ(d.last_step_ns(), 18000u);
}

TEST(DriveModelStepDir, FlagsEachBrokenRule) {
  struct Case {
    const char* rule;
    void (*play)(DriveModel&);
  };
  const Case cases[] = {
      {"pulse width", [](DriveModel& d) { Pulse(d, 10000, 999); }},
      {"step space",
       [](DriveModel& d) {
         Pulse(d, 10000, 3100);
         Pulse(d, 14000);  // 900 ns low
       }},
      {"max rate",
       [](DriveModel& d) {
         Pulse(d, 10000);
         Pulse(d, 13999);
       }},
      {"dir setup",
       [](DriveModel& d) {
         Pulse(d, 10000);
         d.OnEdge(20000, kDir, false);
         Pulse(d, 20499);
       }},
      {"dir hold",
       [](DriveModel& d) {
         Pulse(d, 10000);
         d.OnEdge(11699, kDir, false);  // 699 after the fall
       }},
      {"dir while step high",
       [](DriveModel& d) {
         d.OnEdge(10000, kStep, true);
         d.OnEdge(10500, kDir, false);
       }},
      {"time order",
       [](DriveModel& d) {
         Pulse(d, 10000);
         Pulse(d, 5000);
       }},
  };
  for (const Case& c : cases) {
    DriveModel d(PulseFormat::kStepDir, kTiming);
    c.play(d);
    EXPECT_GE(d.violations(), 1u) << c.rule;
  }
}

TEST(DriveModelCwCcw, LinesPulseEachWayAndSwitchAfterHoldAndSetup) {
  DriveModel ok(PulseFormat::kCwCcw, kTiming);
  Pulse(ok, 10000, 1000, kStep);  // CW: +1
  Pulse(ok, 12200, 1000, kDir);   // CCW 1200 after CW fell: hold 700 + setup 500
  EXPECT_EQ(ok.violations(), 0u);
  EXPECT_EQ(ok.position(), 0);
  EXPECT_EQ(ok.steps(), 2u);

  DriveModel fast(PulseFormat::kCwCcw, kTiming);
  Pulse(fast, 10000, 1000, kStep);
  Pulse(fast, 12199, 1000, kDir);  // 1 ns short of hold + setup
  EXPECT_EQ(fast.violations(), 1u);

  DriveModel both(PulseFormat::kCwCcw, kTiming);
  both.OnEdge(10000, kStep, true);
  both.OnEdge(10100, kDir, true);  // CCW rises while CW is high
  EXPECT_GE(both.violations(), 1u);
}

TEST(DriveModelQuadrature, CountsGrayCodeAndFlagsFastOrSimultaneousEdges) {
  DriveModel d(PulseFormat::kQuadrature, kTiming);
  // +1 sequence (A,B): 00 -> 10 -> 11 -> 01 -> 00, 4000 ns apart: +4; then back one: -1.
  d.OnEdge(4000, kStep, true);
  d.OnEdge(8000, kDir, true);
  d.OnEdge(12000, kStep, false);
  d.OnEdge(16000, kDir, false);
  d.OnEdge(20000, kDir, true);  // 00 -> 01: one step back
  EXPECT_EQ(d.violations(), 0u);
  EXPECT_EQ(d.position(), 3);
  EXPECT_EQ(d.steps(), 5u);

  DriveModel fast(PulseFormat::kQuadrature, kTiming);
  fast.OnEdge(4000, kStep, true);
  fast.OnEdge(7999, kDir, true);
  EXPECT_EQ(fast.violations(), 1u);

  DriveModel together(PulseFormat::kQuadrature, kTiming);
  together.OnEdge(4000, kStep, true);
  together.OnEdge(4000, kDir, true);
  EXPECT_GE(together.violations(), 1u);
}

}  // namespace
}  // namespace volcomp::hal::mock
