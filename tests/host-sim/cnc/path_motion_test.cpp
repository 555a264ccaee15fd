// Arcs run by the simulated CNC (G2/G3 through PathMotion): the emitted steps follow the circle to
// the nearest step, the axis rate limit holds, tangent blocks run as one move at constant feed and
// corners still stop. References: the circle's own equation and the closed-form trapezoid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "expected_value.hpp"
#include "trapezoid_reference.hpp"
#include "volcomp/sim/cnc.hpp"
#include "volcomp/sim/gcode.hpp"

namespace volcomp::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Event {
  int axis;
  uint64_t t_ns;
  int dir;
};

class Recorder : public StepSink {
 public:
  void OnStep(int axis, uint64_t t_ns, int dir) override { events.push_back({axis, t_ns, dir}); }
  std::vector<Event> events;
};

// Trapezoid duration for length L, speed v, acceleration a (closed form).
double TrapezoidSeconds(double L, double v, double a) {
  const double vp = std::min(v, std::sqrt(a * L));
  return vp / a + L / vp;
}

struct ProgramRun {
  Recorder rec;
  std::map<int, std::pair<uint64_t, uint64_t>> line_span_ns;  // first and last tick seen active
  uint64_t end_ns = 0;
};

void RunProgram(const std::string& text, ProgramRun& run, double accel = 10000) {
  CncConfig c;
  c.accel_mm_s2 = accel;
  Cnc cnc(c, &run.rec, [](int) { return false; });
  const Program p = testing::ValueOf(ParseGcode(text, "t.ngc"));
  ASSERT_TRUE(CheckProgramPaths(p, {0, 0, 0}, c.step_mm, "t.ngc").ok());
  cnc.QueueProgram(p);
  uint64_t t = 0;
  for (; !cnc.idle() && t < 200000000000ull; t += 10000) {
    cnc.AdvanceTo(t);
    const int line = cnc.active_line();
    if (line == 0) continue;
    auto it = run.line_span_ns.find(line);
    if (it == run.line_span_ns.end()) {
      run.line_span_ns[line] = {t, t};
    } else {
      it->second.second = t;
    }
  }
  run.end_ns = t;
}

TEST(SimCncArcs, FullCircleStepsStayOnTheCircleToTheNearestStep) {
  ProgramRun run;
  // Start at (10, 0), full clockwise circle about the origin at 600 mm/min.
  RunProgram("G1 X10 F6000\nG2 X10 Y0 I-10 J0 F600\n", run);
  std::vector<int64_t> pos = {0, 0, 0};
  std::vector<int64_t> count = {0, 0, 0};
  std::vector<uint64_t> last_t = {0, 0, 0};
  uint64_t min_gap = UINT64_MAX;
  double worst = 0;
  bool on_circle = false;
  for (const Event& e : run.rec.events) {
    pos[static_cast<size_t>(e.axis)] += e.dir;
    ++count[static_cast<size_t>(e.axis)];
    if (last_t[static_cast<size_t>(e.axis)] != 0) {
      min_gap = std::min(min_gap, e.t_ns - last_t[static_cast<size_t>(e.axis)]);
    }
    last_t[static_cast<size_t>(e.axis)] = e.t_ns;
    if (pos[1] != 0) on_circle = true;
    if (!on_circle) continue;
    const double r =
        std::hypot(static_cast<double>(pos[0]) * 1e-3, static_cast<double>(pos[1]) * 1e-3);
    worst = std::max(worst, std::fabs(r - 10));
  }
  EXPECT_EQ(pos[0], 10000);
  EXPECT_EQ(pos[1], 0);
  // X: 10 mm to the start, then 40 mm around; Y 40 mm around.
  EXPECT_EQ(count[0], 10000 + 40000);
  EXPECT_EQ(count[1], 40000);
  // Each axis is rounded to its nearest step: the point is within sqrt(2)/2 um of the circle
  // (and a step of one axis lands before the other's: 1 um).
  EXPECT_LE(worst, 1.0e-3);
  EXPECT_GE(min_gap, 999u);  // within 1 MHz
  // Clockwise from (10, 0): Y goes negative first.
  for (const Event& e : run.rec.events) {
    if (e.axis == 1) {
      EXPECT_EQ(e.dir, -1);
      break;
    }
  }
  // The circle takes the trapezoid's time (rest to rest; it is not joined to the line).
  const auto span = run.line_span_ns.at(2);
  EXPECT_NEAR(static_cast<double>(span.second - span.first) * 1e-9,
              TrapezoidSeconds(2 * kPi * 10, 10, 10000), 30e-6);
}

TEST(SimCncArcs, TangentArcsRunAsOneMoveAtConstantFeed) {
  ProgramRun run;
  // The ISO 230-4 shape: a run-in quarter, the full circle, a run-out quarter, all tangent, at
  // 2000 mm/min with a low acceleration (the ramp, 3.1 mm, lies inside the run-in quarter).
  RunProgram(
      "G1 X10 F6000\n"
      "G3 X0 Y10 I-10 J0 F2000\n"
      "G3 X0 Y10 I0 J-10\n"
      "G3 X-10 Y0 I0 J-10\n",
      run, 200);
  const double v = 2000.0 / 60;
  const auto in = run.line_span_ns.at(2), full = run.line_span_ns.at(3),
             out = run.line_span_ns.at(4);
  // No stop between them: the full circle takes exactly its length at the feed.
  EXPECT_NEAR(static_cast<double>(full.second - full.first) * 1e-9, 2 * kPi * 10 / v, 30e-6);
  EXPECT_LE(full.first - in.second, 10000u);
  EXPECT_LE(out.first - full.second, 10000u);
  // The three together take the trapezoid of their whole length.
  EXPECT_NEAR(static_cast<double>(out.second + 10000 - in.first) * 1e-9,
              TrapezoidSeconds(3 * kPi * 10, v, 200), 40e-6);
}

TEST(SimCncArcs, ACornerAfterAnArcStops) {
  ProgramRun run;
  // A quarter arc ending along -X, then a line along +Y: 90 degrees, not joined.
  RunProgram("G1 X10 F6000\nG3 X0 Y10 I-10 J0 F600\nG1 Y20\n", run);
  const double v = 10;
  const auto arc = run.line_span_ns.at(2), line = run.line_span_ns.at(3);
  EXPECT_NEAR(static_cast<double>(arc.second - arc.first) * 1e-9,
              TrapezoidSeconds(10 * kPi / 2, v, 10000), 30e-6);
  EXPECT_NEAR(static_cast<double>(line.second - line.first) * 1e-9, TrapezoidSeconds(10, v, 10000),
              30e-6);
}

TEST(SimCncArcs, ArcsInEveryPlaneEndWhereProgrammed) {
  for (const char* program : {"G18 G1 X10 F6000\nG3 X0 Z10 I-10 K0 F3000\n",
                              "G19 G1 Y10 F6000\nG2 Y0 Z-10 J-10 K0 F3000\n",
                              "G17 G1 X10 F6000\nG2 X0 Y-10 R10 F3000\nG3 X10 Y-20 R-10\n",
                              "G17 G1 X10 F6000\nG3 X10 Y0 Z2 I-10 J0 F3000\n"}) {
    ProgramRun run;
    RunProgram(program, run);
    std::vector<int64_t> pos = {0, 0, 0};
    for (const Event& e : run.rec.events) pos[static_cast<size_t>(e.axis)] += e.dir;
    const Program p = testing::ValueOf(ParseGcode(program));
    Point3 end = {0, 0, 0};
    for (const ProgramBlock& b : p) {
      for (size_t a = 0; a < 3; ++a) {
        if (b.has[a]) end[a] = b.value_mm[a];
      }
    }
    for (size_t a = 0; a < 3; ++a) {
      EXPECT_EQ(pos[a], std::llround(end[a] * 1000)) << program << " axis " << a;
    }
  }
}

TEST(SimGcodeArcs, RefusesWhatItCannotRunWithTheLine) {
  auto failure = [](const std::string& text) {
    const Expected<Program> p = ParseGcode(text, "p.ngc");
    if (!p.ok()) return p.error().message;
    const Outcome o = CheckProgramPaths(*p, {0, 0, 0}, {0.001, 0.001, 0.001}, "p.ngc");
    return o.ok() ? std::string() : o.error().message;
  };
  EXPECT_EQ(failure("G1 X1 F100\nG2 X2 Y0\n"),
            "p.ngc:2: G2 needs the centre (I, J, K) or the radius (R)");
  EXPECT_EQ(failure("G1 X1 I3 F100\n"), "p.ngc:1: I, J, K or R without G2 or G3");
  EXPECT_EQ(failure("G3 X1 K1 F100\n"), "p.ngc:1: K is not in the G17 plane");
  EXPECT_EQ(failure("G3 X1 I1 R1 F100\n"), "p.ngc:1: an arc with both I/J/K and R");
  EXPECT_EQ(failure("G3 X1 Y1\n"), "p.ngc:1: G3 without a feed (F)");
  EXPECT_EQ(failure("G1 X5 F100\n\nG3 X1 R1\n"),
            "p.ngc:3: R 1.0000 mm is shorter than half the chord (2.0000 mm)");
  EXPECT_NE(failure("G3 X10 Y10 I5 F100\n").find("p.ngc:1: the arc's end point is"),
            std::string::npos);
  EXPECT_EQ(failure("G18 G2 X1 Z0 I0.5 K0 F100\nG17 G3 X0 Y0 I-0.5 J0\n"), "");
}

}  // namespace
}  // namespace volcomp::sim
