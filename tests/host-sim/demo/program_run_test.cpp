// `volcomp-sim run` (RunProgramOnMachine): a part program through the real firmware on the
// simulated machine. Outside truths: on a machine without errors the tool point lies on the
// programmed circles to the step (the test's own radius about the programmed centre, not the
// code's path distance); the step audit; refusals name the program line.
#include "volcomp/sim/program_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "expected_value.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::sim {
namespace {

// A machine model with every error zero (the travel of the S500).
std::string WriteZeroModel(const std::string& dir) {
  std::filesystem::create_directories(dir);
  const char* names[] = {"x", "y", "z"};
  const int travel[] = {400, 280, 200};
  for (int a = 0; a < 3; ++a) {
    std::ofstream f(dir + "/zero_" + names[a] + ".csv");
    f << "n,position_mm,ex_um,ey_um,ez_um,ea_um_per_mm,eb_um_per_mm,ec_um_per_mm\n"
      << "0,0,0,0,0,0,0,0\n1," << travel[a] << ",0,0,0,0,0,0\n";
  }
  std::ofstream m(dir + "/zero.conf");
  m << "name = no errors\naxis_x = zero_x.csv\naxis_y = zero_y.csv\naxis_z = zero_z.csv\n"
       "squareness_c0y_urad = 0\nsquareness_b0z_urad = 0\nsquareness_a0z_urad = 0\n"
       "tool_offset_mm = 0, 0, 0\nworkpiece_axes =\ntool_axes = XYZ\n"
       "workpiece_errors = relative\nformulation = physical\norder = exact\n";
  return dir + "/zero.conf";
}

// A circle of radius 20 mm about (200, 140, 100) in `plane` (17, 18, 19): run-in quarter, the full
// circle, run-out quarter, counter-clockwise, at 3000 mm/min.
std::string CircleProgram(int plane) {
  std::ostringstream g;
  g << "G21 G90 G" << plane << "\n";
  if (plane == 17) {
    g << "G0 X220 Y140 Z100\nG3 X200 Y160 I-20 J0 F3000\nG3 X200 Y160 I0 J-20\n"
         "G3 X180 Y140 I0 J-20\n";
  } else if (plane == 18) {  // Z-X plane: first axis Z, second X
    g << "G0 X200 Y140 Z120\nG3 X220 Y140 Z100 I0 K-20 F3000\nG3 X220 Z100 I-20 K0\n"
         "G3 X200 Z80 I-20 K0\n";
  } else {  // Y-Z plane
    g << "G0 X200 Y160 Z100\nG3 Y140 Z120 J-20 K0 F3000\nG3 Y140 Z120 J0 K-20\n"
         "G3 Y120 Z100 J0 K-20\n";
  }
  g << "G0 Z150\nM2\n";
  return g.str();
}

TEST(SimProgramRun, OnAMachineWithoutErrorsTheToolFollowsArcsInEveryPlaneToTheStep) {
  // Each test case its own folder: they run in parallel processes.
  const std::string model = WriteZeroModel(testing::TempPath("program_run_zero_arcs"));
  for (int plane : {17, 18, 19}) {
    ProgramRunOptions o;
    o.program_name = "circle_g" + std::to_string(plane) + ".ngc";
    o.program_text = CircleProgram(plane);
    o.model_spec = model;
    std::ostringstream log;
    const ProgramRunResult r = testing::ValueOf(RunProgramOnMachine(o, log));
    EXPECT_EQ(r.lost_steps, 0u);
    EXPECT_EQ(r.timing_violations, 0u);
    // The tool's radius about the programmed centre, on the full circle (line 4), by the test.
    const int first = plane == 17 ? 0 : plane == 18 ? 2 : 1;
    const int second = plane == 17 ? 1 : plane == 18 ? 0 : 2;
    double worst = 0;
    size_t on_circle = 0;
    for (const PathSample& s : r.samples) {
      if (s.line != 4) continue;
      const double centre[3] = {200, 140, 100};
      const double df = s.tool_mm[static_cast<size_t>(first)] - centre[first];
      const double dg = s.tool_mm[static_cast<size_t>(second)] - centre[second];
      worst = std::max(worst, std::fabs(std::hypot(df, dg) - 20) * 1e3);
      ++on_circle;
    }
    // 2 pi 20 mm at 50 mm/s = 2.51 s of samples every 100 us.
    EXPECT_NEAR(static_cast<double>(on_circle), 2 * M_PI * 20 / 50 / 1e-4, 30) << plane;
    EXPECT_LE(worst, 1.0) << plane;  // each axis within half a step
    EXPECT_LE(r.cutting_max_error_um, 1.0) << plane;
    EXPECT_GT(r.cutting_samples, on_circle);
  }
}

TEST(SimProgramRun, TheBallbarReadsEveryDegreeOfBothDirectionsOnTheMeasuredCircles) {
  // The ISO 230-4 program of `volcomp program circular` shape: CCW then CW, each with run-in and
  // run-out quarters; on a machine without errors G, G(b), H and F are the sensor's resolution and
  // the steps (each axis within half a step).
  ProgramRunOptions o;
  o.program_name = "ballbar.ngc";
  o.program_text =
      "G21 G90 G17 G64\nG0 X200 Y90 Z100\nG3 X250 Y140 I0 J50 F2000\nG3 X250 Y140 I-50 J0\n"
      "G3 X200 Y190 I-50 J0\nG2 X250 Y140 I0 J-50\nG2 X250 Y140 I-50 J0\n"
      "G2 X200 Y90 I-50 J0\nM2\n";
  o.model_spec = WriteZeroModel(testing::TempPath("program_run_zero_ballbar"));
  o.ballbar_pivot_mm = Point3{200, 140, 100};
  std::ostringstream log;
  const ProgramRunResult r = testing::ValueOf(RunProgramOnMachine(o, log));
  ASSERT_TRUE(r.circular.has_value());
  EXPECT_GE(r.circular->points_cw, 359u);
  EXPECT_GE(r.circular->points_ccw, 359u);
  for (double v : {r.circular->G_cw_um, r.circular->G_ccw_um, r.circular->G_b_um, r.circular->H_um,
                   r.circular->F_max_um, -r.circular->F_min_um}) {
    EXPECT_LE(v, 1.6);
  }
  // Only the two measured circles are read (not the run-in and run-out quarters): one reading per
  // degree, angles covering the whole turn.
  double lo = 360, hi = 0;
  for (const BallbarReading& b : r.ballbar) {
    lo = std::min(lo, b.angle_deg);
    hi = std::max(hi, b.angle_deg);
    EXPECT_EQ(b.radius_mm, 50);
  }
  EXPECT_LT(lo, 1.0);
  EXPECT_GT(hi, 359.0);
  EXPECT_LE(r.ballbar.size(), 2u * 361u);
  // ballbar.csv is what `volcomp evaluate circular` reads, and gives the same figures.
  const std::string dir = testing::FreshTempPath("program_run_ballbar");
  ASSERT_TRUE(WriteProgramRunReport(r, dir).ok());
  const tools::CsvTable csv = testing::ValueOf(tools::CsvTable::ReadFile(dir + "/ballbar.csv"));
  const metrology::CircularData data = testing::ValueOf(metrology::ReadCircularCsv(csv, 0));
  const metrology::CircularResult again = testing::ValueOf(metrology::EvaluateCircular(data));
  EXPECT_NEAR(again.G_b_um, r.circular->G_b_um, 0.02);
  EXPECT_NEAR(again.H_um, r.circular->H_um, 0.02);
  // A pivot no measured circle turns about is refused.
  o.ballbar_pivot_mm = Point3{0, 0, 0};
  const auto none = RunProgramOnMachine(o, log);
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.error().message.find("the ballbar read nothing"), std::string::npos);
}

TEST(SimProgramRun, RefusesABadProgramWithItsLineBeforeRunning) {
  ProgramRunOptions o;
  o.program_name = "bad.ngc";
  o.program_text = "G21 G90\nG0 X100 Y100 Z100\nG2 X110 Y100 R2 F600\n";
  std::ostringstream log;
  const auto r = RunProgramOnMachine(o, log);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "bad.ngc:3: R 2.0000 mm is shorter than half the chord (5.0000 mm)");
  o.program_text = "G21\nG33 X1\n";
  const auto g33 = RunProgramOnMachine(o, log);
  ASSERT_FALSE(g33.ok());
  EXPECT_EQ(g33.error().message, "bad.ngc:2: G33 is not supported");
}

TEST(SimProgramRun, ReportWritesEverySampleAndThePlot) {
  ProgramRunOptions o;
  o.program_name = "line.ngc";
  o.program_text = "G21 G90\nG0 X100 Y100 Z100\nG1 X300 F6000\nG4 P0.01\nM2\n";
  std::ostringstream log;
  const ProgramRunResult r = testing::ValueOf(RunProgramOnMachine(o, log));
  const std::string dir = testing::FreshTempPath("program_run_report");
  ASSERT_TRUE(WriteProgramRunReport(r, dir).ok());
  std::ifstream csv(dir + "/samples.csv");
  std::string header, row;
  std::getline(csv, header);
  EXPECT_EQ(header, "t_s,line,kind,x_cmd_mm,y_cmd_mm,z_cmd_mm,x_mm,y_mm,z_mm,error_um");
  size_t rows = 0, cutting = 0;
  while (std::getline(csv, row)) {
    ++rows;
    if (row.find(",cutting,") != std::string::npos) ++cutting;
  }
  EXPECT_EQ(rows, r.samples.size());
  EXPECT_EQ(cutting, r.cutting_samples);
  EXPECT_TRUE(std::filesystem::exists(dir + "/index.html"));
  // The S500's own errors (no table): the rest samples measure them against the work offset.
  EXPECT_GT(r.cutting_max_error_um, 1.0);
}

}  // namespace
}  // namespace volcomp::sim
