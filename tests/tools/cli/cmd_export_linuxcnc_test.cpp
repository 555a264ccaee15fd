// `volcomp export linuxcnc`, run as main() runs it: from raw readings (the layout of `evaluate
// positioning`) the means per target and direction become the file's trims; the INI lines name
// the joint and the type; warnings and refusals name the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "temp_paths.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::TempPath;

// dev = +10 um moving up, -6 um moving down, at 0, 50, 100 mm; two runs each. One file per test:
// ctest runs the tests of this file as parallel processes, and a shared file could be read while
// another test rewrites it.
std::string RawReadings() {
  const std::string csv =
      TempPath(std::string("export_linuxcnc_raw_") +
               ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".csv");
  std::ofstream(csv) << "target_mm,direction,run,deviation_um\n"
                        "0,up,1,10\n50,up,1,10\n100,up,1,10\n100,down,1,-6\n50,down,1,-6\n"
                        "0,down,1,-6\n0,up,2,10\n50,up,2,10\n100,up,2,10\n100,down,2,-6\n"
                        "50,down,2,-6\n0,down,2,-6\n";
  return csv;
}

TEST(VolcompExportLinuxcnc, FromRawReadings) {
  const std::string csv = RawReadings();
  const std::string dir = TempPath("export_linuxcnc_lcnc");
  // Two runs: refused unless --allow-few-runs (GOST 27843 and ISO 230-2 ask for five).
  auto r = RunCli({"export", "linuxcnc", "--z", csv, "-o", dir});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("require at least 5"), std::string::npos) << r.err;
  r = RunCli({"export", "linuxcnc", "--z", csv, "-o", dir, "--type", "1", "--joints", "Z=4",
              "--allow-few-runs"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string comp = (std::filesystem::path(dir) / "z.comp").string();
  EXPECT_EQ(r.out.rfind("volcomp export linuxcnc (COMP_FILE_TYPE 1, machine units mm: [TRAJ] "
                        "LINEAR_UNITS = mm)\n"
                        "  axis Z: 3 points from 0 to 100 mm, bidirectional, wrote " +
                            comp +
                            "\n\nINI lines to merge into the [JOINT_n] sections the machine's "
                            "INI file has (also in ",
                        0),
            0u)
      << r.out;
  EXPECT_NE(r.out.find("[JOINT_4]\nCOMP_FILE = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("COMP_FILE_TYPE = 1"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("warning: "), std::string::npos) << r.err;  // the few runs
  std::ifstream f(comp);
  double n, fwd, rev;
  int rows = 0;
  while (f >> n >> fwd >> rev) {
    EXPECT_NEAR(fwd, -0.010, 1e-9);  // a constant deviation is undone exactly
    EXPECT_NEAR(rev, 0.006, 1e-9);
    ++rows;
  }
  EXPECT_EQ(rows, 3);
}

TEST(VolcompExportLinuxcnc, MergesIntoAnIniFile) {
  const std::string csv = RawReadings();
  const std::string dir = TempPath("export_linuxcnc_merge");
  const std::string ini = TempPath("export_linuxcnc_machine.ini");
  const std::string before = "[JOINT_0]\nHOME = 0\n\n[JOINT_0]\nCOMP_FILE = x\n";
  std::ofstream(ini) << before;
  const auto r = RunCli({"export", "linuxcnc", "--x", csv, "--z", csv, "-o", dir, "--joints", "Z=2",
                         "--allow-few-runs", "--ini", ini, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string x = std::filesystem::absolute(std::filesystem::path(dir) / "x.comp").string();
  const std::string z = std::filesystem::absolute(std::filesystem::path(dir) / "z.comp").string();
  std::stringstream merged, backup;
  merged << std::ifstream(ini).rdbuf();
  backup << std::ifstream(ini + ".bak").rdbuf();
  EXPECT_EQ(merged.str(), "[JOINT_0]\nHOME = 0\nCOMP_FILE = " + x +
                              "\nCOMP_FILE_TYPE = 1\n\n[JOINT_0]\nCOMP_FILE = x\n\n"
                              "[JOINT_2]\nCOMP_FILE = " +
                              z + "\nCOMP_FILE_TYPE = 1\n");
  EXPECT_EQ(backup.str(), before);
  // The repeated section: a warning on stderr and in the JSON.
  const std::string warning = ini + ": [JOINT_0] appears 2 times (again at line 4)";
  EXPECT_NE(r.err.find("warning: " + warning), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("\"merge_warnings\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(warning), std::string::npos) << r.out;
  // joints.ini says how its lines go in.
  std::stringstream joints;
  joints << std::ifstream(std::filesystem::path(dir) / "joints.ini").rdbuf();
  EXPECT_EQ(joints.str().rfind("# volcomp export linuxcnc: merge these lines", 0), 0u);
  // Two axes on one joint are refused.
  const auto twice = RunCli({"export", "linuxcnc", "--x", csv, "--z", csv, "-o", dir, "--joints",
                             "Z=0", "--allow-few-runs"});
  EXPECT_EQ(twice.code, tools::kExitUsage);
  EXPECT_NE(twice.err.find("--joints: X and Z both on joint 0"), std::string::npos) << twice.err;
}

// An inch machine: readings in inches and microinches (+400 uin up, -240 uin down at 0, 2, 4 in),
// the files in inches ([TRAJ] LINEAR_UNITS = inch): a constant deviation is undone exactly, so the
// trims are -0.000400 and +0.000240 in at the nominals 0, 2, 4 in.
TEST(VolcompExportLinuxcnc, InchMachine) {
  const std::string csv = TempPath("export_linuxcnc_inch.csv");
  std::ofstream(csv) << "target_in,direction,run,deviation_uin\n"
                        "0,up,1,400\n2,up,1,400\n4,up,1,400\n4,down,1,-240\n2,down,1,-240\n"
                        "0,down,1,-240\n0,up,2,400\n2,up,2,400\n4,up,2,400\n4,down,2,-240\n"
                        "2,down,2,-240\n0,down,2,-240\n";
  const std::string dir = TempPath("export_linuxcnc_inch");
  const std::string ini = TempPath("export_linuxcnc_inch_machine.ini");
  const std::string before = "[TRAJ]\nLINEAR_UNITS = inch\n[JOINT_0]\nHOME = 0\n";
  std::ofstream(ini) << before;
  std::filesystem::remove_all(dir);
  // The INI says inch, the default --units is mm: refused before anything is written.
  auto r = RunCli({"export", "linuxcnc", "--x", csv, "-o", dir, "--allow-few-runs", "--ini", ini});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find(ini + ": [TRAJ] LINEAR_UNITS is inch, the tables would be in mm (--units "
                             "mm): give --units in (nothing was written)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir));
  std::stringstream unchanged;
  unchanged << std::ifstream(ini).rdbuf();
  EXPECT_EQ(unchanged.str(), before);

  r = RunCli({"export", "linuxcnc", "--x", csv, "-o", dir, "--allow-few-runs", "--ini", ini,
              "--units", "in", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"linear_units\": \"in\""), std::string::npos) << r.out;
  std::ifstream f(std::filesystem::path(dir) / "x.comp");
  double n, fwd, rev;
  int rows = 0;
  while (f >> n >> fwd >> rev) {
    EXPECT_NEAR(n, 2.0 * rows, 1e-12);
    EXPECT_NEAR(fwd, -0.000400, 1e-12);
    EXPECT_NEAR(rev, 0.000240, 1e-12);
    ++rows;
  }
  EXPECT_EQ(rows, 3);
  std::stringstream joints;
  joints << std::ifstream(std::filesystem::path(dir) / "joints.ini").rdbuf();
  EXPECT_NE(joints.str().find("[TRAJ] LINEAR_UNITS must be inch"), std::string::npos);

  // A spacing in inches: 1 in gives 5 rows, 0 .. 4 in.
  r = RunCli({"export", "linuxcnc", "--x", csv, "-o", dir, "--allow-few-runs", "--units", "in",
              "--spacing", "X=1", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"points\": 5"), std::string::npos) << r.out;

  // An INI whose LINEAR_UNITS volcomp cannot write: refused naming the line.
  std::ofstream(ini) << "[TRAJ]\nLINEAR_UNITS = 0.5\n";
  r = RunCli({"export", "linuxcnc", "--x", csv, "-o", dir, "--allow-few-runs", "--ini", ini});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find(ini + ":2: [TRAJ] LINEAR_UNITS = 0.5"), std::string::npos) << r.err;
}

// The built-in S500 model's positioning errors as the joints' files: X's trim at 0 mm undoes
// E_XX(0) = -0.466667 um (Table 3.2, samples/model/s500_x.csv), to first order.
TEST(VolcompExportLinuxcnc, FromAModel) {
  const std::string dir = TempPath("export_linuxcnc_model");
  const auto r = RunCli({"export", "linuxcnc", "--model", "s500", "-o", dir, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"format\": \"model\""), std::string::npos) << r.out;
  for (const char* f : {"x.comp", "y.comp", "z.comp"}) {
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(dir) / f)) << f;
  }
  std::ifstream x(std::filesystem::path(dir) / "x.comp");
  double n, fwd, rev;
  ASSERT_TRUE(x >> n >> fwd >> rev);
  EXPECT_EQ(n, 0.0);
  EXPECT_NEAR(fwd, 0.000467, 2e-6);
  EXPECT_EQ(fwd, rev);  // a model has one direction

  // A model file is read once: its reader's warning (here: no squareness block) is said once.
  const std::string isg = TempPath("export_linuxcnc_model_isg.csv");
  std::ofstream(isg) << "X EXX EYX EZX EAX EBX ECX\n0 0 0 0 0 0 0\n100 0.004 0 0 0 0 0\n#\n"
                        "Y EXY EYY EZY EAY EBY ECY\n0 0 0 0 0 0 0\n100 0 0.002 0 0 0 0\n#\n"
                        "Z EXZ EYZ EZZ EAZ EBZ ECZ\n0 0 0 0 0 0 0\n100 0 0 0.003 0 0 0\n";
  const auto m = RunCli({"export", "linuxcnc", "--model", isg, "-o", dir});
  ASSERT_EQ(m.code, 0) << m.err;
  const std::size_t first = m.err.find("not in the file, taken as 0");
  ASSERT_NE(first, std::string::npos) << m.err;
  EXPECT_EQ(m.err.find("not in the file, taken as 0", first + 1), std::string::npos) << m.err;
}

TEST(VolcompExportLinuxcnc, OptionsAreChecked) {
  const std::string csv = RawReadings();
  const std::string dir = TempPath("export_linuxcnc_lcnc_opts");
  const auto usage = [](const std::vector<std::string>& words, const std::string& message) {
    const auto r = RunCli(words);
    EXPECT_EQ(r.code, tools::kExitUsage) << message;
    EXPECT_EQ(r.err, "volcomp export linuxcnc: " + message +
                         "\n(`volcomp help export linuxcnc` lists the options)\n");
  };
  usage({"export", "linuxcnc", "--z", csv, "-o", dir, "--type", "2"},
        "--type must be 0 or 1 (LinuxCNC COMP_FILE_TYPE)");
  usage({"export", "linuxcnc", "--z", csv, "-o", dir, "--joints", "Z=16"},
        "--joints: joint of Z must be 0..15");
  usage({"export", "linuxcnc", "--z", csv, "-o", dir, "--spacing", "Z=0"},
        "--spacing: Z must be > 0");
  usage({"export", "linuxcnc", "-o", dir},
        "give at least one axis file, e.g. --x x.csv, or --model FILE");
  usage({"export", "linuxcnc", "--z", csv, "-o", dir, "--units", "inch"},
        "--units must be mm or in");
  // Too many points for LinuxCNC: refused naming the file.
  const auto r = RunCli(
      {"export", "linuxcnc", "--z", csv, "-o", dir, "--spacing", "Z=0.1", "--allow-few-runs"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_EQ(r.err.rfind("warning: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("volcomp export linuxcnc: error: " + csv +
                       ": 1001 compensation points, LinuxCNC loads at most 256"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace volcomp
