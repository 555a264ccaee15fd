// `volcomp build tracker`, run as main() runs it: the methods on tracker lines, the lattice (also
// measured through a table in force), and the refusals with their exit codes.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "expected_value.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/file_io.hpp"

namespace volcomp {
namespace {

using testing::Appended;
using testing::RunCli;
using testing::SamplePath;
using testing::TempPath;
using testing::ValueOf;

std::string UsageMessage(const std::string& message) {
  return "volcomp build tracker: " + message +
         "\n(`volcomp help build tracker` lists the options)\n";
}

TEST(VolcompBuildTracker, Methods) {
  const std::vector<std::string> a = {"build",
                                      "tracker",
                                      "--points",
                                      SamplePath("model/tracker_s500_315.csv"),
                                      "-o",
                                      TempPath("build_tracker_t.vctb"),
                                      "--resolution-nm",
                                      "X=1000,Y=1000,Z=1000"};
  auto r = RunCli(a);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("volcomp build tracker\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("  method: quasi-differential (exact inverse)\n"), std::string::npos);
  const auto b = Appended(a, {"--method", "interval"});
  r = RunCli(b);
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_EQ(r.err, UsageMessage("the interval method jumps by tens of µm at every cell border (a "
                                "trilinear grid would smear the jumps); use quasi-differential, "
                                "or pass --allow-discontinuous"));
  r = RunCli(Appended(b, {"--allow-discontinuous"}));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("method: interval"), std::string::npos);
  // No forward map for the interval method: the inverse is not checked at the nodes.
  EXPECT_EQ(r.out.find("inverse at the nodes"), std::string::npos) << r.out;
  r = RunCli(Appended(b, {"--allow-discontinuous", "--cosines", "scaled"}));
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_EQ(r.err, UsageMessage("--cosines scaled needs the quasi-differential method: the "
                                "interval method would stretch one cell's step length over the "
                                "whole travel"));
  r = RunCli({"build", "tracker", "--builtin", "s500-315", "--cosines", "printed", "--method",
              "static", "-o", TempPath("build_tracker_t3.vctb"), "--json", "--resolution-nm",
              "X=1000,Y=1000,Z=1000"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"max_inverse_residual_um\""), std::string::npos);
  r = RunCli(
      {"build", "tracker", "--builtin", "s500-999", "-o", TempPath("build_tracker_t4.vctb")});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_EQ(r.err, UsageMessage("--builtin must be s500-315 or s500-240"));
}

TEST(VolcompBuildTracker, LinesThatCannotMakeAModelNameTheData) {
  const std::string path = TempPath("build_tracker_short.csv");
  std::ofstream(path) << "axis,x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n"
                         "X,0,0,0,0,0,0\nX,10,0,0,10,0,0\nX,20,0,0,20,0,0\n"
                         "Y,0,0,0,0,0,0\nY,0,10,0,0,10,0\nY,0,20,0,0,20,0\n"
                         "Z,0,0,0,0,0,0\nZ,0,0,10,0,0,10\nZ,0,0,20,0,0,20\n";
  const auto r =
      RunCli({"build", "tracker", "--points", path, "--static-interval", "5", "-o",
              TempPath("build_tracker_short.vctb"), "--resolution-nm", "X=1000,Y=1000,Z=1000"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_EQ(r.err, "volcomp build tracker: error: " + path +
                       ": tracker: static interval outside the data\n");
}

// A lattice CSV (every node of 0..40 x 0..30 x 0..20 mm every 10 mm, z raised by 1e-6·x·y mm):
// the image holds the inverse, the report names the method; a file with a hole is refused.
TEST(VolcompBuildTracker, Lattice) {
  const std::string path = TempPath("build_tracker_lattice.csv");
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
  const std::string out = TempPath("build_tracker_lattice.vctb");
  auto r = RunCli({"build", "tracker", "--lattice", path, "-o", out, "--resolution-nm",
                   "X=100,Y=100,Z=100", "--element", "float32"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("method: lattice"), std::string::npos) << r.out;
  const image::LoadedImage img = ValueOf(image::ReadImageFile(out));
  const image::ImageEvaluator eval = ValueOf(image::ImageEvaluator::Create(img));
  const int32_t pos[3] = {400000, 300000, 100000};  // (40, 30, 10) mm in 0.1 µm steps
  const bool reverse[3] = {false, false, false};
  int32_t q8[3];
  eval.CorrectionQ8(pos, reverse, q8);
  EXPECT_EQ(q8[0], 0);
  EXPECT_NEAR(q8[2] / 256.0, -1e-6 * 40 * 30 * 1e4, 0.01);  // −1.2 µm = −12 steps
  r = RunCli({"build", "tracker", "--lattice", path, "--builtin", "s500-315"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_EQ(r.err, UsageMessage("give one of --points FILE, --builtin s500-315|s500-240 or "
                                "--lattice FILE"));
  // Options of the lines' methods do not apply to a lattice.
  r = RunCli({"build", "tracker", "--lattice", path, "-o", out, "--resolution-nm",
              "X=100,Y=100,Z=100", "--method", "static"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_EQ(r.err, UsageMessage("option --method does not apply here"));

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
  const std::string in_force = TempPath("build_tracker_in_force.vctb");
  testing::CheckOk(tools::WriteFileBytes(in_force, ValueOf(image::BuildImage(req))));
  const std::string through = TempPath("build_tracker_lattice_through.csv");
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
  const std::string out2 = TempPath("build_tracker_lattice_through.vctb");
  r = RunCli({"build", "tracker", "--lattice", through, "--through", in_force, "-o", out2,
              "--resolution-nm", "X=100,Y=100,Z=100", "--element", "float32"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("  table_in_force: " + in_force + "\n"), std::string::npos) << r.out;
  const image::LoadedImage img2 = ValueOf(image::ReadImageFile(out2));
  ValueOf(image::ImageEvaluator::Create(img2)).CorrectionQ8(pos, reverse, q8);
  EXPECT_NEAR(q8[0] / 256.0, 0, 0.01);
  EXPECT_NEAR(q8[2] / 256.0, -1e-6 * 40 * 30 * 1e4, 0.01);
  // A table in force without a GRID3 cannot be composed.
  r = RunCli({"build", "tracker", "--lattice", through, "--through", SamplePath("model/s500.conf"),
              "-o", out2, "--resolution-nm", "X=100,Y=100,Z=100"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("invalid table image"), std::string::npos) << r.err;
}

// The SpatialAnalyzer samples (hand-written: nodes 0..200 x 0..100 x 0..50 mm, every actual 10 µm
// further in +X and 2 µm higher in Z per 100 mm of X). The exact inverse of p = c + (0.010, 0,
// 0.00002·c.x) mm is c.x = t.x − 0.010, c.z = t.z − 0.00002·(t.x − 0.010): at (100, 50, 25) mm the
// correction is −10 µm in X and −1.9998 µm in Z. XML pairs and ASCII + nominals give one image.
TEST(VolcompBuildTracker, SpatialAnalyzerLattice) {
  const std::string xml_out = TempPath("build_tracker_sa_xml.vctb");
  auto r = RunCli({"build", "tracker", "--lattice", SamplePath("model/tracker_lattice_sa.xml"),
                   "-o", xml_out, "--resolution-nm", "X=100,Y=100,Z=100", "--element", "float32"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("lattice_format: sa-xml"), std::string::npos) << r.out;
  const image::LoadedImage img = ValueOf(image::ReadImageFile(xml_out));
  const image::ImageEvaluator eval = ValueOf(image::ImageEvaluator::Create(img));
  const int32_t pos[3] = {1000000, 500000, 250000};  // (100, 50, 25) mm in 0.1 µm steps
  const bool reverse[3] = {false, false, false};
  int32_t q8[3];
  eval.CorrectionQ8(pos, reverse, q8);
  EXPECT_NEAR(q8[0] / 256.0, -100.0, 0.01);  // −10 µm
  EXPECT_NEAR(q8[1] / 256.0, 0.0, 0.01);
  EXPECT_NEAR(q8[2] / 256.0, -19.998, 0.01);  // −1.9998 µm

  const std::string ascii_out = TempPath("build_tracker_sa_ascii.vctb");
  r = RunCli({"build", "tracker", "--lattice", SamplePath("model/tracker_lattice_sa.txt"),
              "--nominals", SamplePath("model/tracker_lattice_sa_nominals.txt"), "-o", ascii_out,
              "--resolution-nm", "X=100,Y=100,Z=100", "--element", "float32", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"lattice_format\": \"sa-ascii\""), std::string::npos) << r.out;
  const image::LoadedImage ascii_img = ValueOf(image::ReadImageFile(ascii_out));
  const image::ImageEvaluator ascii_eval = ValueOf(image::ImageEvaluator::Create(ascii_img));
  for (const int32_t x : {0, 700000, 2000000}) {
    const int32_t at[3] = {x, 300000, 100000};
    int32_t from_xml[3], from_ascii[3];
    eval.CorrectionQ8(at, reverse, from_xml);
    ascii_eval.CorrectionQ8(at, reverse, from_ascii);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(from_ascii[a], from_xml[a]) << x << " " << a;
  }

  // The ASCII export alone has no commanded nodes.
  r = RunCli({"build", "tracker", "--lattice", SamplePath("model/tracker_lattice_sa.txt"), "-o",
              ascii_out, "--resolution-nm", "X=100,Y=100,Z=100"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_EQ(r.err, UsageMessage(SamplePath("model/tracker_lattice_sa.txt") +
                                " is an SA ASCII export, which holds only the measured points: "
                                "give --nominals FILE with the commanded point of every name"));
  // Forced as CSV, the XML is refused by the CSV reader, with the format it looks like.
  r = RunCli({"build", "tracker", "--lattice", SamplePath("model/tracker_lattice_sa.xml"),
              "--format", "csv", "-o", ascii_out, "--resolution-nm", "X=100,Y=100,Z=100"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("(read as csv; the file looks like sa-xml: --format auto)"),
            std::string::npos)
      << r.err;
  // A name given twice in the measured points.
  const std::string twice = TempPath("build_tracker_sa_twice.txt");
  std::ofstream(twice) << "// SA\nP01 0 0 0\nP02 100 0 0\nP01 0 0 0\n";
  r = RunCli({"build", "tracker", "--lattice", twice, "--nominals",
              SamplePath("model/tracker_lattice_sa_nominals.txt"), "-o", ascii_out,
              "--resolution-nm", "X=100,Y=100,Z=100"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_EQ(r.err, "volcomp build tracker: error: " + twice +
                       ":4: point \"P01\" given twice (first on line 2); every point needs its "
                       "own name to be paired\n");
  r = RunCli({"build", "tracker", "--lattice", twice, "--sa-name-fields", "4", "-o", ascii_out});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_EQ(r.err, UsageMessage("--sa-name-fields 4: a point name has 1 to 3 parts (Collection "
                                "Group Target)"));
}

}  // namespace
}  // namespace volcomp
