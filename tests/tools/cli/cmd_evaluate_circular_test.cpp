// `volcomp evaluate circular` run as main() runs it: the hand-worked ISO 230-4 case of
// tests/tools/metrology/circular_test.cpp through the command (text, JSON keys, SVG, report),
// the sample of samples/metrology/ against the figures it was made with, and refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "expected_value.hpp"
#include "file_contents.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/exit_codes.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::SamplePath;
using testing::ValueOf;

// The hand-worked case (circular_test.cpp HandWorkedCase: G_cw 8, G_ccw 5 + 3/√2, G(b) 10.5,
// H 8 at 90°, F 12 / −5, centre (3, 3.5)), as a ';' file with decimal commas, CW descending.
std::string HandCaseCsv() {
  std::ostringstream s;
  s << "# machine: MILL-7\ndirection;angle_deg;deviation_um\n";
  const double kPi = 3.14159265358979323846;
  for (int dir = 0; dir < 2; ++dir) {
    for (int j = 0; j < 8; ++j) {
      const int k = dir == 0 ? (8 - j) % 8 : j;
      const double t = 45.0 * k * kPi / 180.0;
      double v = 3 * std::cos(t) + 2 * std::sin(t) + 4 * std::cos(2 * t);
      v += dir == 0 ? 5.0 : 1.0 + (k == 2 ? 12.0 : 0.0);
      std::ostringstream num;
      num.precision(12);
      num << v;
      std::string text = num.str();
      for (char& c : text) c = c == '.' ? ',' : c;
      s << (dir == 0 ? "CW" : "ccw") << ";" << 45 * k << ";" << text << "\n";
    }
  }
  return s.str();
}

TEST(EvaluateCircularCli, HandWorkedCaseAsJson) {
  const auto r = RunCli({"evaluate", "circular", "-", "--json"}, HandCaseCsv());
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  EXPECT_NEAR(j.get("G_cw_um")->number, 8.0, 1e-9);
  EXPECT_NEAR(j.get("G_ccw_um")->number, 5.0 + 3.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(j.get("G_b_um")->number, 10.5, 1e-9);
  EXPECT_NEAR(j.get("H_um")->number, 8.0, 1e-9);
  EXPECT_NEAR(j.get("F_max_um")->number, 12.0, 1e-9);
  EXPECT_NEAR(j.get("F_min_um")->number, -5.0, 1e-9);
  const tools::JsonValue* offset = j.get("centre_offset_um");
  ASSERT_NE(offset, nullptr);
  EXPECT_NEAR(offset->get("x")->number, 3.0, 1e-9);
  EXPECT_NEAR(offset->get("y")->number, 3.5, 1e-9);
  EXPECT_EQ(j.get("conditions")->get("machine")->string, "MILL-7");
}

TEST(EvaluateCircularCli, HandWorkedCaseAsText) {
  const auto r = RunCli({"evaluate", "circular", "-"}, HandCaseCsv());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("conditions: machine MILL-7"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("circular deviation G  CW 8.00 µm, CCW 7.12 µm"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("bidirectional G(b)    10.50 µm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("circular hysteresis H 8.00 µm at 90.0°"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("radial deviation F    max 12.00 µm, min -5.00 µm"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("centre offset         (3.00, 3.50) µm"), std::string::npos) << r.out;
}

TEST(EvaluateCircularCli, OneDirectionLeavesBothDirectionFiguresNull) {
  const auto r = RunCli({"evaluate", "circular", "-", "--json"},
                        "direction,angle_deg,deviation_um\ncw,0,1\ncw,120,2\ncw,240,3\n");
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  EXPECT_TRUE(j.get("G_ccw_um")->is_null());
  EXPECT_TRUE(j.get("G_b_um")->is_null());
  EXPECT_TRUE(j.get("H_um")->is_null());
  EXPECT_FALSE(j.get("G_cw_um")->is_null());
  const auto t = RunCli({"evaluate", "circular", "-"},
                        "direction,angle_deg,deviation_um\ncw,0,1\ncw,120,2\ncw,240,3\n");
  EXPECT_NE(t.out.find("bidirectional G(b)    -"), std::string::npos) << t.out;
}

// The sample was made with a centre offset (8, −5) µm, a radius 1.2 µm long, lost motion and
// reversal spikes (samples/metrology/generate_samples.py circular()).
TEST(EvaluateCircularCli, SampleShowsTheFiguresItWasMadeWith) {
  testing::ScratchDir dir("evaluate_circular");
  const std::string svg = dir / "polar.svg";
  const auto r = RunCli({"evaluate", "circular", SamplePath("metrology/circular_xy.csv"), "--json",
                         "--svg", svg, "--report", dir.path()});
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  EXPECT_NEAR(j.get("centre_offset_um")->get("x")->number, 8.0, 0.3);
  EXPECT_NEAR(j.get("centre_offset_um")->get("y")->number, -5.0, 0.3);
  // Lost motion 6 µm in X: the two paths are 6 µm apart (plus spikes) near 0° and 180°.
  EXPECT_GT(j.get("H_um")->number, 6.0);
  EXPECT_GE(j.get("G_b_um")->number, j.get("G_cw_um")->number);
  EXPECT_GE(j.get("G_b_um")->number, j.get("G_ccw_um")->number);
  EXPECT_EQ(j.get("warnings")->array.size(), 0u);
  EXPECT_EQ(j.get("paths")->get("cw")->get("angle_deg")->array.size(), 360u);
  EXPECT_EQ(j.get("paths")->get("ccw")->get("deviation_um")->array.size(), 360u);
  const std::string plot = testing::ReadText(svg);
  EXPECT_NE(plot.find("<svg"), std::string::npos);
  EXPECT_NE(plot.find("CCW"), std::string::npos);
  const std::string html = testing::ReadText(dir / "circular_circular_xy.html");
  EXPECT_NE(html.find("ISO 230-4"), std::string::npos);
  EXPECT_NE(html.find("MILL-7"), std::string::npos);
  EXPECT_NE(testing::ReadText(dir / "circular_circular_xy.json").find("\"G_b_um\""),
            std::string::npos);
}

TEST(EvaluateCircularCli, RadiiWithTheNominalRadius) {
  const std::string csv =
      "direction,angle_deg,radius_mm\nccw,0,100.003\nccw,90,100.001\nccw,180,99.999\n"
      "ccw,270,100.001\n";
  auto r = RunCli({"evaluate", "circular", "-", "--radius", "100", "--json"}, csv);
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  EXPECT_NEAR(j.get("F_max_um")->number, 3.0, 1e-6);
  EXPECT_NEAR(j.get("F_min_um")->number, -1.0, 1e-6);
  EXPECT_NEAR(j.get("centre_offset_um")->get("x")->number, 2.0, 1e-6);
  EXPECT_NEAR(j.get("nominal_radius_mm")->number, 100.0, 1e-12);
  r = RunCli({"evaluate", "circular", "-"}, csv);
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("<stdin>:1: column \"radius_mm\" holds measured radii: give the nominal "
                       "radius with --radius"),
            std::string::npos)
      << r.err;
}

// The budget by hand (reading U 0.5 µm, drift 1 µm, calibrator U 1 µm, material 21 °C, steel,
// R = 100 mm from the preamble): G, G(b), H: √(0.5² + 0.6²) = √0.61 = 0.78102; F: instrument
// √(0.25 + 1) = 1.11803, thermometer 0.6·11.5·0.1·0.2 = 0.138, expansion 0.6·0.1·1·2 = 0.12,
// environment 0.6: √(1.25 + 0.019044 + 0.0144 + 0.36) = √1.643444 = 1.28197.
TEST(EvaluateCircularCli, EachFigureWithItsUncertainty) {
  const std::string csv = "# nominal_radius_mm: 100\n# calibrator_u_um: 1\n" + HandCaseCsv();
  const std::vector<std::string> args = {
      "evaluate", "circular",         "-", "--instrument-u-um",
      "0.5",      "--drift-range-um", "1", "--material-temperature-c",
      "21"};
  auto r = RunCli(args, csv);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("bidirectional G(b)    10.50 ± 0.78 µm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("max 12.00 ± 1.28 µm, min -5.00 ± 1.28 µm"), std::string::npos) << r.out;
  auto json_args = args;
  json_args.push_back("--json");
  r = RunCli(json_args, csv);
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  const tools::JsonValue& u = *j.get("uncertainty");
  EXPECT_NEAR(u.get("shape_U_um")->number, std::sqrt(0.61), 1e-12);
  EXPECT_NEAR(u.get("F_U_um")->number, std::sqrt(1.643444), 1e-12);
  EXPECT_NEAR(u.get("F")->get("length_mm")->number, 100.0, 0.0);
  EXPECT_EQ(u.get("F")->get("local_U_um"), nullptr);  // F stands for one length only
  // No radius: F without U, said; no reading U: no budget, said; a ppm accuracy: refused.
  r = RunCli({"evaluate", "circular", "-", "--instrument-u-um", "0.5"}, HandCaseCsv());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("F has no U: the nominal radius is not known"), std::string::npos);
  EXPECT_NE(r.out.find("max 12.00 µm, min -5.00 µm"), std::string::npos) << r.out;
  r = RunCli({"evaluate", "circular", "-"}, HandCaseCsv());
  EXPECT_NE(r.err.find("no measurement uncertainty: state the U (k = 2) of one radial reading"),
            std::string::npos);
  r = RunCli({"evaluate", "circular", "-", "--instrument-ppm", "1"}, HandCaseCsv());
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("a ppm accuracy or a beam misalignment does not apply"), std::string::npos);
}

TEST(EvaluateCircularCli, Refusals) {
  auto r = RunCli({"evaluate", "circular"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  r = RunCli({"evaluate", "circular", "x.csv", "--radius", "-5"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--radius must be positive"), std::string::npos) << r.err;
  r = RunCli({"evaluate", "circular", "-"},
             "direction,angle_deg,deviation_um\ncw,0,1\nclockwise,90,2\n");
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("volcomp evaluate circular: error: <stdin>:3: column \"direction\": "
                       "\"clockwise\" is neither cw nor ccw"),
            std::string::npos)
      << r.err;
  r = RunCli({"evaluate", "circular", "-"}, "direction,deviation_um\ncw,1\n");
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("<stdin>:1: missing column \"angle_deg\""), std::string::npos) << r.err;
  r = RunCli({"evaluate", "circular", "-"},
             "direction,angle_deg,deviation_um\nccw,0,1\nccw,90,1\nccw,0,2\n");
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("the counter-clockwise (ccw) path has readings at 2 distinct angle(s)"),
            std::string::npos)
      << r.err;
  r = RunCli({"evaluate", "circular", "/nonexistent/c.csv"});
  EXPECT_EQ(r.code, tools::kExitFailed);
}

}  // namespace
}  // namespace volcomp
