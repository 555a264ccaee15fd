// Axis error tables from CSV: the shipped samples equal the compiled-in data, units convert, and
// bad input gives file:line failures.
#include "volcomp/datasets/axis_table_csv.hpp"

#include <gtest/gtest.h>

#include <string>

#include "expected_value.hpp"
#include "sample_path.hpp"
#include "volcomp/datasets/s500.hpp"

namespace volcomp::datasets {
namespace {

using testing::SamplePath;
using testing::ValueOf;

// The failure's message (kInputInvalid), or "" when the table was read.
std::string ErrorOf(const std::string& csv) {
  const auto table = AxisTableFromCsv(ValueOf(tools::CsvTable::ReadString(csv, "t.csv")));
  if (table.ok()) return "";
  EXPECT_EQ(table.error().code, Error::kInputInvalid) << table.error().message;
  return table.error().message;
}

TEST(datasets_axis_table_csv, SampleAxisTablesEqualTheBuiltInOnes) {
  const char* files[3] = {"model/s500_x.csv", "model/s500_y.csv", "model/s500_z.csv"};
  for (int a = 0; a < 3; ++a) {
    const model::AxisErrorTable f = ValueOf(LoadAxisTableCsv(SamplePath(files[a])));
    const model::AxisErrorTable b = ValueOf(S500AxisTable(a));
    ASSERT_EQ(f.size(), b.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
      EXPECT_EQ(f.position_mm(i), b.position_mm(i));
      for (int j = 0; j < 3; ++j) {
        EXPECT_EQ(f.row(i).linear_um[j], b.row(i).linear_um[j]);
        EXPECT_NEAR(f.row(i).angular_urad[j], b.row(i).angular_urad[j], 1e-12);
      }
    }
  }
}

TEST(datasets_axis_table_csv, ErrorsNameLineAndProblem) {
  const std::string header = "position_mm,ex_um,ey_um,ez_um,ea_urad,eb_urad,ec_urad\n";
  EXPECT_EQ(ErrorOf(header + "0,1,2,3,4,5,6\n10,1,2,x,4,5,6\n"),
            "t.csv:3: column \"ez_um\": \"x\" is not a number");
  EXPECT_EQ(ErrorOf(header + "0,1,2,3,4,5,6\n0,1,2,3,4,5,6\n"),
            "t.csv:3: positions must increase from row to row");
  EXPECT_EQ(ErrorOf(header + "0,1,2,3,4,5,6\n"), "t.csv:1: an axis table needs at least 2 rows");
  EXPECT_EQ(ErrorOf("position_mm,ex_um,ey_um,ez_um,ea_urad,eb_urad\n0,1,2,3,4,5\n"),
            "t.csv:1: missing column \"ec_urad\" (or _mrad, _um_per_mm, _arcsec)");
  EXPECT_EQ(ErrorOf("position_mm,ex_um,ey_um,ez_um,ea_urad,ea_mrad,eb_urad,ec_urad\n"),
            "t.csv:1: columns \"ea_urad\" and \"ea_mrad\" give the same angle twice");
  const auto missing = LoadAxisTableCsv("/nonexistent/x.csv");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().code, Error::kIoError);
  EXPECT_EQ(missing.error().message, "/nonexistent/x.csv: cannot open");
}

TEST(datasets_axis_table_csv, AngleUnitsConvertToMicroradians) {
  // 0.03 µm/mm = 30 µrad; 1 arcsec = 4.848 µrad.
  const model::AxisErrorTable t = ValueOf(AxisTableFromCsv(ValueOf(tools::CsvTable::ReadString(
      "position_mm,ex_um,ey_um,ez_um,ea_um_per_mm,eb_arcsec,ec_mrad\n0,0,0,0,0.03,1,0.002\n"
      "10,0,0,0,0,0,0\n"))));
  EXPECT_NEAR(t.row(0).angular_urad.x, 30, 1e-12);
  EXPECT_NEAR(t.row(0).angular_urad.y, 4.84813681, 1e-8);
  EXPECT_NEAR(t.row(0).angular_urad.z, 2, 1e-12);
}

}  // namespace
}  // namespace volcomp::datasets
