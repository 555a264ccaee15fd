// `volcomp build image` run as main() runs it, on images made by `build grid` and `build axis`
// from the samples: `lookup` of the joined image gives, at every point and direction, the sum of
// what the parts give (the firmware adds GRID3 and AXIS1D corrections); parts that do not belong
// together are refused naming the mismatch, and nothing is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "expected_value.hpp"
#include "file_contents.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/csv.hpp"
#include "volcomp/tools/exit_codes.hpp"
#include "volcomp/tools/file_io.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::SamplePath;
using testing::ValueOf;

struct Parts {
  testing::ScratchDir dir{"build_image"};
  std::string grid = dir / "grid.vct";
  std::string axis = dir / "axis.vct";
  std::string joined = dir / "joined.vct";

  explicit Parts(const std::string& axis_resolution = "X=1000", const std::string& axis_id = "7") {
    auto r = RunCli({"build", "grid", "--csv", SamplePath("grid_example.csv"), "-o", grid,
                     "--resolution-nm", "X=1000,Y=1000,Z=500", "--table-id", "7"});
    EXPECT_EQ(r.code, 0) << r.err;
    r = RunCli({"build", "axis", "--x", SamplePath("metrology/gost27843_example_long.csv"), "-o",
                axis, "--resolution-nm", axis_resolution, "--table-id", axis_id});
    EXPECT_EQ(r.code, 0) << r.err;
  }
};

// The dX, dY, dZ (steps) of `lookup IMAGE --points FILE`, one row per point.
std::vector<std::vector<double>> Lookup(const std::string& image,
                                        const std::string& points,
                                        const std::vector<std::string>& columns) {
  const auto r = RunCli({"lookup", image, "--points", points});
  EXPECT_EQ(r.code, 0) << r.err;
  const tools::CsvTable t = ValueOf(tools::CsvTable::ReadString(r.out, image));
  std::vector<std::vector<double>> rows;
  for (const tools::CsvRow& row : t.rows()) {
    std::vector<double> v;
    for (const std::string& c : columns) v.push_back(ValueOf(row.Number(c)));
    rows.push_back(v);
  }
  return rows;
}

TEST(VolcompBuildImage, JoinedImageCorrectsAsTheSumOfItsParts) {
  Parts p;
  auto r = RunCli({"build", "image", "--grid", p.grid, "--axis", p.axis, "-o", p.joined, "--info",
                   "operator=QA", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  EXPECT_EQ(j.get("table_id")->integer, 7);
  ASSERT_EQ(j.get("axis1d_axes")->array.size(), 1u);
  EXPECT_EQ(j.get("axis1d_axes")->array[0].string, "X");
  r = RunCli({"inspect", p.joined});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("GRID3: int16"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("AXIS1D X:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("operator=QA"), std::string::npos) << r.out;

  std::ostringstream xyz, x;
  xyz << "x_mm,y_mm,z_mm,dir_x\n";
  x << "x_mm,dir_x\n";
  for (int i = 0; i <= 40; ++i) {
    const double xm = -20.0 + 13.7 * i, ym = 7.3 * i, zm = 300.0 - 6.9 * i;
    const int dir = i % 2 == 0 ? 1 : -1;
    xyz << xm << "," << ym << "," << zm << "," << dir << "\n";
    x << xm << "," << dir << "\n";
  }
  const std::string xyz_path = p.dir / "xyz.csv", x_path = p.dir / "x.csv";
  testing::WriteText(xyz_path, xyz.str());
  testing::WriteText(x_path, x.str());
  const auto joined = Lookup(p.joined, xyz_path, {"dx_steps", "dy_steps", "dz_steps"});
  const auto grid = Lookup(p.grid, xyz_path, {"dx_steps", "dy_steps", "dz_steps"});
  const auto axis = Lookup(p.axis, x_path, {"dx_steps"});
  ASSERT_EQ(joined.size(), 41u);
  ASSERT_EQ(grid.size(), 41u);
  ASSERT_EQ(axis.size(), 41u);
  bool axis_matters = false;
  for (std::size_t i = 0; i < joined.size(); ++i) {
    EXPECT_DOUBLE_EQ(joined[i][0], grid[i][0] + axis[i][0]) << "point " << i;
    EXPECT_DOUBLE_EQ(joined[i][1], grid[i][1]) << "point " << i;
    EXPECT_DOUBLE_EQ(joined[i][2], grid[i][2]) << "point " << i;
    axis_matters = axis_matters || axis[i][0] != 0.0;
  }
  EXPECT_TRUE(axis_matters);
}

TEST(VolcompBuildImage, PartsThatDoNotBelongTogetherAreRefused) {
  {
    Parts p("X=500");
    const auto r = RunCli({"build", "image", "--grid", p.grid, "--axis", p.axis, "-o", p.joined});
    EXPECT_EQ(r.code, tools::kExitFailed);
    EXPECT_NE(
        r.err.find("the images do not belong together: axis X is 1000 steps/mm (1000 nm/step) in " +
                   p.grid + " but 2000 steps/mm (500 nm/step) in " + p.axis),
        std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(p.joined));
  }
  {
    Parts p("X=1000", "9");
    auto r = RunCli({"build", "image", "--grid", p.grid, "--axis", p.axis, "-o", p.joined});
    EXPECT_EQ(r.code, tools::kExitFailed);
    EXPECT_NE(r.err.find("table id 7 in " + p.grid + " but 9 in " + p.axis), std::string::npos)
        << r.err;
    r = RunCli(
        {"build", "image", "--grid", p.grid, "--axis", p.axis, "-o", p.joined, "--table-id", "9"});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("table id 9"), std::string::npos) << r.out;
    // The parts swapped.
    r = RunCli({"build", "image", "--grid", p.axis, "--axis", p.grid, "-o", p.dir / "x.vct"});
    EXPECT_EQ(r.code, tools::kExitFailed);
    EXPECT_NE(r.err.find(p.axis + ": no GRID3 section"), std::string::npos) << r.err;
  }
  auto r = RunCli({"build", "image", "--grid", "g.vct", "-o", "c.vct"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  r = RunCli({"build", "image", "--grid", "g.vct", "--axis", "a.vct", "-o", "g.vct"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  r = RunCli({"build", "image", "--grid", "/nonexistent/g.vct", "--axis", "a.vct", "-o", "c.vct"});
  EXPECT_EQ(r.code, tools::kExitFailed);
}

// The joined image is the one the board gets: `--board FILE` checks it against the board's
// settings file before it is written (as `build model` does), here the bank size: the joined
// image's own size passes, one byte less is refused and nothing is written.
TEST(VolcompBuildImage, BoardFileChecksTheJoinedImage) {
  Parts p;
  const std::string board = p.dir / "board.ini";
  ASSERT_TRUE(tools::WriteTextFile(board,
                                   "[board]\naxes = X Y Z\n[axis X]\n[axis Y]\n[axis Z]\n"
                                   "units_per_step = 0.0005\n")
                  .ok());
  auto r = RunCli({"build", "image", "--grid", p.grid, "--axis", p.axis, "-o", p.joined, "--board",
                   board, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue d = ValueOf(tools::ParseJson(r.out, "stdout"));
  ASSERT_NE(d.get("board_check"), nullptr) << r.out;
  const int64_t size = d.get("bytes")->integer;
  EXPECT_EQ(d.get("board_check")->get("image_bytes")->integer, size);
  EXPECT_TRUE(d.get("board_check")->get("problems")->array.empty());
  std::filesystem::remove(p.joined);
  r = RunCli({"build", "image", "--grid", p.grid, "--axis", p.axis, "-o", p.joined, "--board",
              board, "--bank-bytes", std::to_string(size - 1)});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("the image of " + std::to_string(size) +
                       " bytes does not fit the board's table bank of " + std::to_string(size - 1) +
                       " bytes"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(p.joined));
}

}  // namespace
}  // namespace volcomp
