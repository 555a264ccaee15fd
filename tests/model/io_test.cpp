// Input files: the shipped samples equal the compiled-in data, and bad input gives file:line
// errors.
#include "volcomp/model/io.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "volcomp/model/s500.hpp"
#include "volcomp/model/tracker.hpp"

namespace volcomp::model {
namespace {

std::string Sample(const std::string& name) {
  const char* root = std::getenv("VOLCOMP_SOURCE_DIR");
  return std::string(root ? root : ".") + "/samples/model/" + name;
}

std::string ErrorOf(const std::string& csv) {
  try {
    AxisTableFromCsv(tools::CsvTable::ParseString(csv, "t.csv"));
  } catch (const tools::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(model_io, SampleAxisTablesEqualTheBuiltInOnes) {
  const char* files[3] = {"s500_x.csv", "s500_y.csv", "s500_z.csv"};
  for (int a = 0; a < 3; ++a) {
    const AxisErrorTable f = LoadAxisTableCsv(Sample(files[a]));
    const AxisErrorTable b = S500AxisTable(a);
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

TEST(model_io, SampleConfigEqualsTheBuiltInModel) {
  const Model f = LoadModelConfig(Sample("s500.conf"));
  const Model b = S500Model();
  EXPECT_EQ(f.squareness.c0y_urad, b.squareness.c0y_urad);
  EXPECT_EQ(f.squareness.b0z_urad, b.squareness.b0z_urad);
  EXPECT_EQ(f.squareness.a0z_urad, b.squareness.a0z_urad);
  EXPECT_EQ(f.chain.ToString(), b.chain.ToString());
  EXPECT_EQ(f.order, b.order);
  for (const Vec3& p : {Vec3{0, 0, 0}, Vec3{123, 45, 67}, Vec3{400, 280, 200}}) {
    EXPECT_NEAR(Norm(ToolPointError_um(f, p) - ToolPointError_um(b, p)), 0.0, 1e-9);
  }
}

TEST(model_io, SampleTrackerFileEqualsTheBuiltInData) {
  const TrackerData f = LoadTrackerCsv(Sample("tracker_s500_315.csv"));
  const TrackerData b = S500Tracker315();
  ASSERT_TRUE(f.has_printed_cosines);
  for (int a = 0; a < 3; ++a) {
    ASSERT_EQ(f.lines[a].size(), b.lines[a].size());
    for (std::size_t i = 0; i < f.lines[a].size(); ++i) {
      EXPECT_EQ(f.lines[a][i].q_mm, b.lines[a][i].q_mm);
      EXPECT_EQ(Norm(f.lines[a][i].p_mm - b.lines[a][i].p_mm), 0.0);
      EXPECT_EQ(Norm(f.lines[a][i].printed_cos - b.lines[a][i].printed_cos), 0.0);
    }
  }
  EXPECT_EQ(LoadTrackerCsv(Sample("tracker_s500_240.csv")).lines[2].size(), 17u);
}

TEST(model_io, AxisTableErrorsNameLineAndProblem) {
  const std::string header = "position_mm,ex_um,ey_um,ez_um,ea_urad,eb_urad,ec_urad\n";
  EXPECT_EQ(ErrorOf(header + "0,1,2,3,4,5,6\n10,1,2,x,4,5,6\n"),
            "t.csv:3: column \"ez_um\": \"x\" is not a number");
  EXPECT_NE(ErrorOf(header + "0,1,2,3,4,5,6\n0,1,2,3,4,5,6\n")
                .find("t.csv:3: positions must "
                      "increase"),
            std::string::npos);
  EXPECT_NE(ErrorOf(header + "0,1,2,3,4,5,6\n").find("at least 2 rows"), std::string::npos);
  EXPECT_NE(ErrorOf("position_mm,ex_um,ey_um,ez_um,ea_urad,eb_urad\n0,1,2,3,4,5\n")
                .find("missing column \"ec_urad\""),
            std::string::npos);
  EXPECT_NE(ErrorOf("position_mm,ex_um,ey_um,ez_um,ea_urad,ea_mrad,eb_urad,ec_urad\n")
                .find("same angle twice"),
            std::string::npos);
  // Units: 0.03 µm/mm = 30 µrad; 1 arcsec = 4.848 µrad.
  const AxisErrorTable t = AxisTableFromCsv(tools::CsvTable::ParseString(
      "position_mm,ex_um,ey_um,ez_um,ea_um_per_mm,eb_arcsec,ec_mrad\n0,0,0,0,0.03,1,0.002\n"
      "10,0,0,0,0,0,0\n"));
  EXPECT_NEAR(t.row(0).angular_urad.x, 30, 1e-12);
  EXPECT_NEAR(t.row(0).angular_urad.y, 4.84813681, 1e-8);
  EXPECT_NEAR(t.row(0).angular_urad.z, 2, 1e-12);
}

TEST(model_io, ConfigErrorsNameLineAndProblem) {
  const auto error_of = [](const std::string& text) -> std::string {
    try {
      ModelFromConfigText(text, "m.conf", ".");
    } catch (const tools::InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error_of("builtin = s500\n\nsquareness_c0y_urad = abc\n"),
            "m.conf:3: squareness_c0y_urad: \"abc\" is not a number");
  EXPECT_EQ(error_of("builtin = s500\ncolour = red\n"), "m.conf:2: unknown key \"colour\"");
  EXPECT_EQ(error_of("builtin = s500\norder = first\norder = exact\n"),
            "m.conf:3: key \"order\" repeats line 2");
  EXPECT_EQ(error_of("builtin = s500\ntool_axes = XYZX\n"),
            "m.conf:2: chain: axis X appears twice");
  EXPECT_EQ(error_of("builtin = s500\ntool_offset_mm = 1, 2\n"),
            "m.conf:2: tool_offset_mm needs three numbers: X, Y, Z");
  EXPECT_NE(error_of("name = nothing\n").find("no table for axis X"), std::string::npos);
  EXPECT_NE(error_of("axis_x = /nonexistent/x.csv\n").find("/nonexistent/x.csv"),
            std::string::npos);
  EXPECT_EQ(error_of("just words\n"), "m.conf:1: expected `key = value`, got \"just words\"");
  // A valid override of the built-in model.
  const Model m = ModelFromConfigText(
      "builtin = s500\norder = first\ntool_offset_mm = 0, 0, 100\nworkpiece_axes = Y\n"
      "tool_axes = XZ\n",
      "m.conf", ".");
  EXPECT_EQ(m.order, Order::kFirst);
  EXPECT_EQ(m.tool_offset_mm.z, 100);
  EXPECT_EQ(m.chain.ToString(), "Y|XZ");
}

TEST(model_io, TrackerErrorsNameLineAndProblem) {
  const auto error_of = [](const std::string& text) -> std::string {
    try {
      TrackerDataFromCsv(tools::CsvTable::ParseString(text, "tr.csv"));
    } catch (const tools::InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string h = "axis,x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm\n";
  EXPECT_EQ(error_of(h + "Q,0,0,0,0,0,0\n"), "tr.csv:2: axis must be X, Y or Z, got \"Q\"");
  EXPECT_NE(error_of(h + "X,0,0,0,0,0,0\nX,15,1,0,15,0,0\n")
                .find("tr.csv:3: the X line must "
                      "keep y_cmd_mm at 0"),
            std::string::npos);
  EXPECT_NE(error_of(h + "X,15,0,0,0,0,0\n").find("tr.csv:2: the X line must start"),
            std::string::npos);
  EXPECT_NE(error_of(h + "X,0,0,0,0,0,0\nX,15,0,0,15,0,0\nX,25,0,0,25,0,0\n")
                .find("tr.csv:4: the X line must be equally spaced"),
            std::string::npos);
  EXPECT_NE(error_of(h + "X,0,0,0,0,0,0\nX,15,0,0,15,0,0\nX,30,0,0,30,0,0\n")
                .find("the Y line needs at least 3 nodes"),
            std::string::npos);
}

}  // namespace
}  // namespace volcomp::model
