// Reproduction of the dissertation's chapter 3 results (Pimushkin 2023, Tables 3.7-3.15 and
// Appendix А) with the named "dissertation" formulation. Every expected number below is copied from
// the printed tables (seed 001 lines 1795-1900 and 2996-3089); the tolerance 1e-5 µm is the one the
// issue asks for (the printed values carry 6 decimals; inputs are the printed Tables 3.2-3.6).
#include "volcomp/model/dissertation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "expected_value.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/model/rigid_body.hpp"

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

struct GridRow {
  double k;
  int nx, ny, nz;
  double plus_um, minus_um, first_um;  // δ+, δ−, δ as printed
};

// Tables 3.7 (k = 1), 3.8 (0.5), 3.9 (5), 3.10 (10), 3.11 (50), 3.12 (100), 3.13 (1000).
const GridRow kGridRows[] = {
    {1, 3, 5, 5, 28.449109, 28.449111, 28.449118},       // Table 3.7, 3/5/5
    {1, 6, 17, 19, 53.955309, 53.95532, 53.955318},      // Table 3.7, 6/17/19
    {1, 9, 13, 20, 49.983661, 49.983672, 49.983674},     // Table 3.7, 9/13/20
    {1, 7, 14, 11, 49.419014, 49.419023, 49.419024},     // Table 3.7, 7/14/11
    {1, 10, 20, 14, 64.809708, 64.809723, 64.809725},    // Table 3.7, 10/20/14
    {1, 4, 11, 12, 39.485267, 39.485272, 39.485271},     // Table 3.7, 4/11/12
    {0.5, 3, 5, 5, 28.370336, 28.370337, 28.370339},     // Table 3.8, 3/5/5
    {0.5, 6, 17, 19, 53.834281, 53.834284, 53.834284},   // Table 3.8, 6/17/19
    {0.5, 9, 13, 20, 49.873753, 49.873756, 49.873756},   // Table 3.8, 9/13/20
    {0.5, 7, 14, 11, 49.316609, 49.316611, 49.316611},   // Table 3.8, 7/14/11
    {0.5, 10, 20, 14, 64.676917, 64.676921, 64.676922},  // Table 3.8, 10/20/14
    {0.5, 4, 11, 12, 39.410534, 39.410536, 39.410535},   // Table 3.8, 4/11/12
    {5, 3, 5, 5, 29.152728, 29.152795, 29.152943},       // Table 3.9, 3/5/5
    {5, 6, 17, 19, 54.947891, 54.948195, 54.948124},     // Table 3.9, 6/17/19
    {5, 9, 13, 20, 50.88456, 50.884827, 50.884869},      // Table 3.9, 9/13/20
    {5, 7, 14, 11, 50.265387, 50.265628, 50.265634},     // Table 3.9, 7/14/11
    {5, 10, 20, 14, 65.901588, 65.901975, 65.902005},    // Table 3.9, 10/20/14
    {5, 4, 11, 12, 40.118286, 40.118432, 40.118403},     // Table 3.9, 4/11/12
    {10, 3, 5, 5, 30.205137, 30.205458, 30.205997},      // Table 3.10, 3/5/5
    {10, 6, 17, 19, 56.246911, 56.248181, 56.247862},    // Table 3.10, 6/17/19
    {10, 9, 13, 20, 52.062477, 52.063603, 52.063726},    // Table 3.10, 9/13/20
    {10, 7, 14, 11, 51.388448, 51.389474, 51.389454},    // Table 3.10, 7/14/11
    {10, 10, 20, 14, 67.337389, 67.33902, 67.339079},    // Table 3.10, 10/20/14
    {10, 4, 11, 12, 40.994111, 40.99475, 40.994601},     // Table 3.10, 4/11/12
    {50, 3, 5, 5, 43.405378, 43.419629, 43.424703},      // Table 3.11, 3/5/5
    {50, 6, 17, 19, 68.49389, 68.533996, 68.520455},     // Table 3.11, 6/17/19
    {50, 9, 13, 20, 63.141004, 63.177479, 63.173417},    // Table 3.11, 9/13/20
    {50, 7, 14, 11, 62.460727, 62.495631, 62.488362},    // Table 3.11, 7/14/11
    {50, 10, 20, 14, 81.113989, 81.167449, 81.158915},   // Table 3.11, 10/20/14
    {50, 4, 11, 12, 50.699415, 50.723265, 50.714804},    // Table 3.11, 4/11/12
    // Table 3.12 3/5/5: the printed δ− 65.397367 is a copy of δ+ (digest D4 item 14); checked
    // separately below, so here NAN marks "not comparable".
    {100, 3, 5, 5, 65.397367, NAN, 65.463165},               // Table 3.12, 3/5/5
    {100, 6, 17, 19, 86.759787, 86.941687, 86.871489},       // Table 3.12, 6/17/19
    {100, 9, 13, 20, 79.649106, 79.817301, 79.778319},       // Table 3.12, 9/13/20
    {100, 7, 14, 11, 79.633549, 79.797071, 79.747421},       // Table 3.12, 7/14/11
    {100, 10, 20, 14, 102.058171, 102.305887, 102.240111},   // Table 3.12, 10/20/14
    {100, 4, 11, 12, 66.965766, 67.079324, 67.033176},       // Table 3.12, 4/11/12
    {1000, 3, 5, 5, 517.530078, 524.862639, 521.793105},     // Table 3.13, 3/5/5
    {1000, 6, 17, 19, 475.646964, 496.68112, 486.839523},    // Table 3.13, 6/17/19
    {1000, 9, 13, 20, 431.566307, 451.695328, 442.758356},   // Table 3.13, 9/13/20
    {1000, 7, 14, 11, 455.011516, 474.508707, 465.605871},   // Table 3.13, 7/14/11
    {1000, 10, 20, 14, 555.782144, 585.310912, 572.045132},  // Table 3.13, 10/20/14
    {1000, 4, 11, 12, 431.729067, 444.850595, 438.680522},   // Table 3.13, 4/11/12
};

struct PointRow {
  double k;
  double plus_um, minus_um, first_um;
};

// Table 3.14: point M_max (all 18 errors = Table 3.5).
const PointRow kMaxRows[] = {
    {0.5, 117.369557, 117.369555, 117.36956},   {1, 117.352224, 117.352219, 117.352238},
    {5, 117.228659, 117.228546, 117.229021},    {10, 117.111999, 117.111629, 117.11349},
    {50, 117.688717, 117.695519, 117.733795},   {100, 122.053765, 122.157189, 122.26615},
    {1000, 429.035708, 469.562124, 454.539188},
};
// Table 3.15: point M_min (Table 3.6).
const PointRow kMinRows[] = {
    {0.5, 7.845964, 7.845961, 7.845964},        {1, 7.743264, 7.743255, 7.743263},
    {5, 7.149337, 7.149236, 7.149386},          {10, 7.068228, 7.068518, 7.068776},
    {50, 20.88039, 20.930123, 20.908691},       {100, 43.616936, 43.8251, 43.727767},
    {1000, 454.713217, 475.777818, 465.552512},
};

double Delta(const PointErrors& p, double k, DissertationCase which) {
  DissertationOptions o;
  o.k = k;
  o.which = which;
  return DissertationError(p, o).norm_um;
}

TEST(model_ch3, Tables3_7To3_13AtGridNodes) {
  double worst = 0.0;
  for (const GridRow& r : kGridRows) {
    const PointErrors p = S500PointErrorsAtNode(r.nx, r.ny, r.nz);
    SCOPED_TRACE(::testing::Message()
                 << "k=" << r.k << " node " << r.nx << "/" << r.ny << "/" << r.nz);
    const double first = Delta(p, r.k, DissertationCase::kFirstOrder);
    const double plus = Delta(p, r.k, DissertationCase::kPlus);
    const double minus = Delta(p, r.k, DissertationCase::kMinus);
    EXPECT_NEAR(first, r.first_um, kTolUm);
    EXPECT_NEAR(plus, r.plus_um, kTolUm);
    worst = std::fmax(worst, std::fmax(std::fabs(first - r.first_um), std::fabs(plus - r.plus_um)));
    if (!std::isnan(r.minus_um)) {
      EXPECT_NEAR(minus, r.minus_um, kTolUm);
      worst = std::fmax(worst, std::fabs(minus - r.minus_um));
    }
  }
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
  for (const PointRow& r : kMaxRows) {
    SCOPED_TRACE(::testing::Message() << "M_max k=" << r.k);
    EXPECT_NEAR(Delta(S500MaxErrors(), r.k, DissertationCase::kFirstOrder), r.first_um, kTolUm);
    EXPECT_NEAR(Delta(S500MaxErrors(), r.k, DissertationCase::kPlus), r.plus_um, kTolUm);
    EXPECT_NEAR(Delta(S500MaxErrors(), r.k, DissertationCase::kMinus), r.minus_um, kTolUm);
  }
  for (const PointRow& r : kMinRows) {
    SCOPED_TRACE(::testing::Message() << "M_min k=" << r.k);
    EXPECT_NEAR(Delta(S500MinErrors(), r.k, DissertationCase::kFirstOrder), r.first_um, kTolUm);
    EXPECT_NEAR(Delta(S500MinErrors(), r.k, DissertationCase::kPlus), r.plus_um, kTolUm);
    EXPECT_NEAR(Delta(S500MinErrors(), r.k, DissertationCase::kMinus), r.minus_um, kTolUm);
  }
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
