// Reproduction of the dissertation's КМТПП results (Pimushkin 2023, ch. 4: the Mathcad example of
// §4.3 and Tables 4.1-4.4, 4.9), and properties of the project's smooth variant. Expected values
// are the printed ones (seed 001 lines 2270-2790) unless a comment says otherwise.
#include "volcomp/model/kmtpp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "expected_value.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/model/tracker.hpp"

namespace volcomp::model {
namespace {

using datasets::S500AxisTables;
using datasets::S500Tracker315;
using testing::ValueOf;

constexpr double kTolQ = 6e-4;  // printed 3 decimals

void ExpectVecNear(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

// The calibration of the §4.3 listing as it prints it (r01 and l_x, l_y, l_z to 9 decimals, taken
// from the workbook behind Table 2.10-2.12).
KmtppCalibration PrintedCalibration() {
  KmtppCalibration c;
  c.r01_mm = {-0.006368359, -0.002503989, 0.005996301};
  c.lx = {0.999999851, 0.000545926, 0.000015963};
  c.ly = {0.000371486, 0.999999883, 0.000309413};
  c.lz = {0.000497191, 0.00002308, 0.999999876};
  return c;
}

// The same calibration derived by the library from the 7-digit Tables 2.10-2.12.
KmtppCalibration Calibration() {
  TrackerOptions o;
  o.cosines = CosineSource::kSigned;  // interval 15→30 has no negative cosine: same as printed
  return KmtppCalibrationFromTracker(ValueOf(TrackerModel::Create(S500Tracker315(), o)), 1);
}

KmtppResult RunPrinted(double k,
                       double l,
                       const Vec3& target,
                       std::vector<KmtppStep>* trace = nullptr) {
  return ValueOf(
      Kmtpp(S500AxisTables(), PrintedCalibration(), KmtppDissertationOptions(k, l), target, trace));
}

TEST(model_kmtpp, CalibrationFromTheTrackerTablesMatchesThePrintedOne) {
  const KmtppCalibration c = Calibration(), p = PrintedCalibration();
  ExpectVecNear(c.r01_mm, p.r01_mm, 5e-8);
  ExpectVecNear(c.lx, p.lx, 5e-9);
  ExpectVecNear(c.ly, p.ly, 5e-9);
  ExpectVecNear(c.lz, p.lz, 5e-9);
  // Either calibration gives the printed Table 4.1 row l = 1.
  const KmtppResult r =
      ValueOf(Kmtpp(S500AxisTables(), c, KmtppDissertationOptions(1.5, 1.0), {50, 50, 50}));
  ExpectVecNear(r.command_mm, {53.73, 53.718, 53.717}, kTolQ);
}

TEST(model_kmtpp, MathcadExampleOfSection4_3) {
  // q_d = (50, 50, 50), K = 1.5, l = 1, coarse Tables 3.2-3.4.
  std::vector<KmtppStep> trace;
  const KmtppResult r = RunPrinted(1.5, 1.0, {50, 50, 50}, &trace);
  ASSERT_EQ(r.steps, 3);
  ASSERT_EQ(trace.size(), 3u);
  // Step 1.
  ExpectVecNear(trace[0].q_mm, {75, 75, 75}, 1e-12);
  EXPECT_EQ(trace[0].row, (std::array<int, 3>{4, 8, 8}));
  EXPECT_NEAR(trace[0].a_rad, 1.522e-5, 5e-9);
  EXPECT_NEAR(trace[0].b_rad, 5.152e-5, 5e-9);
  EXPECT_NEAR(trace[0].c_rad, 2.634e-5, 5e-9);
  EXPECT_NEAR(trace[0].phi_rad, 5.983e-5, 5e-9);
  ExpectVecNear(trace[0].q1, {0.999999836, 0.000572267, -0.000035549}, 5e-9);
  ExpectVecNear(trace[0].q2, {0.000345163, 0.999999888, 0.000324614}, 5e-9);
  ExpectVecNear(trace[0].q3, {0.00054871, 0.000007873, 0.999999849}, 5e-9);
  // Step 2.
  ExpectVecNear(trace[1].q_mm, {37.5, 37.5, 37.5}, 1e-12);
  EXPECT_EQ(trace[1].row, (std::array<int, 3>{2, 4, 4}));
  EXPECT_NEAR(trace[1].a_rad, 8.55e-6, 5e-9);
  EXPECT_NEAR(trace[1].b_rad, 4.97e-5, 5e-8);
  EXPECT_NEAR(trace[1].c_rad, 1.35e-5, 5e-8);
  EXPECT_NEAR(trace[1].phi_rad, 5.221e-5, 5e-9);
  ExpectVecNear(trace[1].q1, {0.999999843, 0.000559426, -0.000033733}, 5e-9);
  ExpectVecNear(trace[1].q2, {0.000358002, 0.999999885, 0.000317945}, 5e-9);
  ExpectVecNear(trace[1].q3, {0.00054689, 0.000014537, 0.99999985}, 5e-9);
  // The listing shows S = (37.522, 37.526, 37.518) — the state after step 2 (digest ch.4 item 8).
  ExpectVecNear(trace[1].s_mm, {37.522, 37.526, 37.518}, 5e-4);
  // Final.
  ExpectVecNear(r.reached_mm, {56.275495189, 56.286114115, 56.284664996}, 5e-8);
  const double g[9] = {0.99999984, 0.000352542,  0.00054679,  0.000564886, 0.999999887,
                       0.00001231, -0.000033631, 0.000320175, 0.99999985};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(r.g.m[static_cast<std::size_t>(i)], g[i], 5e-9) << i;
  ExpectVecNear(r.command_mm, {53.73, 53.718, 53.717}, kTolQ);
}

struct Row {
  double k, l;
  int m;
  Vec3 q;
};

TEST(model_kmtpp, Table4_1) {
  // q_d = (50, 50, 50), K = 1.5. The printed q of rows l = 0.1 and l = 0.015 are swapped (their m
  // are right; digest ch.4 item 13), so those two rows are checked against each other's q.
  const Row rows[] = {
      {1.5, 1, 3, {53.730, 53.718, 53.717}},
      {1.5, 0.5, 2, {43.103, 53.094, 53.093}},
      {1.5, 0.1, 10, {49.820, 49.813, 49.813}},  // printed in row l = 0.015
      {1.5, 0.05, 21, {49.703, 49.696, 49.695}},
      {1.5, 0.015, 71, {49.914, 49.907, 49.906}},  // printed in row l = 0.1
  };
  for (const Row& r : rows) {
    SCOPED_TRACE(::testing::Message() << "l=" << r.l);
    const KmtppResult res = RunPrinted(r.k, r.l, {50, 50, 50});
    EXPECT_EQ(res.steps, r.m);
    ExpectVecNear(res.command_mm, r.q, kTolQ);
  }
  // The swap is real: the printed l = 0.1 row is not what l = 0.1 gives.
  EXPECT_GT(std::fabs(RunPrinted(1.5, 0.1, {50, 50, 50}).command_mm.x - 49.914), 0.05);
}

TEST(model_kmtpp, Table4_2) {
  // q_d = (50, 50, 50), l = 0.1; row K = 1.5 repeats Table 4.1's swapped value (49.914, ...).
  const Row rows[] = {
      {0.1, 0.1, 161, {49.890, 49.883, 49.882}}, {0.5, 0.1, 32, {49.662, 49.655, 49.654}},
      {1, 0.1, 16, {49.242, 49.235, 49.234}},    {1.5, 0.1, 10, {49.820, 49.813, 49.813}},
      {2, 0.1, 8, {48.365, 48.358, 48.357}},
  };
  for (const Row& r : rows) {
    SCOPED_TRACE(::testing::Message() << "K=" << r.k);
    const KmtppResult res = RunPrinted(r.k, r.l, {50, 50, 50});
    EXPECT_EQ(res.steps, r.m);
    ExpectVecNear(res.command_mm, r.q, kTolQ);
  }
}

TEST(model_kmtpp, Tables4_3And4_4) {
  // q_d = (130, 140, 106). The "q_tr" columns are the computed commands (digest ch.4 item 14).
  const Row rows[] = {
      {1.5, 1, 4, {128.054, 138.668, 106.555}},  // Table 4.3
      {1.5, 0.5, 2, {128.052, 138.672, 106.552}},   {1.5, 0.1, 17, {128.133, 138.759, 106.614}},
      {1.5, 0.05, 34, {129.107, 139.807, 107.408}}, {1.5, 0.015, 116, {129.207, 139.916, 107.489}},
      {1, 1, 1, {139.928, 139.921, 109.926}},  // Table 4.4 (needs round(6.5) = 7)
      {1, 0.5, 4, {128.052, 138.673, 106.551}},     {1, 0.1, 26, {128.328, 138.969, 106.772}},
      {1, 0.05, 52, {128.956, 139.645, 107.285}},
  };
  for (const Row& r : rows) {
    SCOPED_TRACE(::testing::Message() << "K=" << r.k << " l=" << r.l);
    const KmtppResult res = RunPrinted(r.k, r.l, {130, 140, 106});
    EXPECT_EQ(res.steps, r.m);
    ExpectVecNear(res.command_mm, r.q, kTolQ);
  }
}

TEST(model_kmtpp, Table4_4LastRowIsNotReproducible) {
  // Printed m = 152, q = (129.132, 139.957, 107.263) violates the stop rule (140·0.985^152 > 10);
  // the rule gives m = 175 and q = (129.160, 139.865, 107.451) (digest ch.4 item 15).
  const KmtppResult res = RunPrinted(1, 0.015, {130, 140, 106});
  EXPECT_EQ(res.steps, 175);
  ExpectVecNear(res.command_mm, {129.160, 139.865, 107.451}, kTolQ);
  EXPECT_GT(std::fabs(res.command_mm.z - 107.263), 0.1);
}

TEST(model_kmtpp, Table4_9FineTablesAt50_50_50) {
  // Tables 4.5-4.7 are the 2 mm linear refinement of Tables 3.2-3.4 over 0-200 mm.
  std::array<AxisErrorTable, 3> fine;
  for (int a = 0; a < 3; ++a) {
    fine[static_cast<std::size_t>(a)] =
        ValueOf(ValueOf(datasets::S500AxisTable(a)).Resampled(2.0, 200.0));
  }
  const KmtppResult res =
      ValueOf(Kmtpp(fine, Calibration(), KmtppDissertationOptions(1.5, 0.1), {50, 50, 50}));
  EXPECT_EQ(res.steps, 20);
  ExpectVecNear(res.command_mm, {49.917, 49.907, 49.905}, kTolQ);
}

TEST(model_kmtpp, SmoothFinalStepHasNoJumpsThePrintedOneDoes) {
  // Along the diagonal, targets 0.1 mm apart: the printed (grid-node) final step jumps by up to
  // u/2 when the node changes; the traced-point step stays smooth (digest ch.4 §4.3: ≤ 0.14 µm).
  const auto tables = S500AxisTables();
  KmtppOptions smooth;  // defaults: traced point, (4.9) sum
  KmtppOptions printed = KmtppDissertationOptions(1.5, 0.1);
  double max_smooth_um = 0, max_printed_um = 0;
  Vec3 prev_s, prev_p;
  for (int i = 0; i <= 1000; ++i) {
    const double t = 50.0 + 0.1 * i;
    const Vec3 target = {t, t, t};
    const Vec3 s = ValueOf(Kmtpp(tables, Calibration(), smooth, target)).command_mm - target;
    const Vec3 p = ValueOf(Kmtpp(tables, Calibration(), printed, target)).command_mm - target;
    if (i > 0) {
      max_smooth_um = std::fmax(max_smooth_um, 1e3 * MaxAbs(s - prev_s));
      max_printed_um = std::fmax(max_printed_um, 1e3 * MaxAbs(p - prev_p));
    }
    prev_s = s;
    prev_p = p;
  }
  EXPECT_LT(max_smooth_um, 0.5);
  EXPECT_GT(max_printed_um, 1000.0);
}

TEST(model_kmtpp, RejectsBadParameters) {
  KmtppOptions o;
  o.gain = 10;
  o.step = 1;  // K·l = 10: the trace diverges
  const auto r = Kmtpp(S500AxisTables(), Calibration(), o, {50, 50, 50});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, Error::kInvalidArgument);
  EXPECT_EQ(r.error().message, "КМТПП: K·l must lie in (0, 2) for the trace to converge");
}

}  // namespace
}  // namespace volcomp::model
