// GOST 27843-88 §2.7 target plans, the linear and pseudo-pilgrim cycles, and G-code output
// (test_program.hpp); impossible plans are failures naming the problem.
#include "volcomp/metrology/test_program.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;

TargetPlan Plan() {
  TargetPlan p;
  p.start = 0.0;
  p.end = 1500.0;
  p.count = 11;
  p.pitch = 10.0;
  p.seed = 7;
  return p;
}

TEST(MetrologyTestProgram, TargetsFollowNPlusRTimesP) {
  const auto t = ValueOf(PlanGostTargets(Plan()));
  ASSERT_EQ(t.size(), 11u);
  std::set<long> fractions;
  for (std::size_t j = 0; j < t.size(); ++j) {
    EXPECT_GE(t[j], 0.0);
    EXPECT_LE(t[j], 1500.0);
    if (j > 0) {
      EXPECT_GT(t[j], t[j - 1]);
    }
    // P_j / P = N + r with r a 2-digit decimal fraction.
    const double q = t[j] / 10.0;
    const double r = q - std::floor(q);
    EXPECT_NEAR(r * 100.0, std::round(r * 100.0), 1e-6);
    fractions.insert(std::lround(r * 100.0));
    // Spread evenly: within one pitch of the uniform grid 0, 149, 298, ... (N_j = round(j·149/10)).
    EXPECT_NEAR(std::floor(q), std::round(static_cast<double>(j) * 149.0 / 10.0), 0.5);
  }
  EXPECT_EQ(fractions.size(), 11u) << "r must differ between positions";
}

TEST(MetrologyTestProgram, SameSeedSamePlanOtherSeedOtherPlan) {
  EXPECT_EQ(ValueOf(PlanGostTargets(Plan())), ValueOf(PlanGostTargets(Plan())));
  TargetPlan other = Plan();
  other.seed = 8;
  EXPECT_NE(ValueOf(PlanGostTargets(Plan())), ValueOf(PlanGostTargets(other)));
}

TEST(MetrologyTestProgram, RotaryPlanContainsTheCardinalAngles) {
  TargetPlan p;
  p.rotary = true;
  p.count = 12;
  p.pitch = 5.0;  // e.g. a worm-wheel pitch angle
  p.seed = 3;
  const auto t = ValueOf(PlanGostTargets(p));
  for (double a : {0.0, 90.0, 180.0, 270.0}) {
    EXPECT_NE(std::find(t.begin(), t.end(), a), t.end()) << a;
  }
  for (double v : t) {
    EXPECT_GE(v, 0.0);
    EXPECT_LT(v, 360.0);
  }
}

TEST(MetrologyTestProgram, ImpossiblePlansAreRejected) {
  TargetPlan p = Plan();
  p.pitch = 200.0;  // 7 pitches for 11 positions
  ExpectFailure(PlanGostTargets(p), Error::kInvalidArgument, {"the travel holds only 7 pitches"});
  p = Plan();
  p.count = 1;
  ExpectFailure(PlanGostTargets(p), Error::kInvalidArgument, {"at least 2 target positions"});
  p = Plan();
  p.end = -1.0;
  ExpectFailure(PlanGostTargets(p), Error::kInvalidArgument, {"the end must be beyond the start"});
}

TEST(MetrologyTestProgram, ImpossibleCyclesAndProgramsAreRejected) {
  ExpectFailure(BuildCycle({0.0}, Cycle::kLinear, 1, 1.0), Error::kInvalidArgument,
                {"at least 2 targets"});
  ExpectFailure(BuildCycle({0.0, 1.0}, Cycle::kLinear, 0, 1.0), Error::kInvalidArgument,
                {"at least 1 run"});
  ExpectFailure(BuildCycle({0.0, 1.0}, Cycle::kLinear, 1, 0.0), Error::kInvalidArgument,
                {"the overrun must be positive"});
  GcodeOptions o;
  o.axes = {"X", "Y"};
  ExpectFailure(EmitGcode({}, o), Error::kInvalidArgument, {"the same size"});
}

// Every target is reached once ↑ and once ↓ per run, and really from that side.
void CheckCycle(Cycle c) {
  const std::vector<double> t = {0.0, 10.0, 25.0, 40.0};
  const auto moves = ValueOf(BuildCycle(t, c, 3, 2.0));
  std::map<std::tuple<int, int, int>, int> count;  // (run, target, dir)
  for (std::size_t i = 1; i < moves.size(); ++i) {
    const CycleMove& m = moves[i];
    if (!m.measure) continue;
    const double from = moves[i - 1].position;
    if (m.approach == Direction::kUp) {
      EXPECT_LT(from, m.position) << "move " << i;
    } else {
      EXPECT_GT(from, m.position) << "move " << i;
    }
    ++count[{m.run, m.target, m.approach == Direction::kUp ? 0 : 1}];
  }
  EXPECT_EQ(count.size(), 3u * 4u * 2u);
  for (const auto& [k, n] : count) EXPECT_EQ(n, 1);
  EXPECT_LT(moves.front().position, t.front());
}

TEST(MetrologyTestProgram, LinearCycleApproachesEveryTargetFromBothSides) {
  CheckCycle(Cycle::kLinear);
}

TEST(MetrologyTestProgram, PseudoPilgrimCycleApproachesEveryTargetFromBothSides) {
  CheckCycle(Cycle::kPseudoPilgrim);
  // The step-return order: P1↑ P2↑ P1↓ P3↑ P2↓ P4↑ P3↓ (overrun) P4↓.
  const auto m = ValueOf(BuildCycle({0.0, 10.0, 20.0, 30.0}, Cycle::kPseudoPilgrim, 1, 1.0));
  std::vector<int> order;
  for (const auto& mv : m) {
    if (mv.measure) order.push_back(mv.approach == Direction::kUp ? mv.target : -mv.target);
  }
  EXPECT_EQ(order, (std::vector<int>{1, 2, -1, 3, -2, 4, -3, -4}));
}

TEST(MetrologyTestProgram, GcodeMarksEveryMeasuredStop) {
  const auto moves = ValueOf(BuildCycle({0.0, 100.0, 200.0}, Cycle::kLinear, 2, 5.0));
  GcodeOptions o;
  o.axes = {"Y"};
  o.dwell_s = 1.5;
  o.feed = 800;
  const std::string g = ValueOf(EmitGcode(moves, o));
  EXPECT_EQ(g.rfind("G21 G90 G94", 0) == std::string::npos, true);  // preceded by comments
  EXPECT_NE(g.find("G21 G90 G94\n"), std::string::npos);
  EXPECT_NE(g.find("G0 Y-5.000\nF800\n"), std::string::npos);
  EXPECT_NE(g.find("G1 Y200.000 (P3 up run 1)\nG4 P1.5\n"), std::string::npos);
  EXPECT_NE(g.find("G1 Y205.000\n"), std::string::npos);
  std::size_t dwells = 0;
  for (std::size_t p = g.find("G4 P"); p != std::string::npos; p = g.find("G4 P", p + 1)) ++dwells;
  EXPECT_EQ(dwells, 2u * 3u * 2u);
  EXPECT_EQ(g.substr(g.size() - 3), "M2\n");
}

// Hand-checked: a 3-4-5 diagonal from (1, 2, 0) in = (25.4, 50.8, 0) mm; the stop 127 mm = 5 in
// along it is (1 + 3, 2 + 4, 0) in; the overrun 25.4 mm before the start is (0.4, 1.2, 0) in;
// 254 mm/min is 10 in/min.
TEST(MetrologyTestProgram, GcodeInInches) {
  const auto moves = ValueOf(BuildCycle({0.0, 127.0}, Cycle::kLinear, 1, 25.4));
  GcodeOptions o;
  o.axes = {"X", "Y", "Z"};
  o.origin = {25.4, 50.8, 0.0};
  o.direction = {0.6, 0.8, 0.0};
  o.feed = 254;
  o.inch = true;
  const std::string g = ValueOf(EmitGcode(moves, o));
  EXPECT_NE(g.find("G20 G90 G94\n"), std::string::npos) << g;
  EXPECT_EQ(g.find("G21"), std::string::npos) << g;
  EXPECT_NE(g.find("G0 X0.40000 Y1.20000 Z0.00000\nF10.000\n"), std::string::npos) << g;
  EXPECT_NE(g.find("G1 X1.00000 Y2.00000 Z0.00000 (P1 up run 1)"), std::string::npos) << g;
  EXPECT_NE(g.find("G1 X4.00000 Y6.00000 Z0.00000 (P2 up run 1)"), std::string::npos) << g;
}

TEST(MetrologyTestProgram, GcodeAlongADiagonal) {
  const auto moves = ValueOf(BuildCycle({0.0, 5.0}, Cycle::kLinear, 1, 1.0));
  GcodeOptions o;
  o.axes = {"X", "Y", "Z"};
  o.origin = {10.0, 20.0, 30.0};
  o.direction = {0.6, 0.8, 0.0};
  const std::string g = ValueOf(EmitGcode(moves, o));
  EXPECT_NE(g.find("G1 X13.000 Y24.000 Z30.000 (P2 up run 1)"), std::string::npos);
  EXPECT_NE(g.find("G0 X9.400 Y19.200 Z30.000"), std::string::npos);
}

// RS274NGC (LinuxCNC): a comment runs from '(' to the first ')' and may not nest.
TEST(MetrologyTestProgram, TitleCommentDoesNotNest) {
  const std::vector<CycleMove> moves = ValueOf(BuildCycle({10.0, 20.0}, Cycle::kLinear, 1, 5.0));
  GcodeOptions o;
  o.axes = {"X"};
  o.title = "linear cycle (fig. 1), I_x (mm)";
  const std::string g = ValueOf(EmitGcode(moves, o));
  EXPECT_EQ(g.substr(0, g.find('\n')), "(linear cycle [fig. 1], I_x [mm])");
  for (std::size_t line = 0; line < g.size(); line = g.find('\n', line) + 1) {
    const std::string l = g.substr(line, g.find('\n', line) - line);
    int depth = 0;
    for (char c : l) {
      depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      EXPECT_LE(depth, 1) << l;
    }
  }
}

}  // namespace
}  // namespace volcomp::metrology
