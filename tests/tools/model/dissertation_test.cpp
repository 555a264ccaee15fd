// Reproduction of the dissertation's chapter 3 results (Pimushkin 2023, Tables 3.7-3.15 and
// Appendix А) with the named "dissertation" formulation. Every expected number is a printed one:
// Tables 3.7-3.15 (seed 001 lines 1795-1900) as the reproduce library types them, Appendix А
// (lines 2996-3089) below; the tolerance 1e-5 µm is the one the issue asks for (the printed values
// carry 6 decimals; inputs are the printed Tables 3.2-3.6).
#include "volcomp/model/dissertation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "expected_value.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/reproduce/reproduction.hpp"

namespace volcomp::model {
namespace {

using datasets::S500DissertationModel;
using datasets::S500MaxErrors;
using datasets::S500MinErrors;
using testing::ValueOf;

PointErrors S500PointErrorsAtNode(int nx, int ny, int nz) {
  return ValueOf(datasets::S500PointErrorsAtNode(nx, ny, nz));
}

constexpr double kTolUm = 1e-5;

// The printed values of Tables 3.7-3.15 are typed once, with their seed lines, in the reproduce
// library (tools/reproduce/src/dissertation_ch3.cpp); this test takes the printed side from there
// and computes its own side here, so it stays independent of the code that judges them.
const reproduce::Table& PrintedTable(const std::string& id) {
  static const reproduce::SeedReproduction printed = ValueOf(reproduce::ReproduceDissertation());
  for (const reproduce::Table& t : printed.tables)
    if (t.id == id) return t;
  ADD_FAILURE() << "no printed Table " << id;
  static const reproduce::Table empty;
  return empty;
}

/// The case a printed column holds, or false for another column (%, |E″|).
bool CaseOfColumn(const std::string& column, DissertationCase* which) {
  if (column == "δ+")
    *which = DissertationCase::kPlus;
  else if (column == "δ−")
    *which = DissertationCase::kMinus;
  else if (column == "δ")
    *which = DissertationCase::kFirstOrder;
  else
    return false;
  return true;
}

double Delta(const PointErrors& p, double k, DissertationCase which) {
  DissertationOptions o;
  o.k = k;
  o.which = which;
  return DissertationError(p, o).norm_um;
}

TEST(model_ch3, Tables3_7To3_13AtGridNodes) {
  // Tables 3.7 (k = 1), 3.8 (0.5), 3.9 (5), 3.10 (10), 3.11 (50), 3.12 (100), 3.13 (1000).
  const struct {
    const char* id;
    double k;
  } tables[] = {{"3.7", 1},   {"3.8", 0.5},  {"3.9", 5},    {"3.10", 10},
                {"3.11", 50}, {"3.12", 100}, {"3.13", 1000}};
  double worst = 0.0;
  int compared = 0;
  for (const auto& t : tables) {
    for (const reproduce::Cell& c : PrintedTable(t.id).cells) {
      DissertationCase which;
      if (!CaseOfColumn(c.column, &which)) continue;
      // Table 3.12 3/5/5 δ−: a copy of δ+ (digest D4 item 14), checked separately below.
      if (!c.misprint.empty()) continue;
      int nx = 0, ny = 0, nz = 0;
      ASSERT_EQ(std::sscanf(c.row.c_str(), "%d/%d/%d", &nx, &ny, &nz), 3) << c.row;
      SCOPED_TRACE(::testing::Message()
                   << "Table " << t.id << " node " << c.row << " " << c.column);
      const double ours = Delta(S500PointErrorsAtNode(nx, ny, nz), t.k, which);
      EXPECT_NEAR(ours, c.printed, kTolUm);
      worst = std::fmax(worst, std::fabs(ours - c.printed));
      ++compared;
    }
  }
  EXPECT_EQ(compared, 7 * 6 * 3 - 1);
  // The digest (D0) found every printed value within 1.6e-6 µm of a recomputation.
  EXPECT_LT(worst, 2e-6);
}

TEST(model_ch3, Table3_12CopyErrorIsNotReproduced) {
  // Table 3.12, 3/5/5, k = 100: printed δ− = 65.397367 equals δ+ (copy error, digest D4 item 14);
  // the digest's own recomputation gives 65.463946, consistent with the printed 0.001 %.
  const PointErrors p = S500PointErrorsAtNode(3, 5, 5);
  const double minus = Delta(p, 100, DissertationCase::kMinus);
  EXPECT_NEAR(minus, 65.463946, kTolUm);
  EXPECT_GT(std::fabs(minus - 65.397367), 0.06);
  const double first = Delta(p, 100, DissertationCase::kFirstOrder);
  EXPECT_NEAR(std::fabs(minus / first - 1.0) * 100.0, 0.001, 0.0005);  // printed "0.001"
}

TEST(model_ch3, Tables3_14And3_15AtMmaxMmin) {
  const struct {
    const char* id;
    PointErrors errors;
  } tables[] = {{"3.14", S500MaxErrors()}, {"3.15", S500MinErrors()}};
  int compared = 0;
  for (const auto& t : tables) {
    for (const reproduce::Cell& c : PrintedTable(t.id).cells) {
      DissertationCase which;
      if (!CaseOfColumn(c.column, &which)) continue;
      double k = 0;
      ASSERT_EQ(std::sscanf(c.row.c_str(), "k = %lf", &k), 1) << c.row;
      SCOPED_TRACE(::testing::Message() << "Table " << t.id << " k=" << k << " " << c.column);
      EXPECT_NEAR(Delta(t.errors, k, which), c.printed, kTolUm);
      ++compared;
    }
  }
  EXPECT_EQ(compared, 2 * 7 * 3);
}

TEST(model_ch3, AppendixAWorkedExample) {
  // Appendix А: n_x/n_y/n_z = 15/15/5 (300/150/50 mm), k = 1, r = 10 mm each.
  const PointErrors p = S500PointErrorsAtNode(15, 15, 5);
  // Inputs as printed in the appendix.
  EXPECT_EQ(p.delta_um[0][0], 30.566667);
  EXPECT_EQ(p.delta_um[1][0], -7.45);
  EXPECT_EQ(p.delta_um[2][2], -5.633333);
  EXPECT_EQ(p.eps_um_per_mm[0][2], 0.05105);
  EXPECT_EQ(p.eps_um_per_mm[2][2], -0.00493);

  DissertationOptions o;
  o.which = DissertationCase::kPlus;
  const DissertationResult plus = DissertationError(p, o);
  o.which = DissertationCase::kMinus;
  const DissertationResult minus = DissertationError(p, o);
  o.which = DissertationCase::kFirstOrder;
  const DissertationResult first = DissertationError(p, o);

  EXPECT_NEAR(plus.a_rad, 0.000010512, 5e-10);   // A_p
  EXPECT_NEAR(minus.a_rad, 0.000010508, 5e-10);  // A_o
  EXPECT_NEAR(plus.b_rad, 0.000053111, 5e-10);
  EXPECT_NEAR(minus.b_rad, 0.000053109, 5e-10);
  EXPECT_NEAR(plus.c_rad, 0.00006738, 5e-10);  // 9 decimals, trailing 0 dropped
  EXPECT_NEAR(minus.c_rad, 0.00006738, 5e-10);
  EXPECT_NEAR(plus.l, 0.999999998, 5e-10);
  EXPECT_EQ(first.l, 1.0);
  EXPECT_NEAR(plus.norm_um, 54.789011, kTolUm);   // δp
  EXPECT_NEAR(minus.norm_um, 54.789025, kTolUm);  // δo
  EXPECT_NEAR(first.norm_um, 54.789039, kTolUm);  // δ
  // Signed percentages ((δ·/δ) − 1)·100 as printed: −5.08e-5 % and −2.417e-5 %.
  EXPECT_NEAR((plus.norm_um / first.norm_um - 1.0) * 100.0, -5.08e-5, 0.005e-5);
  EXPECT_NEAR((minus.norm_um / first.norm_um - 1.0) * 100.0, -2.417e-5, 0.0005e-5);
}

TEST(model_ch3, LinearGroupingQuirkMatters) {
  // Digest D3.9: grouping ρ by direction (physics) instead of (3.8) moves the appendix point from
  // 54.789039 to 71.620758 µm (independent recomputation by the digest, not printed).
  DissertationOptions o;
  o.group_linear_by_direction = true;
  EXPECT_NEAR(DissertationError(S500PointErrorsAtNode(15, 15, 5), o).norm_um, 71.620758, 1e-5);
  // Same digest table, first-order vector at 3/5/5 as published model.
  const DissertationResult r = DissertationError(S500PointErrorsAtNode(3, 5, 5), {});
  EXPECT_NEAR(r.delta_um.x, 21.313600, 1e-5);
  EXPECT_NEAR(r.delta_um.y, 16.616733, 1e-5);
  EXPECT_NEAR(r.delta_um.z, 8.886333, 1e-5);
}

TEST(model_ch3, ModelVariantMatchesAtNodesAndInterpolates) {
  // The Model-level dissertation variant (tables sampled at positions) equals the row-based
  // formula at nodes: Table 3.7, 6/17/19 = 120/170/190 mm.
  const Model first = S500DissertationModel(Order::kFirst);
  EXPECT_NEAR(Norm(ToolPointError_um(first, {120, 170, 190})), 53.955318, kTolUm);
  const Model plus = S500DissertationModel(Order::kSecond, DissertationCase::kPlus, 50);
  EXPECT_NEAR(Norm(ToolPointError_um(plus, {180, 130, 200})), 63.141004, kTolUm);  // Table 3.11
  // Between nodes: first order is a sum of univariate piecewise-linear functions, so the value
  // half-way between two X nodes is the mean of the node values (other coordinates fixed).
  const Vec3 a = ToolPointError_um(first, {60, 55, 50});
  const Vec3 b = ToolPointError_um(first, {80, 55, 50});
  const Vec3 mid = ToolPointError_um(first, {70, 55, 50});
  EXPECT_NEAR(mid.x, 0.5 * (a.x + b.x), 1e-9);
  EXPECT_NEAR(mid.y, 0.5 * (a.y + b.y), 1e-9);
  EXPECT_NEAR(mid.z, 0.5 * (a.z + b.z), 1e-9);
}

}  // namespace
}  // namespace volcomp::model
