// ISO 230-6 (diagonal.hpp): target positions (§5.2) and E/B per diagonal on synthetic data with
// known mean deviations; bad input is a failure naming the line.
#include "volcomp/metrology/diagonal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::Csv;
using testing::ExpectFailure;
using testing::ValueOf;

TEST(MetrologyDiagonalPlan, TargetsAndAxisIncrementsOfSection5_2) {
  // 3-4-12 box: D = 13·50 = 650 mm.
  const DiagonalPlan p = ValueOf(PlanDiagonal({0, 0, 0}, {150, 200, 600}, 65.0));
  EXPECT_NEAR(p.length_mm, 650.0, 1e-9);
  EXPECT_EQ(p.steps, 10);
  EXPECT_NEAR(p.increment_mm, 65.0, 1e-12);
  // I_x = (I_d / D)·X_v.
  EXPECT_NEAR(p.axis_increment_mm.x, 15.0, 1e-12);
  EXPECT_NEAR(p.axis_increment_mm.y, 20.0, 1e-12);
  EXPECT_NEAR(p.axis_increment_mm.z, 60.0, 1e-12);
  ASSERT_EQ(p.points.size(), 11u);
  EXPECT_NEAR(p.points[4].z, 240.0, 1e-12);
  EXPECT_NEAR(p.distances.back(), 650.0, 1e-12);
  EXPECT_TRUE(p.warnings.empty());
  // An increment that does not divide D is rounded (650/90 = 7.2 -> 7 steps), with a warning.
  const DiagonalPlan q = ValueOf(PlanDiagonal({0, 0, 0}, {150, 200, 600}, 90.0));
  EXPECT_EQ(q.steps, 7);
  EXPECT_NEAR(q.increment_mm, 650.0 / 7, 1e-12);
  ASSERT_FALSE(q.warnings.empty());
  EXPECT_NE(q.warnings[0].find("increment adjusted"), std::string::npos);
  // Too few targets: 2 m diagonal, 500 mm increment -> 5 targets, 10 needed.
  const DiagonalPlan r = ValueOf(PlanDiagonal({0, 0, 0}, {0, 1200, 1600}, 500.0));
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.back().find("§5.2"), std::string::npos);
  ExpectFailure(PlanDiagonal({1, 1, 1}, {1, 1, 1}, 10.0), Error::kInvalidArgument,
                {"P1 and P2 are the same point"});
  ExpectFailure(PlanDiagonal({0, 0, 0}, {1, 1, 1}, 0.0), Error::kInvalidArgument,
                {"the diagonal increment must be positive"});
}

// One diagonal's rows: x̄↑_j = up[j], x̄↓_j = down[j]; runs scatter symmetrically about them.
void AddDiagonal(std::string* csv,
                 const std::string& name,
                 const std::vector<double>& up,
                 const std::vector<double>& down,
                 double step_mm) {
  const double scatter[5] = {-0.2, 0.1, 0.0, -0.1, 0.2};
  for (int run = 1; run <= 5; ++run) {
    for (std::size_t j = 0; j < up.size(); ++j) {
      *csv += "\"" + name + "\"," + std::to_string(step_mm * static_cast<double>(j)) + ",up," +
              std::to_string(run) + "," + std::to_string(up[j] + scatter[run - 1]) + "\n";
    }
    for (std::size_t j = down.size(); j-- > 0;) {
      *csv += "\"" + name + "\"," + std::to_string(step_mm * static_cast<double>(j)) + ",down," +
              std::to_string(run) + "," + std::to_string(down[j] - scatter[run - 1]) + "\n";
    }
  }
}

TEST(MetrologyDiagonalEvaluation, KnownEAndB) {
  std::string csv = "diagonal,target_mm,direction,run,deviation_um\n";
  // E = max(x̄↑, x̄↓) − min(x̄↑, x̄↓);  B = max |x̄↑ − x̄↓|.
  AddDiagonal(&csv, "PPP", {0, 2, 4, 6, 8, 10}, {-1, 1, 3, 5, 7, 9}, 200);         // E 11, B 1
  AddDiagonal(&csv, "PPN", {0, 1, 0, -1, 0, 1}, {3, 3, 3, 3, 3, 3}, 200);          // E 4, B 4 (j=4)
  AddDiagonal(&csv, "PNP", {5, 5, 5, 5, 5, 5}, {5, 5, 5, 5, 5, 2.5}, 200);         // E 2.5, B 2.5
  AddDiagonal(&csv, "NPP", {-3, -2, -1, 0, 1, 2}, {-2, -2, -2, -2, -2, -2}, 200);  // E 5, B 4
  AddDiagonal(&csv, "+X+Y Z0", {0, 1, 2, 3, 4}, {0, 1, 2, 3, 4}, 250);             // E 4, B 0
  AddDiagonal(&csv, "+X-Y Z0", {0, 0, 0, 0, 0}, {-6, 0, 0, 0, 0}, 250);            // E 6, B 6
  const auto ev = ValueOf(EvaluateDiagonals(Csv(csv, "d.csv"), GroupingOptions{}));
  ASSERT_EQ(ev.diagonals.size(), 6u);
  const double e[6] = {11, 4, 2.5, 5, 4, 6}, b[6] = {1, 4, 2.5, 4, 0, 6};
  for (int i = 0; i < 6; ++i) {
    SCOPED_TRACE(ev.diagonals[i].name.text);
    EXPECT_NEAR(ev.diagonals[i].E.value, e[i], 1e-9);
    EXPECT_NEAR(ev.diagonals[i].B.value, b[i], 1e-9);
  }
  EXPECT_EQ(ev.diagonals[1].name.text, "+X+Y-Z");
  EXPECT_EQ(ev.diagonals[1].B.position, 3u);
  EXPECT_NEAR(ev.diagonals[0].length_mm, 1000.0, 1e-9);
  ASSERT_TRUE(ev.body);
  EXPECT_NEAR(ev.body->E_d, 11.0, 1e-9);
  EXPECT_EQ(ev.body->E_from, "+X+Y+Z");
  EXPECT_NEAR(ev.body->B_d, 4.0, 1e-9);
  EXPECT_EQ(ev.body->diagonals, 4);
  ASSERT_EQ(ev.faces.size(), 1u);
  EXPECT_EQ(ev.faces[0].name, "XY Z0");
  EXPECT_NEAR(ev.faces[0].E_d, 6.0, 1e-9);
  EXPECT_NEAR(ev.faces[0].B_d, 6.0, 1e-9);
  EXPECT_EQ(ev.faces[0].B_from, "+X-Y Z0");
  // The only warning: no instrument stated, so no uncertainty (listed once, not per diagonal).
  ASSERT_EQ(ev.warnings.size(), 1u);
  EXPECT_NE(ev.warnings[0].find("no measurement uncertainty"), std::string::npos);
  EXPECT_FALSE(ev.body->E_d_U);
}

TEST(MetrologyDiagonalEvaluation, WarnsAboutMissingAndRepeatedBodyDiagonals) {
  std::string csv = "diagonal,target_mm,direction,run,deviation_um\n";
  AddDiagonal(&csv, "+X+Y+Z", {0, 1, 2, 3, 4, 5}, {0, 1, 2, 3, 4, 5}, 200);
  AddDiagonal(&csv, "-X-Y-Z", {0, 1, 2, 3, 4, 5}, {0, 1, 2, 3, 4, 5}, 200);
  const auto ev = ValueOf(EvaluateDiagonals(Csv(csv, "d.csv"), GroupingOptions{}));
  std::string all;
  for (const auto& w : ev.warnings) all += w + "\n";
  EXPECT_NE(all.find("same body diagonal"), std::string::npos) << all;
  EXPECT_NE(all.find("only 1 of the 4 body diagonals"), std::string::npos) << all;
}

TEST(MetrologyDiagonalEvaluation, TooFewTargetsPerMetreWarns) {
  std::string csv = "diagonal,target_mm,direction,run,deviation_um\n";
  AddDiagonal(&csv, "+X+Y", {0, 1, 2, 3, 4}, {0, 1, 2, 3, 4}, 500);  // 5 targets on 2 m
  const auto ev = ValueOf(EvaluateDiagonals(Csv(csv, "d.csv"), GroupingOptions{}));
  std::string all;
  for (const auto& w : ev.warnings) all += w + "\n";
  EXPECT_NE(all.find("§5.2: 5 targets on 2000 mm; at least 10"), std::string::npos) << all;
}

TEST(MetrologyDiagonalEvaluation, BadInput) {
  std::string csv = "diagonal,target_mm,direction,run,deviation_um\n";
  AddDiagonal(&csv, "PPP", {0, 1, 2, 3, 4}, {0, 1, 2, 3, 4}, 200);
  std::string bad_name = csv;
  bad_name.replace(bad_name.find("\"PPP\""), 5, "\"PQP\"");
  ExpectFailure(EvaluateDiagonals(Csv(bad_name, "d.csv"), GroupingOptions{}), Error::kInputInvalid,
                {"d.csv:2:", "\"PQP\" is not a diagonal name"});
  ExpectFailure(EvaluateDiagonals(Csv("target_mm,direction,run,deviation_um\n0,up,1,1\n", "d.csv"),
                                  GroupingOptions{}),
                Error::kInputInvalid, {"d.csv:1:", "missing column \"diagonal\""});
  std::string up_only = "diagonal,target_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= 5; ++run) {
    for (int t = 0; t < 5; ++t) {
      up_only += "PPP," + std::to_string(t * 100) + ",up," + std::to_string(run) + ",0\n";
    }
  }
  ExpectFailure(EvaluateDiagonals(Csv(up_only, "d.csv"), GroupingOptions{}), Error::kInputInvalid,
                {"d.csv:2:", "diagonal +X+Y+Z has only one direction", "§5.3"});
  std::string wrong_unit = "diagonal,target_deg,direction,run,deviation_arcsec\nPPP,0,up,1,0\n";
  ExpectFailure(EvaluateDiagonals(Csv(wrong_unit, "d.csv"), GroupingOptions{}),
                Error::kInputInvalid, {"d.csv:1:", "target_mm"});
}

}  // namespace
}  // namespace volcomp::metrology
