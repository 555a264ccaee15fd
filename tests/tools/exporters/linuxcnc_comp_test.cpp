// LinuxCNC joint compensation files: the trims invert the measured deviations (checked against the
// closed-form inverse of a linear deviation), type 0 and type 1 carry the same trims in
// LinuxCNC's two conventions, and LinuxCNC's 256-entry limit is refused with a clear message.
#include "volcomp/exporters/linuxcnc_comp.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "expected_value.hpp"

namespace volcomp::exporters {
namespace {

using model::PositioningData;
using testing::ValueOf;

// Deviation dev(q) = a + b q (µm, q in mm), forward; reverse shifted by `shift_um`.
PositioningData Linear(double a_um, double b_um_per_mm, double shift_um, bool reverse) {
  PositioningData d;
  for (int i = 0; i <= 10; ++i) {
    const double p = 20.0 * i;
    d.position.push_back(p);
    d.dev_forward.push_back(a_um + b_um_per_mm * p);
    if (reverse) d.dev_reverse.push_back(a_um + shift_um + b_um_per_mm * p);
  }
  return d;
}

// Closed form: the command q with q + dev(q)/1000 = t is q = (t - a/1000) / (1 + b/1000) inside
// the tested 0..200 mm (beyond it the deviation holds its end value); the trim LinuxCNC must add
// is q - t (mm).
double Trim(double t, double a_um, double b) {
  double q = (t - a_um / 1000) / (1 + b / 1000);
  if (q < 0) q = t - a_um / 1000;
  if (q > 200) q = t - (a_um + b * 200) / 1000;
  return q - t;
}

TEST(LinuxcncComp, TrimsInvertTheDeviation) {
  const LinuxcncComp c =
      ValueOf(BuildLinuxcncComp(Linear(12.0, -0.08, -5.0, true), LinuxcncCompType::kTrims, 0));
  ASSERT_EQ(c.rows.size(), 11u);
  for (const LinuxcncCompRow& r : c.rows) {
    EXPECT_NEAR(r.forward, Trim(r.nominal, 12.0, -0.08), 1e-9) << r.nominal;
    EXPECT_NEAR(r.reverse, Trim(r.nominal, 7.0, -0.08), 1e-9) << r.nominal;
  }
  EXPECT_DOUBLE_EQ(c.rows.front().nominal, 0.0);
  EXPECT_DOUBLE_EQ(c.rows.back().nominal, 200.0);
}

TEST(LinuxcncComp, TypeZeroHoldsPositionsWithTheSameTrims) {
  const PositioningData d = Linear(-30.0, 0.2, 4.0, true);
  const LinuxcncComp t1 = ValueOf(BuildLinuxcncComp(d, LinuxcncCompType::kTrims, 10.0));
  const LinuxcncComp t0 = ValueOf(BuildLinuxcncComp(d, LinuxcncCompType::kPositions, 10.0));
  ASSERT_EQ(t0.rows.size(), 21u);
  ASSERT_EQ(t1.rows.size(), t0.rows.size());
  for (size_t i = 0; i < t0.rows.size(); ++i) {
    // LinuxCNC (usrmotLoadComp): type 0 trim = nominal - forward.
    EXPECT_NEAR(t0.rows[i].nominal - t0.rows[i].forward, t1.rows[i].forward, 1e-12);
    EXPECT_NEAR(t0.rows[i].nominal - t0.rows[i].reverse, t1.rows[i].reverse, 1e-12);
    // Where the uncompensated axis arrives: nominal + dev(nominal) to first order (the slope
    // 0.2 um/mm times the 0.03 mm trim: 0.006 um).
    EXPECT_NEAR(t0.rows[i].forward, t0.rows[i].nominal + (-30.0 + 0.2 * t0.rows[i].nominal) / 1000,
                1e-5);
  }
}

TEST(LinuxcncComp, OneDirectionGivesEqualReverseTrims) {
  const LinuxcncComp c =
      ValueOf(BuildLinuxcncComp(Linear(5.0, 0.01, 0, false), LinuxcncCompType::kTrims, 0));
  for (const LinuxcncCompRow& r : c.rows) EXPECT_EQ(r.forward, r.reverse);
}

TEST(LinuxcncComp, JointIniLines) {
  EXPECT_EQ(LinuxcncJointIni(4, "/comp/z.comp", LinuxcncCompType::kPositions),
            "[JOINT_4]\nCOMP_FILE = /comp/z.comp\nCOMP_FILE_TYPE = 0\n");
}

TEST(LinuxcncComp, FileIsTripletsOnly) {
  const LinuxcncComp c =
      ValueOf(BuildLinuxcncComp(Linear(1.0, 0.0, 0, false), LinuxcncCompType::kTrims, 0));
  std::istringstream in(FormatLinuxcncComp(c));
  std::string line;
  size_t n = 0;
  while (std::getline(in, line)) {
    double a, b, e;
    char extra;
    EXPECT_EQ(std::sscanf(line.c_str(), "%lf %lf %lf %c", &a, &b, &e, &extra), 3) << line;
    ++n;
  }
  EXPECT_EQ(n, c.rows.size());
}

TEST(LinuxcncComp, MoreThanLinuxcncLoadsIsRefused) {
  const auto refused =
      BuildLinuxcncComp(Linear(1.0, 0.0, 0, false), LinuxcncCompType::kTrims, 0.5);  // 401 rows
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().code, Error::kInvalidArgument);
  EXPECT_EQ(refused.error().message,
            "401 compensation points, LinuxCNC loads at most 256: use a spacing of at least "
            "0.784314");
  EXPECT_EQ(
      ValueOf(BuildLinuxcncComp(Linear(1.0, 0.0, 0, false), LinuxcncCompType::kTrims, 200.0 / 255))
          .rows.size(),
      256u);
}

}  // namespace
}  // namespace volcomp::exporters
