// LinuxCNC joint compensation files: the trims invert the measured deviations (checked against the
// closed-form inverse of a linear deviation), type 0 and type 1 carry the same trims in
// LinuxCNC's two conventions, the file ends at the last tested position, LinuxCNC's 256-entry
// limit is refused with a clear message, and the INI lines merge into the machine's [JOINT_n]
// sections (never a second header) with warnings for what a user must know.
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

// An inch machine's file: nominals and trims in inches, the same trims as the mm file / 25.4.
TEST(LinuxcncComp, InchRowsAreTheMmRowsIn25Point4) {
  const PositioningData d = Linear(12.0, -0.08, -5.0, true);
  const LinuxcncComp mm = ValueOf(BuildLinuxcncComp(d, LinuxcncCompType::kTrims, 0));
  const LinuxcncComp in =
      ValueOf(BuildLinuxcncComp(d, LinuxcncCompType::kTrims, 0, LengthUnit::kInch));
  EXPECT_EQ(in.unit, LengthUnit::kInch);
  ASSERT_EQ(in.rows.size(), mm.rows.size());
  for (size_t i = 0; i < in.rows.size(); ++i) {
    EXPECT_NEAR(in.rows[i].nominal * 25.4, mm.rows[i].nominal, 1e-7);
    EXPECT_NEAR(in.rows[i].forward * 25.4, mm.rows[i].forward, 1e-12);
    EXPECT_NEAR(in.rows[i].reverse * 25.4, mm.rows[i].reverse, 1e-12);
  }
  // A spacing in inches: 2 in = 50.8 mm over the 200 mm tested: 0, 2, 4, 6 in and the last
  // tested position, 200 mm = 7.874016 in.
  const LinuxcncComp spaced =
      ValueOf(BuildLinuxcncComp(d, LinuxcncCompType::kTrims, 2.0, LengthUnit::kInch));
  ASSERT_EQ(spaced.rows.size(), 5u);
  EXPECT_DOUBLE_EQ(spaced.rows[3].nominal, 6.0);
  EXPECT_NEAR(spaced.rows[4].nominal, 200 / 25.4, 1e-9);
}

// [TRAJ] LINEAR_UNITS as LinuxCNC reads it (the words of its INI documentation and the sample
// configurations: mm, metric, inch, in, imperial; or units per mm).
TEST(LinuxcncComp, LinearUnitsOfAnIniFile) {
  const auto unit = [](const std::string& ini) {
    return ValueOf(LinuxcncLinearUnits(ini, "m.ini"));
  };
  EXPECT_EQ(unit("[TRAJ]\nLINEAR_UNITS = inch\n"), LengthUnit::kInch);
  EXPECT_EQ(unit("[TRAJ]\nLINEAR_UNITS =          in  # comment\n"), LengthUnit::kInch);
  EXPECT_EQ(unit("[TRAJ]\nLINEAR_UNITS = imperial\n"), LengthUnit::kInch);
  EXPECT_EQ(unit("[TRAJ]\nLINEAR_UNITS = 0.03937\n"), LengthUnit::kInch);
  EXPECT_EQ(unit("[TRAJ]\nLINEAR_UNITS = mm\n"), LengthUnit::kMm);
  EXPECT_EQ(unit("[TRAJ]\nLINEAR_UNITS = metric\n"), LengthUnit::kMm);
  EXPECT_EQ(unit("[TRAJ]\nLINEAR_UNITS =\t1.0\n"), LengthUnit::kMm);
  // Another section's key, or none: not said.
  EXPECT_FALSE(unit("[DISPLAY]\nLINEAR_UNITS = inch\n[TRAJ]\nCOORDINATES = X\n").has_value());
  // The first [TRAJ] section counts.
  EXPECT_EQ(unit("[TRAJ]\nLINEAR_UNITS = mm\n[TRAJ]\nLINEAR_UNITS = inch\n"), LengthUnit::kMm);
  const auto odd = LinuxcncLinearUnits("[EMC]\n[TRAJ]\nLINEAR_UNITS = furlong\n", "m.ini");
  ASSERT_FALSE(odd.ok());
  EXPECT_EQ(odd.error().message.rfind("m.ini:3: [TRAJ] LINEAR_UNITS = furlong", 0), 0u)
      << odd.error().message;
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
            "0.784314 mm");
  EXPECT_EQ(
      ValueOf(BuildLinuxcncComp(Linear(1.0, 0.0, 0, false), LinuxcncCompType::kTrims, 200.0 / 255))
          .rows.size(),
      256u);
}

TEST(LinuxcncComp, EndsAtTheLastTestedPosition) {
  // 0..200 mm at a spacing of 30: the lattice 0, 30, ..., 180, 210 would end 10 mm past the test.
  const LinuxcncComp c =
      ValueOf(BuildLinuxcncComp(Linear(12.0, -0.08, -5.0, true), LinuxcncCompType::kTrims, 30.0));
  ASSERT_EQ(c.rows.size(), 8u);
  EXPECT_DOUBLE_EQ(c.rows[6].nominal, 180.0);
  EXPECT_DOUBLE_EQ(c.rows.back().nominal, 200.0);
  for (const LinuxcncCompRow& r : c.rows) {
    EXPECT_NEAR(r.forward, Trim(r.nominal, 12.0, -0.08), 1e-9) << r.nominal;
    EXPECT_NEAR(r.reverse, Trim(r.nominal, 7.0, -0.08), 1e-9) << r.nominal;
  }
  // A spacing that meets the end exactly keeps its lattice.
  const LinuxcncComp even =
      ValueOf(BuildLinuxcncComp(Linear(12.0, -0.08, -5.0, true), LinuxcncCompType::kTrims, 40.0));
  ASSERT_EQ(even.rows.size(), 6u);
  EXPECT_DOUBLE_EQ(even.rows.back().nominal, 200.0);
}

TEST(LinuxcncComp, MergesIntoTheExistingJointSections) {
  const std::string ini =
      "[KINS]\nJOINTS = 3\n\n[JOINT_0]\nTYPE = LINEAR\n# a comment\nHOME = 0\n\n"
      "[JOINT_1]\nTYPE = LINEAR\nCOMP_FILE = old.comp\nCOMP_FILE_TYPE = 1\nHOME = 0\n\n"
      "[AXIS_X]\nMIN_LIMIT = 0\n";
  const LinuxcncIniMerge m = MergeLinuxcncJointIni(ini,
                                                   {{0, "/c/x.comp", LinuxcncCompType::kTrims},
                                                    {1, "/c/y.comp", LinuxcncCompType::kPositions},
                                                    {2, "/c/z.comp", LinuxcncCompType::kTrims}},
                                                   "machine.ini");
  EXPECT_EQ(m.text,
            "[KINS]\nJOINTS = 3\n\n[JOINT_0]\nTYPE = LINEAR\n# a comment\nHOME = 0\n"
            "COMP_FILE = /c/x.comp\nCOMP_FILE_TYPE = 1\n\n"
            "[JOINT_1]\nTYPE = LINEAR\nCOMP_FILE = /c/y.comp\nCOMP_FILE_TYPE = 0\nHOME = 0\n\n"
            "[AXIS_X]\nMIN_LIMIT = 0\n\n"
            "[JOINT_2]\nCOMP_FILE = /c/z.comp\nCOMP_FILE_TYPE = 1\n");
  ASSERT_EQ(m.warnings.size(), 2u);
  EXPECT_EQ(m.warnings[0], "machine.ini: [JOINT_1] COMP_FILE was old.comp, now /c/y.comp");
  EXPECT_EQ(m.warnings[1], "machine.ini: [JOINT_1] COMP_FILE_TYPE was 1, now 0");
  // Merging again changes nothing and says nothing.
  const LinuxcncIniMerge again =
      MergeLinuxcncJointIni(m.text,
                            {{0, "/c/x.comp", LinuxcncCompType::kTrims},
                             {1, "/c/y.comp", LinuxcncCompType::kPositions},
                             {2, "/c/z.comp", LinuxcncCompType::kTrims}},
                            "machine.ini");
  EXPECT_EQ(again.text, m.text);
  EXPECT_TRUE(again.warnings.empty());
}

TEST(LinuxcncComp, RepeatedSectionIsNamedNotRepeated) {
  // What `cat joints.ini >> machine.ini` leaves: a second [JOINT_0], which LinuxCNC ignores.
  const std::string ini =
      "[JOINT_0]\nHOME = 0\nCOMP_FILE = a.comp\nCOMP_FILE = b.comp\n"
      "[JOINT_0]\nCOMP_FILE = c.comp\n";
  const LinuxcncIniMerge m =
      MergeLinuxcncJointIni(ini, {{0, "/c/x.comp", LinuxcncCompType::kTrims}}, "m.ini");
  EXPECT_EQ(m.text,
            "[JOINT_0]\nHOME = 0\nCOMP_FILE = /c/x.comp\nCOMP_FILE_TYPE = 1\n"
            "[JOINT_0]\nCOMP_FILE = c.comp\n");
  ASSERT_EQ(m.warnings.size(), 3u);
  EXPECT_EQ(m.warnings[0],
            "m.ini: [JOINT_0] appears 2 times (again at line 5): LinuxCNC reads the first only; "
            "the lines went into the first, merge or delete the others");
  EXPECT_EQ(m.warnings[1], "m.ini: [JOINT_0] COMP_FILE was a.comp, now /c/x.comp");
  EXPECT_EQ(m.warnings[2], "m.ini: [JOINT_0] had a second COMP_FILE (b.comp): removed");
}

}  // namespace
}  // namespace volcomp::exporters
