// Tracker lines and lattices from CSV: the shipped samples equal the compiled-in data, lattices in
// any row order, and bad input gives file:line failures.
#include "volcomp/datasets/tracker_csv.hpp"

#include <gtest/gtest.h>

#include <string>

#include "expected_value.hpp"
#include "sample_path.hpp"
#include "volcomp/datasets/s500.hpp"

namespace volcomp::datasets {
namespace {

using testing::SamplePath;
using testing::ValueOf;

tools::CsvTable Csv(const std::string& text, const std::string& source) {
  return ValueOf(tools::CsvTable::ReadString(text, source));
}

TEST(datasets_tracker_csv, SampleTrackerFileEqualsTheBuiltInData) {
  const model::TrackerData f = ValueOf(LoadTrackerCsv(SamplePath("model/tracker_s500_315.csv")));
  const model::TrackerData b = S500Tracker315();
  ASSERT_TRUE(f.has_printed_cosines);
  for (int a = 0; a < 3; ++a) {
    ASSERT_EQ(f.lines[a].size(), b.lines[a].size());
    for (std::size_t i = 0; i < f.lines[a].size(); ++i) {
      EXPECT_EQ(f.lines[a][i].q_mm, b.lines[a][i].q_mm);
      EXPECT_EQ(Norm(f.lines[a][i].p_mm - b.lines[a][i].p_mm), 0.0);
      EXPECT_EQ(Norm(f.lines[a][i].printed_cos - b.lines[a][i].printed_cos), 0.0);
    }
  }
  EXPECT_EQ(ValueOf(LoadTrackerCsv(SamplePath("model/tracker_s500_240.csv"))).lines[2].size(), 17u);
}

TEST(datasets_tracker_csv, LineErrorsNameLineAndProblem) {
  const auto error_of = [](const std::string& text) -> std::string {
    const auto r = TrackerDataFromCsv(Csv(text, "tr.csv"));
    if (r.ok()) return "";
    EXPECT_EQ(r.error().code, Error::kInputInvalid) << r.error().message;
    return r.error().message;
  };
  const std::string h = "axis,x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n";
  EXPECT_EQ(error_of(h + "Q,0,0,0,0,0,0\n"), "tr.csv:2: axis must be X, Y or Z, got \"Q\"");
  EXPECT_EQ(error_of(h + "X,0,0,0,0,0,0\nX,15,1,0,15,0,0\n"),
            "tr.csv:3: the X line must keep y_cmd_mm at 0 (the lines run through a common "
            "origin)");
  EXPECT_EQ(error_of(h + "X,15,0,0,0,0,0\n"),
            "tr.csv:2: the X line must start at its origin node (commanded 0)");
  EXPECT_EQ(error_of(h + "X,0,0,0,0,0,0\nX,15,0,0,15,0,0\nX,25,0,0,25,0,0\n"),
            "tr.csv:4: the X line must be equally spaced (step 15.000000 mm)");
  EXPECT_EQ(error_of(h + "X,0,0,0,0,0,0\nX,15,0,0,15,0,0\nX,30,0,0,30,0,0\n"),
            "tr.csv: tracker: the Y line needs at least 3 nodes");
  EXPECT_EQ(error_of("axis,x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm,cos_x\n"),
            "tr.csv:1: give all of cos_x, cos_y, cos_z or none");
}

TEST(datasets_tracker_csv, LatticeInAnyOrderAndHolesRefused) {
  std::string csv = "x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n";
  for (int k = 0; k < 2; ++k) {
    for (int j = 0; j < 3; ++j) {
      for (int i = 1; i >= 0; --i) {  // any order
        csv += std::to_string(i * 10) + "," + std::to_string(j * 20) + "," + std::to_string(k * 5) +
               "," + std::to_string(i * 10 + 0.001) + "," + std::to_string(j * 20) + "," +
               std::to_string(k * 5 - 0.002 * j) + "\n";
      }
    }
  }
  const model::TrackerLatticeData d = ValueOf(TrackerLatticeFromCsv(Csv(csv, "t.csv")));
  EXPECT_EQ(d.lattice[0].nodes, 2u);
  EXPECT_EQ(d.lattice[1].nodes, 3u);
  EXPECT_EQ(d.lattice[2].nodes, 2u);
  EXPECT_DOUBLE_EQ(d.lattice[1].spacing_mm, 20.0);
  const model::TrackerLattice lattice = ValueOf(model::TrackerLattice::Create(d));
  EXPECT_NEAR(lattice.Position_mm({10, 40, 5}).z, 5 - 0.004, 1e-12);

  const auto error_of = [](const std::string& text) -> std::string {
    const auto r = TrackerLatticeFromCsv(Csv(text, "t.csv"));
    if (r.ok()) return "";
    EXPECT_EQ(r.error().code, Error::kInputInvalid) << r.error().message;
    return r.error().message;
  };
  // Drop one node: refused with the count.
  const std::string holed = csv.substr(0, csv.rfind('\n', csv.size() - 2) + 1);
  EXPECT_EQ(error_of(holed), "t.csv:1: 11 nodes for a 2x3x2 lattice (12 needed)");
  // A node given twice.
  EXPECT_EQ(error_of(csv + "0,0,0,0,0,0\n"), "t.csv:14: node given twice (first on line 3)");
  EXPECT_EQ(error_of("x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n0,0,0,0,0,0\n"),
            "t.csv:1: the lattice needs at least 2 nodes along X");
}

}  // namespace
}  // namespace volcomp::datasets
