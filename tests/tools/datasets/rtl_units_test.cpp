// The units of a Renishaw .rtl (issue 25 item 3): an inch file (targets in inches, deviations in
// µin; no real one exists in public, so written by hand from the mm layout) and the environment
// units recognised by range, each converted value worked by hand from the definitions (1 in =
// 25.4 mm, °C = (°F − 32)/1.8, 1 mmHg = 133.322387415 Pa, 1 inHg = 25.4 mmHg, 1 ppm/°F = 1.8
// ppm/°C), each refusal with the line it must name.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "expected_value.hpp"
#include "volcomp/datasets/positioning_file.hpp"
#include "volcomp/datasets/rtl_reader.hpp"

namespace volcomp::datasets {
namespace {

using testing::ValueOf;

// An inch test: 3 targets 0, 4 and 8 in, 2 runs; °F, inHg and ppm/°F. Line n is element n − 1.
std::vector<std::string> Inch() {
  return {"HEADER::",
          "TARGET DATA::",
          "Target-count: 3",
          "Targets :",
          "0.000000 4.000000 8.000000",
          "RUNS::",
          "Run-count: 2",
          "DEVIATIONS::",
          "1 1 100.000",
          "1 2 -50.000",
          "1 3 250.000",
          "2 3 0.000",
          "2 2 -125.000",
          "2 1 10.000",
          "ENVIRONMENT::",
          "Air temp : 68.000000 77.000000 0",
          "Air press : 29.921260 29.921260 1",
          "Mat temp 1 : 68.000000 68.000000 0",
          "Exp coeff : 6.400000 6.400000 0"};
}

// A metric test (°C); the environment lines are appended by the tests from line 11.
std::vector<std::string> Metric() {
  return {"HEADER::",     "TARGET DATA::", "Target-count: 2", "Targets :", "0 100",        "RUNS::",
          "Run-count: 1", "DEVIATIONS::",  "1 1 1.5",         "1 2 -2.5",  "ENVIRONMENT::"};
}

std::string Text(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\r\n";
  return s;
}

RtlOptions Units(RtlUnits units, RtlExpansionPer per = RtlExpansionPer::kAuto) {
  RtlOptions o;
  o.units = units;
  o.expansion_per = per;
  return o;
}

RtlTest Read(const std::vector<std::string>& lines, const RtlOptions& o = RtlOptions{}) {
  return ValueOf(ParseRtl(Text(lines), "t.rtl", o));
}

std::string ErrorOf(const std::vector<std::string>& lines) {
  const auto r = ParseRtl(Text(lines), "t.rtl");
  if (r.ok()) return "(accepted)";
  EXPECT_EQ(r.error().code, Error::kInputInvalid);
  return r.error().message;
}

// The warning that starts with "t.rtl:LINE: " and holds `what`, or "" when none does.
std::string WarningAt(const RtlTest& t, int line, const std::string& what) {
  for (const std::string& w : t.warnings) {
    if (w.rfind("t.rtl:" + std::to_string(line) + ": ", 0) == 0 &&
        w.find(what) != std::string::npos) {
      return w;
    }
  }
  return "";
}

TEST(datasets_rtl_units, InchTargetsAndMicroinchDeviationsConvertExactly) {
  const RtlTest t = Read(Inch(), Units(RtlUnits::kIn));
  // 4 in = 101.6 mm, 8 in = 203.2 mm.
  ASSERT_EQ(t.targets_mm.size(), 3u);
  EXPECT_DOUBLE_EQ(t.targets_mm[1], 101.6);
  EXPECT_DOUBLE_EQ(t.targets_mm[2], 203.2);
  // 100 µin = 2.54 µm, −50 µin = −1.27 µm, 250 µin = 6.35 µm, −125 µin = −3.175 µm.
  const auto& r = t.readings.readings;
  ASSERT_EQ(r.size(), 6u);
  const double um[] = {2.54, -1.27, 6.35, 0.0, -3.175, 0.254};
  for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(r[k].deviation, um[k], 1e-12) << k;
  EXPECT_DOUBLE_EQ(r[4].target, 101.6);
  EXPECT_TRUE(t.readings.read_in_inches);
  EXPECT_NEAR(t.readings.column_scale, 0.0254, 1e-15);
  EXPECT_EQ(t.conditions.Find("units as read"),
            "targets in, deviations µin, temperatures °F, pressure inHg, expansion coefficient "
            "ppm/°F (converted to mm, µm, °C, kPa and ppm/°C)");
  // No warning that the file might be metric: its temperatures are °F.
  EXPECT_EQ(WarningAt(t, 16, "--rtl-units"), "");
  EXPECT_STREQ(RtlUnitsName(RtlUnits::kIn), "in");
}

TEST(datasets_rtl_units, FahrenheitIsRecognisedAboveFortyFiveAndSaidAloud) {
  const RtlTest t = Read(Inch(), Units(RtlUnits::kIn));
  const RtlEnvironment& env = t.environment;
  ASSERT_TRUE(env.air_temperature_c && env.material_temperature_c[0]);
  EXPECT_NEAR(env.air_temperature_c->start, 20.0, 1e-12);  // 68 °F
  EXPECT_NEAR(env.air_temperature_c->end, 25.0, 1e-12);    // 77 °F
  EXPECT_NEAR(env.material_temperature_c[0]->start, 20.0, 1e-12);
  EXPECT_EQ(t.conditions.Find("air temperature C"), "20 at start, 25 at end");
  EXPECT_EQ(WarningAt(t, 16, ""),
            "t.rtl:16: Air temp is above 45, so read as °F: 68 and 77 °F = 20 and 25 °C");
  EXPECT_NE(WarningAt(t, 18, "Mat temp 1 is above 45, so read as °F"), "");
  // The same file read as mm: converted all the same, and the unit system is questioned.
  const RtlTest mm = Read(Inch());
  EXPECT_NEAR(mm.environment.air_temperature_c->start, 20.0, 1e-12);
  EXPECT_NE(WarningAt(mm, 16,
                      "probably written in inch units; if its targets are inches, read "
                      "it with --rtl-units in"),
            "");
}

TEST(datasets_rtl_units, CelsiusInAnInchFileIsQuestioned) {
  std::vector<std::string> l = Metric();
  l.push_back("Air temp : 20.5 21.0 0");  // line 12
  const RtlTest t = Read(l, Units(RtlUnits::kIn));
  EXPECT_NEAR(t.environment.air_temperature_c->start, 20.5, 0.0);
  EXPECT_NE(WarningAt(t, 12,
                      "probably written in metric units; if its targets are mm, read it "
                      "with --rtl-units mm"),
            "");
  EXPECT_EQ(t.conditions.Find("units as read"),
            "targets in, deviations µin (converted to mm, µm, °C, kPa and ppm/°C)");
  // Read as mm: no warning, no "units as read".
  const RtlTest mm = Read(l);
  EXPECT_TRUE(mm.warnings.empty()) << mm.warnings.front();
  EXPECT_FALSE(mm.conditions.Find("units as read"));
}

TEST(datasets_rtl_units, MixedTemperatureUnitsAreWarned) {
  std::vector<std::string> l = Metric();
  l.push_back("Air temp : 68 68 0");    // line 12: °F
  l.push_back("Mat temp 1 : 20 20 0");  // line 13: °C (or 20 °F = −6.7 °C, no shop)
  const RtlTest t = Read(l, Units(RtlUnits::kIn));
  EXPECT_NEAR(t.environment.material_temperature_c[0]->start, 20.0, 0.0);
  EXPECT_NE(WarningAt(t, 13, "45 or below, so read as °C, but line 12's is °F"), "");
}

// The standard atmosphere, 101.325 kPa, in each unit: 1013.25 hPa; 760 mmHg = 101.32501 kPa
// (133.322387415 Pa each); 760 mmHg = 29.921260 inHg (760/25.4).
TEST(datasets_rtl_units, PressureUnitsAreRecognisedByRangeAndConverted) {
  struct Case {
    const char* line;
    double kpa;
    const char* unit;  // named in the warning; nullptr: kPa, no warning
  };
  const Case cases[] = {
      {"Air press : 101.325 99.0 1", 101.325, nullptr},
      {"Air press : 1013.25 990.0 1", 101.325, "hPa (mbar)"},
      {"Air press : 760 742.5 1", 101.3250144354, "mmHg"},
      {"Air press : 29.921260 29.232 1", 101.3250144354, "inHg"},
      // 800–825 is both hPa and mmHg: read as hPa (a factory at altitude), said aloud.
      {"Air press : 810 812 1", 81.0, "hPa (mbar)"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> l = Metric();
    l.push_back(c.line);  // line 12
    const RtlTest t = Read(l);
    ASSERT_TRUE(t.environment.air_pressure_kpa) << c.line;
    EXPECT_NEAR(t.environment.air_pressure_kpa->start, c.kpa, 1e-5) << c.line;
    if (c.unit == nullptr) {
      EXPECT_TRUE(t.warnings.empty()) << t.warnings.front();
      continue;
    }
    const std::string w =
        WarningAt(t, 12, std::string("Air press read as ") + c.unit + " by its range");
    EXPECT_NE(w, "") << c.line;
    EXPECT_NE(t.conditions.Find("units as read")->find(std::string("pressure ") + c.unit),
              std::string::npos)
        << c.line;
  }
  // 990 hPa at the end is 99 kPa.
  std::vector<std::string> l = Metric();
  l.push_back("Air press : 1013.25 990.0 1");
  EXPECT_NEAR(Read(l).environment.air_pressure_kpa->end, 99.0, 1e-12);
}

TEST(datasets_rtl_units, ImplausibleEnvironmentIsRefusedWithTheLineAndTheRanges) {
  std::vector<std::string> l = Metric();
  l.push_back("Air press : 50 50 1");
  EXPECT_EQ(ErrorOf(l),
            "t.rtl:12: Air press 50 is in none of the air pressure ranges (kPa 80–110, hPa (mbar) "
            "800–1100, mmHg 600–825 or inHg 23.6–32.5, start and end alike)");
  l.back() = "Air press : 99.0 1000.0 1";  // start kPa, end hPa: neither
  EXPECT_EQ(ErrorOf(l).rfind("t.rtl:12: Air press 99 and 1000 is in none", 0), 0u) << ErrorOf(l);
  l.back() = "Air temp : 150 150 0";
  EXPECT_EQ(ErrorOf(l),
            "t.rtl:12: Air temp 150 is not a shop temperature: °C up to 45, or °F above 45 up to "
            "113 (45 °C), start and end alike");
  l.back() = "Mat temp 1 : 40 50 0";  // one each side of 45
  EXPECT_EQ(ErrorOf(l).rfind("t.rtl:12: Mat temp 1 40 and 50 is not a shop temperature", 0), 0u)
      << ErrorOf(l);
}

TEST(datasets_rtl_units, ExpansionCoefficientFollowsTheTemperaturesOrTheOption) {
  // °F file, auto: 6.4 ppm/°F = 11.52 ppm/°C, warned.
  const RtlTest a = Read(Inch(), Units(RtlUnits::kIn));
  EXPECT_NEAR(a.environment.expansion_ppm_per_c->start, 11.52, 1e-12);
  EXPECT_EQ(a.conditions.Find("expansion coefficient ppm/C"), "11.52");
  EXPECT_EQ(WarningAt(a, 19, ""),
            "t.rtl:19: Exp coeff read as ppm/°F, since the temperatures are °F: 6.4 ppm/°F = "
            "11.52 ppm/°C; give --rtl-expansion-per C if the file states ppm/°C");
  // °F file, C: 6.4 ppm/°C as written (granite, say), no warning about it.
  const RtlTest c = Read(Inch(), Units(RtlUnits::kIn, RtlExpansionPer::kCelsius));
  EXPECT_EQ(c.environment.expansion_ppm_per_c->start, 6.4);
  EXPECT_EQ(WarningAt(c, 19, ""), "");
  EXPECT_EQ(c.conditions.Find("units as read")->find("ppm/°F"), std::string::npos);
  // °C file, F: 6.4 ppm/°F = 11.52 ppm/°C as asked; auto leaves it.
  std::vector<std::string> l = Metric();
  l.push_back("Air temp : 20 20 0");
  l.push_back("Exp coeff : 6.4 6.4 0");
  const RtlTest f = Read(l, Units(RtlUnits::kMm, RtlExpansionPer::kFahrenheit));
  EXPECT_NEAR(f.environment.expansion_ppm_per_c->start, 11.52, 1e-12);
  EXPECT_EQ(f.conditions.Find("units as read"),
            "expansion coefficient ppm/°F (converted to mm, µm, °C, kPa and ppm/°C)");
  EXPECT_EQ(Read(l).environment.expansion_ppm_per_c->start, 6.4);
}

TEST(datasets_rtl_units, LoaderSaysWhichUnitsTheFileWasReadIn) {
  PositioningReadOptions o;
  o.rtl.units = RtlUnits::kIn;
  o.rtl.runs = RtlRuns::kForward;  // both runs ↑: two approaches per target
  const PositioningFile f = ValueOf(ReadPositioningText(Text(Inch()), "t.rtl", o));
  EXPECT_EQ(f.rtl_units, RtlUnits::kIn);
  metrology::GroupingOptions few;
  few.allow_few_approaches = true;
  const model::PositioningData d = ValueOf(PositioningMeans(f, few));
  ASSERT_EQ(d.position.size(), 3u);
  EXPECT_DOUBLE_EQ(d.position[2], 203.2);
  EXPECT_NEAR(d.dev_forward[2], 3.175, 1e-12);    // (250 + 0)/2 µin
  EXPECT_NEAR(d.dev_forward[1], -2.2225, 1e-12);  // (−50 − 125)/2 µin
}

}  // namespace
}  // namespace volcomp::datasets
