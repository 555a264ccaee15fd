// The table-builder commands, run in-process: images are valid, reports say what they must, bad
// input is refused with a clear message.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::tools {
namespace {

std::string Sample(const std::string& name) {
  const char* root = std::getenv("VOLCOMP_SOURCE_DIR");
  return std::string(root ? root : ".") + "/samples/model/" + name;
}

std::string TempPath(const std::string& name) {
  return testing::TempDir() + "volcomp_model_" + name;
}

// Runs a command; returns its stdout. Exceptions propagate.
std::string RunCommand(int (*cmd)(Args&), std::vector<std::string> argv, int* rc = nullptr) {
  Args args(std::move(argv));
  testing::internal::CaptureStdout();
  int code = 0;
  try {
    code = cmd(args);
  } catch (...) {
    testing::internal::GetCapturedStdout();
    throw;
  }
  if (rc != nullptr) *rc = code;
  return testing::internal::GetCapturedStdout();
}

template <typename E>
std::string ErrorOf(int (*cmd)(Args&), std::vector<std::string> argv) {
  try {
    RunCommand(cmd, std::move(argv));
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

TEST(model_cli, BuildModelWritesAValidImageAndReports) {
  const std::string out = TempPath("s500.vctb");
  int rc = -1;
  const std::string report =
      RunCommand(RunBuildModel,
                 {"--model", Sample("s500.conf"), "-o", out, "--resolution-nm",
                  "X=1000,Y=1000,Z=1000", "--table-id", "7"},
                 &rc);
  EXPECT_EQ(rc, 0);
  EXPECT_NE(report.find("predicted interpolation error between nodes"), std::string::npos);
  EXPECT_NE(report.find("inverse at the nodes: worst residual"), std::string::npos);
  const image::LoadedImage img = image::LoadImageFile(out);
  EXPECT_EQ(img.view().table_id, 7u);
  EXPECT_EQ(img.view().axis_count, 3u);
}

TEST(model_cli, BuildModelRefusesCorrectionsBeyondTheBound) {
  const std::string msg = ErrorOf<InputError>(
      RunBuildModel, {"--model", "s500", "-o", TempPath("x.vctb"), "--resolution-nm",
                      "X=1000,Y=1000,Z=1000", "--max-correction-um", "100"});
  EXPECT_NE(msg.find("exceeds the configured bound of 100.0 µm"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--max-correction-um"), std::string::npos) << msg;
}

TEST(model_cli, GridOptionsAreChecked) {
  const std::vector<std::string> base = {"--model", "s500", "-o", TempPath("x.vctb")};
  auto with = [&base](std::vector<std::string> extra) {
    std::vector<std::string> v = base;
    v.insert(v.end(), extra.begin(), extra.end());
    return v;
  };
  EXPECT_NE(ErrorOf<UsageError>(RunBuildModel, with({})).find("needs --resolution-nm"),
            std::string::npos);
  EXPECT_NE(ErrorOf<UsageError>(RunBuildModel, with({"--resolution-nm", "X=300,Y=1000,Z=1000",
                                                     "--spacing-mm", "X=20.00005,Y=10,Z=10"}))
                .find("not a whole number of steps"),
            std::string::npos);
  EXPECT_NE(
      ErrorOf<UsageError>(RunBuildModel, with({"--resolution-nm", "X=1000,Y=1000,Z=1000",
                                               "--spacing-mm", "10", "--max-interp-error-um", "1"}))
          .find("not both"),
      std::string::npos);
  EXPECT_NE(ErrorOf<UsageError>(RunBuildModel, with({"--resolution-nm", "X=1000,Y=1000,Z=1000",
                                                     "--range", "X=5:1"}))
                .find("--range"),
            std::string::npos);
}

TEST(model_cli, BuildTrackerMethods) {
  const std::vector<std::string> res = {"--resolution-nm", "X=1000,Y=1000,Z=1000"};
  std::vector<std::string> a = {"--points", Sample("tracker_s500_315.csv"), "-o",
                                TempPath("t.vctb")};
  a.insert(a.end(), res.begin(), res.end());
  EXPECT_NE(RunCommand(RunBuildTracker, a).find("quasi-differential (exact inverse)"),
            std::string::npos);
  std::vector<std::string> b = a;
  b.insert(b.end(), {"--method", "interval"});
  EXPECT_NE(ErrorOf<UsageError>(RunBuildTracker, b).find("--allow-discontinuous"),
            std::string::npos);
  b.push_back("--allow-discontinuous");
  EXPECT_NE(RunCommand(RunBuildTracker, b).find("method: interval"), std::string::npos);
  std::vector<std::string> s = b;
  s.insert(s.end(), {"--cosines", "scaled"});
  EXPECT_NE(ErrorOf<UsageError>(RunBuildTracker, s).find("needs the quasi-differential method"),
            std::string::npos);
  std::vector<std::string> c = {"--builtin", "s500-315", "--cosines",         "printed", "--method",
                                "static",    "-o",       TempPath("t3.vctb"), "--json"};
  c.insert(c.end(), res.begin(), res.end());
  EXPECT_NE(RunCommand(RunBuildTracker, c).find("\"max_inverse_residual_um\""), std::string::npos);
}

// A lattice CSV (every node of 0..40 x 0..30 x 0..20 mm every 10 mm, z raised by 1e-6·x·y mm):
// the image holds the inverse, the report names the method; a file with a hole is refused.
TEST(model_cli, BuildTrackerLattice) {
  const std::string path = TempPath("lattice.csv");
  {
    std::ofstream f(path);
    f << "x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n";
    for (int z = 0; z <= 20; z += 10) {
      for (int y = 0; y <= 30; y += 10) {
        for (int x = 0; x <= 40; x += 10) {
          f << x << "," << y << "," << z << "," << x << "," << y << "," << z + 1e-6 * x * y << "\n";
        }
      }
    }
  }
  const std::string out = TempPath("lattice.vctb");
  const std::string report =
      RunCommand(RunBuildTracker, {"--lattice", path, "-o", out, "--resolution-nm",
                                   "X=100,Y=100,Z=100", "--element", "float32"});
  EXPECT_NE(report.find("method: lattice"), std::string::npos) << report;
  const image::LoadedImage img(image::ReadFileBytes(out), out);
  const image::ImageEvaluator eval(img);
  const int32_t pos[3] = {400000, 300000, 100000};  // (40, 30, 10) mm in 0.1 µm steps
  const bool reverse[3] = {false, false, false};
  int32_t q8[3];
  eval.CorrectionQ8(pos, reverse, q8);
  EXPECT_EQ(q8[0], 0);
  EXPECT_NEAR(q8[2] / 256.0, -1e-6 * 40 * 30 * 1e4, 0.01);  // −1.2 µm = −12 steps
  EXPECT_NE(ErrorOf<UsageError>(RunBuildTracker, {"--lattice", path, "--builtin", "s500-315"})
                .find("give one of"),
            std::string::npos);

  // The same machine measured through a table in force that adds 5 µm in x everywhere: the
  // readings are 5 µm further in x; with --through the new table holds the same correction.
  image::ImageRequest req;
  for (char name : {'X', 'Y', 'Z'}) {
    image::AxisDef d;
    d.name = name;
    d.resolution_e9 = 100000;
    req.axes.push_back(d);
  }
  image::GridCorrections g;
  for (auto& l : g.lattice) l = {2, -100000, 1000000};
  for (int n = 0; n < 8; ++n) g.correction_steps.insert(g.correction_steps.end(), {50, 0, 0});
  req.grid = g;
  const std::string in_force = TempPath("in_force.vctb");
  image::WriteFileBytes(in_force, image::BuildImage(req));
  const std::string through = TempPath("lattice_through.csv");
  {
    std::ofstream f(through);
    f << "x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n";
    for (int z = 0; z <= 20; z += 10) {
      for (int y = 0; y <= 30; y += 10) {
        for (int x = 0; x <= 40; x += 10) {
          f << x << "," << y << "," << z << "," << x + 0.005 << "," << y << ","
            << z + 1e-6 * (x + 0.005) * y << "\n";
        }
      }
    }
  }
  const std::string out2 = TempPath("lattice_through.vctb");
  RunCommand(RunBuildTracker, {"--lattice", through, "--through", in_force, "-o", out2,
                               "--resolution-nm", "X=100,Y=100,Z=100", "--element", "float32"});
  const image::LoadedImage img2(image::ReadFileBytes(out2), out2);
  image::ImageEvaluator(img2).CorrectionQ8(pos, reverse, q8);
  EXPECT_NEAR(q8[0] / 256.0, 0, 0.01);
  EXPECT_NEAR(q8[2] / 256.0, -1e-6 * 40 * 30 * 1e4, 0.01);
}

TEST(model_cli, BuildKmtppDefaultAndDissertationForm) {
  const std::vector<std::string> base = {
      "--model", "s500", "-o", TempPath("k.vctb"), "--resolution-nm", "X=1000,Y=1000,Z=1000"};
  EXPECT_NE(RunCommand(RunBuildKmtpp, base).find("final_step: traced point"), std::string::npos);
  std::vector<std::string> d = base;
  d.push_back("--dissertation");
  EXPECT_NE(ErrorOf<UsageError>(RunBuildKmtpp, d).find("--allow-discontinuous"), std::string::npos);
}

TEST(model_cli, BuildAxisFromAPositioningTest) {
  const std::string out = TempPath("a.vctb");
  const std::string report =
      RunCommand(RunBuildAxis, {"--x", Sample("positioning_x.csv"), "-o", out, "--resolution-nm",
                                "X=1000", "--reverse", "backlash", "--spacing", "X=20"});
  EXPECT_NE(report.find("21 nodes from 0 every 20 mm"), std::string::npos) << report;
  EXPECT_NE(report.find("backlash 4.0"), std::string::npos) << report;
  EXPECT_EQ(image::LoadImageFile(out).view().axis_count, 1u);
  // A rotary axis given a linear file is refused, naming the file.
  const std::string msg = ErrorOf<InputError>(
      RunBuildAxis, {"--a", Sample("positioning_x.csv"), "-o", out, "--resolution-nm", "A=1000"});
  EXPECT_NE(msg.find("is rotary"), std::string::npos) << msg;
}

// `export linuxcnc` from raw readings (the layout of `evaluate positioning`): the means per target
// and direction become the file's trims; the INI lines name the joint and the type.
TEST(model_cli, ExportLinuxcncFromRawReadings) {
  const std::string csv = TempPath("raw.csv");
  // dev = +10 um moving up, -6 um moving down, at 0, 50, 100 mm; two runs each.
  std::ofstream(csv) << "target_mm,direction,run,deviation_um\n"
                        "0,up,1,10\n50,up,1,10\n100,up,1,10\n100,down,1,-6\n50,down,1,-6\n"
                        "0,down,1,-6\n0,up,2,10\n50,up,2,10\n100,up,2,10\n100,down,2,-6\n"
                        "50,down,2,-6\n0,down,2,-6\n";
  const std::string dir = TempPath("lcnc");
  // Two runs: refused unless --allow-few-runs (GOST 27843 and ISO 230-2 ask for five).
  const std::string few = ErrorOf<InputError>(RunExportLinuxcnc, {"--z", csv, "-o", dir});
  EXPECT_NE(few.find("require at least 5"), std::string::npos) << few;
  const std::string out = RunCommand(RunExportLinuxcnc, {"--z", csv, "-o", dir, "--type", "1",
                                                         "--joints", "Z=4", "--allow-few-runs"});
  EXPECT_NE(out.find("[JOINT_4]\nCOMP_FILE = "), std::string::npos) << out;
  EXPECT_NE(out.find("COMP_FILE_TYPE = 1"), std::string::npos) << out;
  std::ifstream f(dir + "/z.comp");
  double n, fwd, rev;
  int rows = 0;
  while (f >> n >> fwd >> rev) {
    EXPECT_NEAR(fwd, -0.010, 1e-9);  // a constant deviation is undone exactly
    EXPECT_NEAR(rev, 0.006, 1e-9);
    ++rows;
  }
  EXPECT_EQ(rows, 3);
  const std::string msg =
      ErrorOf<UsageError>(RunExportLinuxcnc, {"--z", csv, "-o", dir, "--type", "2"});
  EXPECT_NE(msg.find("--type must be 0 or 1"), std::string::npos) << msg;
}

TEST(model_cli, ModelEvalForwardAndInverse) {
  const std::string points = TempPath("points.csv");
  std::ofstream(points) << "x_mm,y_mm,z_mm\n300,150,50\n";
  // Appendix А in the dissertation formulation: 54.789039 µm (printed δ).
  const std::string out =
      RunCommand(RunModelEval, {"--model", "s500", "--formulation", "dissertation", "--order",
                                "first", "--tool-offset-mm", "10,10,10", points});
  EXPECT_NE(out.find(",54.789039\n"), std::string::npos) << out;
  const std::string inv = RunCommand(RunModelEval, {"--model", "s500", "--inverse", points});
  EXPECT_EQ(inv.rfind("x_mm,y_mm,z_mm,cmd_x_mm", 0), 0u) << inv;
  std::ofstream(points) << "x_mm,y_mm\n1,2\n";
  EXPECT_NE(ErrorOf<InputError>(RunModelEval, {"--model", "s500", points}).find("z_mm"),
            std::string::npos);
  EXPECT_NE(ErrorOf<InputError>(RunModelEval, {"--model", "/nonexistent.conf", points})
                .find("/nonexistent.conf"),
            std::string::npos);
}

}  // namespace
}  // namespace volcomp::tools
