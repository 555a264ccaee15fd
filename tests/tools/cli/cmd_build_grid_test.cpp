// `volcomp build grid`: an image from corrections at the nodes of a lattice, the file named on
// stderr; bad input refused naming the line, bad options with the usage exit code.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "cli_runner.hpp"
#include "expected_value.hpp"
#include "file_contents.hpp"
#include "node_grid_csv.hpp"
#include "temp_paths.hpp"
#include "volcomp/image/image_reader.hpp"

namespace volcomp {
namespace {

using testing::kSmallGridCsv;
using testing::RunCli;
using testing::TempPath;
using testing::ValueOf;
using testing::WriteText;

TEST(VolcompBuildGrid, WritesTheImageAndNamesItOnStderr) {
  const std::string csv = TempPath("build_grid_grid_ok.csv"),
                    img = TempPath("build_grid_grid_ok.vct");
  WriteText(csv, kSmallGridCsv);
  const auto r = RunCli({"build", "grid", "--csv", csv, "-o", img, "--steps-per-unit",
                         "X=1000,Y=1000,Z=1000", "--table-id", "3"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const image::LoadedImage loaded = ValueOf(image::ReadImageFile(img));
  EXPECT_EQ(r.err, "wrote " + img + ": " + std::to_string(loaded.size()) + " bytes, 2x2x2 nodes\n");
  EXPECT_EQ(loaded.view().table_id, 3u);
  EXPECT_NE(std::string(loaded.view().info, loaded.view().info_size).find("source=" + csv),
            std::string::npos);
}

TEST(VolcompBuildGrid, ErrorsNameTheLine) {
  const std::string csv = TempPath("build_grid_bad.csv"), img = TempPath("build_grid_bad.vct");
  struct Case {
    std::string text, expected;
  };
  const std::string head = "x_mm,y_mm,z_mm,dx_um,dy_um,dz_um\n";
  std::string full;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        full += std::to_string(i * 10) + "," + std::to_string(j * 10) + "," +
                std::to_string(k * 10) + ",1,2,3\n";
  const Case cases[] = {
      {"x_mm,y_mm,z_mm,dx_um,dy_um\n0,0,0,1,2\n", "bad.csv:1: missing column \"dz_um\""},
      {head + "0,0,0,1,2,x\n", "bad.csv:2: column \"dz_um\": \"x\" is not a number"},
      {head + "0.0004,0,0,1,2,3\n",
       "bad.csv:2: column \"x_mm\": 0.0004 is not a whole number of steps"},
      {head + full.substr(0, full.rfind('\n', full.size() - 2) + 1),
       "lattice 2x2x2 needs 8 rows, found 7"},
      {head + full + "0,0,0,1,1,1\n", "lattice 2x2x2 needs 8 rows, found 9"},
      {head + "0,0,0,1,2,3\n", "axis X needs at least 2 node positions"},
      {head + "0,0,0,1,2,3\n10,0,0,1,2,3\n25,0,0,1,2,3\n", "not equally spaced"},
      {head + full + "", ""},  // valid
      {head + "0,0,0,1,2,3\n0,10,0,1,2,3\n0,0,10,1,2,3\n0,10,10,1,2,3\n10,0,0,1,2,3\n10,10,0,1,2,"
              "3\n10,0,10,1,2,3\n0,0,10,9,9,9\n",
       "bad.csv:9: node repeats line 4"},
      {head + "0,0,0,1e6,2,3\n10,0,0,1,2,3\n0,10,0,1,2,3\n10,10,0,1,2,3\n0,0,10,1,2,3\n10,0,10,1,2,"
              "3\n0,10,10,1,2,3\n10,10,10,1,2,3\n",
       "exceeds the maximum correction"},
  };
  for (const Case& c : cases) {
    WriteText(csv, c.text);
    const auto r = RunCli(
        {"build", "grid", "--csv", csv, "-o", img, "--resolution-nm", "X=1000,Y=1000,Z=1000"});
    if (c.expected.empty()) {
      EXPECT_EQ(r.code, 0) << r.err;
    } else {
      EXPECT_EQ(r.code, 1) << c.expected;
      EXPECT_NE(r.err.find(c.expected), std::string::npos) << "got: " << r.err;
    }
  }
  // Usage errors.
  EXPECT_EQ(RunCli({"build", "grid", "--csv", csv}).code, 2);
  EXPECT_EQ(RunCli({"build", "grid", "--csv", csv, "-o", img}).code, 2);  // no resolution
  EXPECT_EQ(
      RunCli({"build", "grid", "--csv", csv, "-o", img, "--resolution-nm", "X=1,Y=1,Q=1"}).code, 2);
  EXPECT_EQ(RunCli({"build", "grid", "--csv", csv, "-o", img, "--resolution-nm", "X=1,Y=1,Z=1",
                    "--bogus"})
                .code,
            2);
}

}  // namespace
}  // namespace volcomp
