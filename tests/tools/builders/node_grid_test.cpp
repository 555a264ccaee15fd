// A GRID3 from corrections at the nodes of a lattice (CSV): units to steps, any row order, and
// refusals naming the line.
#include "volcomp/builders/node_grid.hpp"

#include <gtest/gtest.h>

#include <string>

#include "expected_value.hpp"
#include "volcomp/image/axis_units.hpp"

namespace volcomp::builders {
namespace {

using testing::ValueOf;

Expected<image::GridCorrections> Read(const std::string& text) {
  const std::vector<image::AxisDef> axes =
      ValueOf(image::MakeAxisDefs({'X', 'Y', 'Z'}, "X=1000,Y=500,Z=250", ""));
  return NodeGridFromCsv(ValueOf(tools::CsvTable::ReadString(text, "g.csv")), axes);
}

TEST(builders_node_grid, UnitsBecomeStepsInNodeOrder) {
  std::string csv = "z_mm,y_mm,x_steps,dx_um,dy_steps,dz_um\n";
  for (int k = 1; k >= 0; --k) {
    for (int j = 1; j >= 0; --j) {
      for (int i = 1; i >= 0; --i) {
        csv += std::to_string(k * 5) + "," + std::to_string(j * 2) + "," +
               std::to_string(-10 + i * 40) + "," + std::to_string(i + 2 * j + 4 * k) + ",3,-1\n";
      }
    }
  }
  const image::GridCorrections g = ValueOf(Read(csv));
  EXPECT_EQ(g.lattice[0].origin_steps, -10);
  EXPECT_EQ(g.lattice[0].spacing_steps, 40u);
  EXPECT_EQ(g.lattice[1].spacing_steps, 4000u);   // 2 mm of 0.5 µm
  EXPECT_EQ(g.lattice[2].spacing_steps, 20000u);  // 5 mm of 0.25 µm
  ASSERT_EQ(g.correction_steps.size(), 24u);
  for (int n = 0; n < 8; ++n) {
    EXPECT_DOUBLE_EQ(g.correction_steps[3 * n], n);       // dx µm in steps of 1 µm, node order
    EXPECT_DOUBLE_EQ(g.correction_steps[3 * n + 1], 3);   // already steps
    EXPECT_DOUBLE_EQ(g.correction_steps[3 * n + 2], -4);  // −1 µm in steps of 0.25 µm
  }
}

TEST(builders_node_grid, RefusalsNameTheLine) {
  const std::string head = "x_mm,y_mm,z_mm,dx_um,dy_um,dz_um\n";
  const auto error_of = [](const std::string& text) {
    const auto r = Read(text);
    EXPECT_FALSE(r.ok());
    if (r.ok()) return std::string();
    EXPECT_EQ(r.error().code, Error::kInputInvalid);
    return r.error().message;
  };
  EXPECT_EQ(error_of(head), "g.csv:1: no data rows");
  EXPECT_EQ(error_of(head + "0.0004,0,0,1,2,3\n"),
            "g.csv:2: column \"x_mm\": 0.0004 is not a whole number of steps (0.001000 per step)");
  EXPECT_EQ(error_of(head + "0,0,0,1,2,3\n"), "g.csv:1: axis X needs at least 2 node positions");
  EXPECT_EQ(error_of(head + "0,0,0,1,2,3\n0,0,0,1,2,3\n10,10,10,1,2,3\n"),
            "g.csv:1: lattice 2x2x2 needs 8 rows, found 3");
  // Found by fuzz_csv: a position beyond the int32 step range was converted to int64 (UB).
  EXPECT_EQ(error_of(head + "2.01111e+38,0,0,1,2,3\n"),
            "g.csv:2: column \"x_mm\": 2.01111e+38 is beyond the lattice's step range (at most "
            "2147483647 steps from 0)");
  EXPECT_EQ(error_of("x_steps,y_mm,z_mm,dx_um,dy_um,dz_um\n-9000000000000000000,0,0,1,2,3\n"),
            "g.csv:2: column \"x_steps\": -9000000000000000000 is beyond the lattice's step range "
            "(at most 2147483647 steps from 0)");
}

}  // namespace
}  // namespace volcomp::builders
