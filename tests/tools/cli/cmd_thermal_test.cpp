// `volcomp evaluate thermal` and `volcomp build thermal` run as main() runs them: a hand-worked
// drift test through the commands (JSON figures, the same figures in the text, chart and report
// files), the sample drift test of samples/metrology/ against the model it was generated with
// (generate_samples.py drift_test), the sign convention end to end (a drift of +d, fitted into an
// image, read back and applied by the board's ThermalCorrection, is a correction of -d), and the
// refusals.
#include <gtest/gtest.h>

#include <string>

#include "cli_runner.hpp"
#include "expected_value.hpp"
#include "file_contents.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/thermal/thermal_model.hpp"
#include "volcomp/tools/exit_codes.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using report::FormatSigned;
using testing::RunCli;
using testing::SamplePath;
using testing::ValueOf;

bool Has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// X at 0 and 100 mm, channel "a" 20 → 22 °C: drift +3 at 0 mm, +5 at 100 mm. By hand
// (tests/tools/builders/thermal_fit_test.cpp): correction offset -2 µm/K, slope -10 µm/(K·m)
// about p0 = 50 mm. Evaluation: drift 3 and 5, rate over the whole test (< 1 h):
// 3 µm in 3600 s = 3 µm/h and 5 µm/h; offset at 50 mm (3 + 5)/2 = 4 µm at t = 3600 s, where
// X 100's drift is interpolated between (10 s, 0) and (3610 s, 5): 5·3590/3600.
const char* const kHandCase =
    "# machine: MILL-7\n"
    "time_s,axis,position_mm,deviation_um,T_a_C\n"
    "0,X,0,1.0,20\n"
    "10,X,100,-2.0,20\n"
    "3600,X,0,4.0,22\n"
    "3610,X,100,3.0,22\n";

TEST(EvaluateThermalCli, HandWorkedCaseAsJsonAndText) {
  const auto r = RunCli({"evaluate", "thermal", "-", "--json"}, kHandCase);
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  EXPECT_EQ(j.get("command")->string, "evaluate thermal");
  EXPECT_EQ(j.get("conditions")->get("machine")->string, "MILL-7");
  EXPECT_EQ(j.get("readings")->integer, 4);
  EXPECT_DOUBLE_EQ(j.get("rate_window_s")->number, 3600);
  const tools::JsonValue& x = j.get("axes")->array.at(0);
  EXPECT_EQ(x.get("axis")->string, "X");
  const tools::JsonValue& p0 = x.get("points")->array.at(0);
  const tools::JsonValue& p1 = x.get("points")->array.at(1);
  EXPECT_DOUBLE_EQ(p0.get("max_drift_um")->number, 3);
  EXPECT_DOUBLE_EQ(p0.get("max_drift_time_s")->number, 3600);
  EXPECT_DOUBLE_EQ(p1.get("range_um")->number, 5);
  EXPECT_NEAR(p0.get("rate_um_per_h")->number, 3, 1e-12);
  EXPECT_NEAR(p1.get("rate_um_per_h")->number, 5, 1e-12);
  EXPECT_EQ(p1.get("drift_um")->array.size(), 2u);
  const double d1 = 5.0 * 3590.0 / 3600.0;
  EXPECT_NEAR(x.get("final")->get("offset_um")->number, (3 + d1) / 2, 1e-12);
  EXPECT_NEAR(x.get("final")->get("slope_um_per_m")->number, (d1 - 3) * 10, 1e-9);
  const tools::JsonValue& a = j.get("channels")->array.at(0);
  EXPECT_EQ(a.get("name")->string, "a");
  EXPECT_EQ(a.get("channel")->integer, 0);
  EXPECT_DOUBLE_EQ(a.get("rise_K")->number, 2);

  // The text shows the same figures.
  const auto t = RunCli({"evaluate", "thermal", "-"}, kHandCase);
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_TRUE(Has(t.out, "4 readings over 1.00 h")) << t.out;
  EXPECT_TRUE(Has(t.out, "  0                   +3.00   1.00       3.00     +3.00      +3.00"))
      << t.out;
  EXPECT_TRUE(Has(t.out, "  100                 +5.00   1.00       5.00     +5.00      +5.00"))
      << t.out;
  EXPECT_TRUE(Has(t.out, "offset at 50 mm: " + FormatSigned((3 + d1) / 2, 2) + " µm at 1.00 h"))
      << t.out;
  EXPECT_TRUE(Has(t.out, "slope: " + FormatSigned((d1 - 3) * 10, 2) + " µm/m")) << t.out;
  EXPECT_TRUE(Has(t.out, "0 a              20.00 →   22.00  (min 20.00, max 22.00)  rise +2.00 K"))
      << t.out;
}

TEST(EvaluateThermalCli, SampleTextShowsEveryJsonFigure) {
  const std::string file = SamplePath("metrology/thermal_drift.csv");
  const auto r = RunCli({"evaluate", "thermal", file, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  const auto t = RunCli({"evaluate", "thermal", file});
  ASSERT_EQ(t.code, 0) << t.err;
  ASSERT_EQ(j.get("axes")->array.size(), 2u);
  for (const tools::JsonValue& axis : j.get("axes")->array) {
    for (const tools::JsonValue& p : axis.get("points")->array) {
      for (const char* key : {"max_drift_um", "final_drift_um", "rate_um_per_h"}) {
        EXPECT_TRUE(Has(t.out, FormatSigned(p.get(key)->number, 2))) << key << "\n" << t.out;
      }
    }
    EXPECT_TRUE(
        Has(t.out, FormatSigned(axis.get("max_slope")->get("slope_um_per_m")->number, 2) + " µm/m"))
        << t.out;
  }
  ASSERT_EQ(j.get("channels")->array.size(), 3u);
  for (const tools::JsonValue& c : j.get("channels")->array) {
    EXPECT_TRUE(Has(t.out, "rise " + FormatSigned(c.get("rise_K")->number, 2) + " K")) << t.out;
  }
  // The sample's first row: bed 19.99, spindle 20.00, ambient 20.00 °C.
  EXPECT_DOUBLE_EQ(j.get("channels")->array[0].get("first_C")->number, 19.99);
  EXPECT_EQ(j.get("channels")->array[1].get("name")->string, "spindle");
}

TEST(EvaluateThermalCli, WritesTheChartAndTheReport) {
  testing::ScratchDir dir("thermal_eval");
  const auto r = RunCli({"evaluate", "thermal", SamplePath("metrology/thermal_drift.csv"), "--svg",
                         dir / "drift.svg", "--report", dir / "reports"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string svg = testing::ReadText(dir / "drift.svg");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_TRUE(Has(svg, "X 550 mm"));
  EXPECT_TRUE(Has(svg, "1 spindle"));
  EXPECT_TRUE(Has(testing::ReadText(dir / "reports/thermal_thermal_drift.html"), "<svg"));
  const tools::JsonValue j = ValueOf(
      tools::ParseJson(testing::ReadText(dir / "reports/thermal_thermal_drift.json"), "report"));
  EXPECT_EQ(j.get("command")->string, "evaluate thermal");
}

TEST(EvaluateThermalCli, AnErrorNamesTheFileLineAndColumn) {
  const auto r = RunCli({"evaluate", "thermal", "-"},
                        "time_s,axis,position_mm,deviation_um\n0,X,0,0\n1,X,5,x\n");
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_TRUE(Has(r.err, "<stdin>:3: column \"deviation_um\": \"x\" is not a number")) << r.err;
}

// The board's correction of image axis `axis` at `p_mm` once channel 0 reads `t_cC` for long
// enough to slew there (ThermalCorrection, lib/thermal: the code the board runs).
float BoardCorrection(const thermal::ThermalModel& m, uint8_t axis, float p_mm, int16_t t_cC) {
  thermal::TemperatureChannels channels;
  thermal::ChannelConfig c;
  c.source = thermal::ChannelSource::kCanObject;
  c.timeout_ms = 60000;
  c.max_rate_cC_s = 10000;
  EXPECT_TRUE(channels.Configure(0, c, 0).ok());
  thermal::ThermalCorrection correction;
  EXPECT_TRUE(correction.Configure(m, 100).ok());
  for (uint32_t now = 100; now <= 400000; now += 100) {
    EXPECT_TRUE(channels.Reading(0, t_cC, now).ok());
    correction.Update(channels);
  }
  EXPECT_FALSE(correction.status().slewing);
  return correction.CorrectionAt_um(axis, p_mm);
}

TEST(BuildThermalCli, ADriftIsCorrectedWithTheOppositeSignEndToEnd) {
  testing::ScratchDir dir("thermal_sign");
  testing::WriteText(dir / "drift.csv", kHandCase);
  ASSERT_EQ(RunCli({"build", "grid", "--csv", SamplePath("grid_example.csv"), "-o", dir / "g.vct",
                    "--resolution-nm", "X=1000,Y=1000,Z=500"})
                .code,
            0);
  const auto r = RunCli({"build", "thermal", dir / "drift.csv", "--image", dir / "g.vct", "-o",
                         dir / "gt.vct", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  EXPECT_EQ(j.get("sign")->string, "correction = -drift");
  const tools::JsonValue& x = j.get("axes")->array.at(0);
  EXPECT_NEAR(x.get("offset_um_per_K")->array[0].number, -2, 1e-9);
  EXPECT_NEAR(x.get("slope_um_per_K_m")->array[0].number, -10, 1e-9);
  EXPECT_EQ(x.get("reach_from")->string, "image");  // the grid covers X 0..500 mm: reach 450
  EXPECT_DOUBLE_EQ(x.get("reach_mm")->number, 450);
  EXPECT_EQ(j.get("image")->get("replaced_thermal")->boolean, false);

  const image::LoadedImage img = ValueOf(image::ReadImageFile(dir / "gt.vct"));
  ASSERT_NE(img.view().thermal, nullptr);
  const thermal::ThermalModel m = table::ReadThermal(img.view().thermal);
  EXPECT_EQ(m.reference_cC[0], 2000);
  EXPECT_EQ(m.calibrated_high_cC[0], 2200);
  // At 22 °C the drift was +3 µm at 0 mm and +5 µm at 100 mm: the board corrects -3 and -5.
  EXPECT_NEAR(BoardCorrection(m, 0, 0.0f, 2200), -3.0f, 1e-4);
  EXPECT_NEAR(BoardCorrection(m, 0, 100.0f, 2200), -5.0f, 1e-4);
  EXPECT_NEAR(BoardCorrection(m, 1, 100.0f, 2200), 0.0f, 1e-6);  // Y: not in the test

  // The text shows the JSON's figures.
  const auto t = RunCli({"build", "thermal", dir / "drift.csv"});
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_TRUE(Has(t.out, "  a                   -2.0000         -10.0000")) << t.out;
  EXPECT_TRUE(Has(t.out, "0 a: reference 20.00 °C (first reading), calibrated over 20.00 .. 22.00"))
      << t.out;
  EXPECT_TRUE(Has(t.out, "axis X: p0 50 mm, reach 50 mm (from the points), 2 samples")) << t.out;
  EXPECT_TRUE(Has(t.out, "residual RMS 0.000 µm, max 0.000 µm; explained 100.00 %")) << t.out;
  EXPECT_TRUE(Has(t.out, "no image written")) << t.out;
}

TEST(BuildThermalCli, TheSampleGivesTheModelItWasGeneratedWith) {
  // generate_samples.py drift_test: as a correction about p0 (X 300, Y 250 mm)
  //   X: offset bed -3.45, spindle -1.5 µm/K; slope bed -11.5 µm/(K·m)
  //   Y: offset bed -1.5, spindle +0.8 µm/K; slope bed -6.0 µm/(K·m); noise 0.1 µm, 0.01 K.
  const auto r = RunCli({"build", "thermal", SamplePath("metrology/thermal_drift.csv"),
                         "--channels", "bed,spindle", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  const auto& axes = j.get("axes")->array;
  ASSERT_EQ(axes.size(), 2u);
  const double offsets[2][2] = {{-3.45, -1.5}, {-1.5, 0.8}};
  const double slopes[2][2] = {{-11.5, 0}, {-6.0, 0}};
  for (int a = 0; a < 2; ++a) {
    for (int c = 0; c < 2; ++c) {
      EXPECT_NEAR(axes[a].get("offset_um_per_K")->array[c].number, offsets[a][c], 0.1) << a << c;
      EXPECT_NEAR(axes[a].get("slope_um_per_K_m")->array[c].number, slopes[a][c], 0.5) << a << c;
    }
    EXPECT_LT(axes[a].get("residual_rms_um")->number, 0.2);
    EXPECT_GT(axes[a].get("explained")->number, 0.99);
  }
  EXPECT_DOUBLE_EQ(axes[0].get("p0_mm")->number, 300);
  EXPECT_DOUBLE_EQ(axes[1].get("p0_mm")->number, 250);
  const auto& channels = j.get("channels")->array;
  EXPECT_EQ(channels[1].get("name")->string, "spindle");
  EXPECT_EQ(channels[1].get("channel")->integer, 1);
  EXPECT_DOUBLE_EQ(channels[1].get("max_C")->number, 29.63);  // the file's highest spindle value
}

TEST(BuildThermalCli, Refusals) {
  testing::ScratchDir dir("thermal_refusals");
  testing::WriteText(dir / "drift.csv", kHandCase);
  auto r = RunCli({"build", "thermal", dir / "drift.csv", "--image", dir / "none.vct"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_TRUE(Has(r.err, "--image IN and -o OUT go together")) << r.err;
  r = RunCli({"build", "thermal", dir / "drift.csv", "--reference-C", "a=warm"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_TRUE(Has(r.err, "--reference-C takes a temperature")) << r.err;
  r = RunCli({"build", "thermal", dir / "drift.csv", "--channels", "b"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_TRUE(Has(r.err, "\"b\" is not a channel")) << r.err;
  // Two sensors side by side: refused, naming both.
  r = RunCli({"build", "thermal", "-"},
             "time_s,axis,position_mm,deviation_um,T_a_C,T_a2_C\n"
             "0,X,0,0,20,21\n1,X,9,0,20,21\n5,X,0,1,21,22\n6,X,9,2,21,22\n"
             "9,X,0,3,23,24\n10,X,9,2,23,24\n");
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_TRUE(Has(r.err, "channels a and a2 move together")) << r.err;
  // An axis of the test that the image lacks.
  ASSERT_EQ(RunCli({"build", "grid", "--csv", SamplePath("grid_example.csv"), "-o", dir / "g.vct",
                    "--resolution-nm", "X=1000,Y=1000,Z=500"})
                .code,
            0);
  testing::WriteText(dir / "u.csv",
                     "time_s,axis,position_mm,deviation_um,T_a_C\n0,U,0,0,20\n1,U,9,0,20\n"
                     "5,U,0,1,21\n6,U,9,2,21.5\n");
  r = RunCli({"build", "thermal", dir / "u.csv", "--image", dir / "g.vct", "-o", dir / "x.vct"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_TRUE(Has(r.err, "axis U of the drift test is not an axis of the image (X, Y, Z)"))
      << r.err;
}

}  // namespace
}  // namespace volcomp
