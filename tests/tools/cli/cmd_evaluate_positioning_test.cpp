// `volcomp evaluate positioning` run as main() runs it, on the sample data of samples/metrology/:
// text and JSON are the same data, the report holds that JSON, bad options and inputs fail with
// their exit code and message.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "cli_runner.hpp"
#include "file_contents.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::FreshTempPath;
using testing::ReadText;
using testing::RunCli;
using testing::SamplePath;
using testing::SourcePath;

TEST(MetrologyCli, CommandsAreRegistered) {
  for (const auto& [verb, noun] : {std::pair{"evaluate", "positioning"},
                                   {"evaluate", "diagonal"},
                                   {"evaluate", "rotary"},
                                   {"program", "positioning"},
                                   {"program", "diagonal"},
                                   {"report", "compare"}}) {
    const auto r = RunCli({"help", verb, noun});
    EXPECT_EQ(r.code, 0) << verb << " " << noun;
    EXPECT_NE(r.out.find(std::string("usage: volcomp ") + verb + " " + noun), std::string::npos)
        << r.out;
  }
}

TEST(MetrologyCli, EvaluatePositioningGostExampleWithReport) {
  const std::string dir = FreshTempPath("evaluate_positioning_report");
  const auto r = RunCli({"evaluate", "positioning",
                         SamplePath("metrology/gost27843_example_long.csv"), "--report", dir});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("A       = 18.00"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("R_max   = 13.49"), std::string::npos) << r.out;
  const std::string html = dir + "/positioning_gost27843_example_long.html";
  const std::string json = dir + "/positioning_gost27843_example_long.json";
  EXPECT_TRUE(std::filesystem::exists(html));
  EXPECT_NE(r.err.find("report written to " + html + " and " + json + "\n"), std::string::npos)
      << r.err;
  // The report's JSON is the command's --json output.
  const auto j = RunCli(
      {"evaluate", "positioning", SamplePath("metrology/gost27843_example_long.csv"), "--json"});
  EXPECT_EQ(ReadText(json), j.out);
  // Again into the same directory: the earlier report is replaced, and said so.
  const auto again = RunCli({"evaluate", "positioning",
                             SamplePath("metrology/gost27843_example_long.csv"), "--report", dir});
  EXPECT_NE(again.err.find("(replacing the earlier report of that name)"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(MetrologyCli, EvaluatePositioningJsonBothStandards) {
  const auto r =
      RunCli({"evaluate", "positioning",
              SourcePath("tests/tools/metrology/data/gost27843_example_reconstructed.csv"),
              "--json", "--standard", "both"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"standard\": \"GOST 27843-88\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"standard\": \"ISO 230-2:2014\""), std::string::npos);
  EXPECT_NE(r.out.find("\"B_max\""), std::string::npos);
  EXPECT_NE(r.out.find("\"M\""), std::string::npos);
  const auto doc = tools::ParseJson(r.out, "stdout");
  ASSERT_TRUE(doc.ok()) << doc.error().message;
  EXPECT_EQ(doc->get("command")->string, "evaluate positioning");
  EXPECT_EQ(doc->get("positions")->integer, 11);
  EXPECT_EQ(doc->get("evaluations")->array.size(), 2u);
}

// Every figure of the text is in the JSON: the text printed from the JSON read back is the text.
TEST(MetrologyCli, EvaluatePositioningTextIsALayoutOfTheJson) {
  const std::string file = SamplePath("metrology/gost27843_example_long.csv");
  const auto text = RunCli({"evaluate", "positioning", file, "--standard", "both"});
  const auto json = RunCli({"evaluate", "positioning", file, "--standard", "both", "--json"});
  ASSERT_EQ(text.code, 0);
  ASSERT_EQ(json.code, 0);
  const auto doc = tools::ParseJson(json.out, "stdout");
  ASSERT_TRUE(doc.ok());
  const cli::Command* c = nullptr;
  for (const cli::Command* k : cli::Commands()) {
    if (std::string(k->name) == "evaluate positioning") c = k;
  }
  ASSERT_NE(c, nullptr);
  std::istringstream in;
  std::ostringstream out, err;
  cli::Context ctx{in, out, err};
  args::Args args({file, "--standard", "both"}, &c->options);
  const auto output = c->run(args, ctx);
  ASSERT_TRUE(output.ok());
  std::ostringstream relaid;
  output->text(*doc, relaid);
  EXPECT_EQ(relaid.str(), text.out);
}

TEST(MetrologyCli, EvaluateRotaryTablePositioningChecksCardinalAngles) {
  const auto r =
      RunCli({"evaluate", "positioning", SamplePath("metrology/rotary_table_positioning.csv")});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rotary axis, 12 target positions"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("§2.8"), std::string::npos) << r.err;  // 0/90/180/270 present
}

TEST(MetrologyCli, EvaluatePositioningReadsStandardInput) {
  const auto r = RunCli({"evaluate", "positioning", "-"},
                        ReadText(SamplePath("metrology/gost27843_example_long.csv")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("positioning test: <stdin>\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("A       = 18.00"), std::string::npos);
}

// An inch file and its mm twin typed by hand (targets x 25.4 mm, µin x 0.0254 µm): the same
// results in mm and µm, and the inch file's report says how it was read.
TEST(MetrologyCli, EvaluatePositioningOfAnInchFileMatchesItsMillimetreTwin) {
  std::string inch = "target_in,direction,run,deviation_uin\n";
  std::string mm = "target_mm,direction,run,deviation_um\n";
  const char* const in_targets[] = {"0", "4", "8"};
  const char* const mm_targets[] = {"0", "101.6", "203.2"};
  const char* const uin[] = {"100", "-50", "250", "0", "-125"};
  const char* const um[] = {"2.54", "-1.27", "6.35", "0", "-3.175"};
  for (int run = 0; run < 5; ++run) {
    for (int t = 0; t < 3; ++t) {
      for (const char* dir : {"up", "down"}) {
        const int k = (run + t + (dir[0] == 'u' ? 0 : 2)) % 5;
        const std::string tail = std::string(",") + dir + "," + std::to_string(run + 1) + ",";
        inch += in_targets[t] + tail + uin[k] + "\n";
        mm += mm_targets[t] + tail + um[k] + "\n";
      }
    }
  }
  const auto a = RunCli({"evaluate", "positioning", "-", "--standard", "both"}, inch);
  const auto b = RunCli({"evaluate", "positioning", "-", "--standard", "both"}, mm);
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  const std::string units = "units: read in inches, results in mm/µm\n";
  const std::size_t at = a.out.find(units);
  ASSERT_NE(at, std::string::npos) << a.out;
  EXPECT_EQ(b.out.find("units:"), std::string::npos) << b.out;
  EXPECT_EQ(std::string(a.out).erase(at, units.size()), b.out);
  EXPECT_NE(b.out.find("203.200"), std::string::npos) << b.out;
  const auto j = RunCli({"evaluate", "positioning", "-", "--json"}, inch);
  EXPECT_NE(j.out.find("\"input_units\": \"in\""), std::string::npos) << j.out;
}

// The GOST example's axis is 1500.41 mm long. With a 0.5 ppm laser, a 2 µm drift test and the
// material at 23 °C (preamble, decimal comma): instrument 0.6·2·0.5·1.50041 = 0.9004,
// thermometer 0.6·11.5·1.50041·0.2 = 2.0706, expansion 0.6·1.50041·3·2 = 5.4015, environment
// 1.2: U = sqrt(0.8107 + 4.2872 + 29.176 + 1.44) = 5.98; U(B) = 1.2.
TEST(MetrologyCli, EvaluatePositioningShowsEachValueWithItsUncertainty) {
  const std::string data = "# material temperature C: 23,0\n# drift_range_um: 2\n" +
                           ReadText(SamplePath("metrology/gost27843_example_long.csv"));
  auto r = RunCli({"evaluate", "positioning", "-", "--instrument-ppm", "0.5"}, data);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("A       = 18.00 ± 5.98"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("B_max   = 4.48 ± 1.20"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("R_max   = 13.49   at"), std::string::npos) << r.out;  // no U for R
  EXPECT_EQ(r.err.find("no measurement uncertainty"), std::string::npos) << r.err;
  r = RunCli(
      {"evaluate", "positioning", "-", "--instrument-ppm", "0.5", "--standard", "iso", "--json"},
      data);
  const auto doc = tools::ParseJson(r.out, "stdout");
  ASSERT_TRUE(doc.ok()) << r.out;
  const tools::JsonValue& ev = doc->get("evaluations")->array.at(0);
  EXPECT_NEAR(ev.get("parameters")->get("E")->get("U")->number, 5.976, 0.001);
  EXPECT_NEAR(ev.get("uncertainty")->get("local_U_um")->number, 1.2, 1e-9);
  // Without an instrument: the values alone and a warning saying what to state.
  r = RunCli({"evaluate", "positioning", SamplePath("metrology/gost27843_example_long.csv")});
  EXPECT_NE(r.out.find("A       = 18.00   max"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("no measurement uncertainty: state the instrument"), std::string::npos);
}

// An .rtl's environment block feeds the budget: the sample's targets span 400 mm, its
// expansion coefficient is 11.7 ppm/°C and its material sensor reads 20.203292 °C at the start and
// 20.321342 °C at the end (mean 20.262317). With a 0.5 ppm laser: instrument 0.6·2·0.5·0.4 =
// 0.24, thermometer 0.6·11.7·0.4·0.2 = 0.5616, expansion 0.6·0.4·0.262317·2 = 0.125912:
// U = sqrt(0.0576 + 0.31540 + 0.015854) = 0.62358.
TEST(MetrologyCli, EvaluatePositioningTakesTheRtlEnvironmentIntoTheBudget) {
  const auto r = RunCli({"evaluate", "positioning", SamplePath("metrology/renishaw_x.rtl"),
                         "--standard", "iso", "--instrument-ppm", "0.5", "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  const auto doc = tools::ParseJson(r.out, "stdout");
  ASSERT_TRUE(doc.ok()) << r.out;
  const tools::JsonValue& u = *doc->get("evaluations")->array.at(0).get("uncertainty");
  EXPECT_NEAR(u.get("length_mm")->number, 400.0, 1e-9);
  EXPECT_NEAR(u.get("length_U_um")->number, 0.62358, 1e-5);
}

// A rotary table against an angle reference stated ±1″ (preamble) with a 1.5″ drift test:
// instrument 0.6·2·1 = 1.2″, environment 0.6·1.5 = 0.9″, U = √(1.44 + 0.81) = 1.5″ for E, A, M
// and B alike; the targets span 0–330 deg.
TEST(MetrologyCli, EvaluatePositioningGivesARotaryAxisItsAngularUncertainty) {
  const std::string data = "# instrument_accuracy_arcsec: 1\n" +
                           ReadText(SamplePath("metrology/rotary_table_positioning.csv"));
  auto r = RunCli({"evaluate", "positioning", "-", "--drift-range-arcsec", "1.5"}, data);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("A       = 23.42 ± 1.50"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("B_max   = 3.84 ± 1.50"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("over 330.0 deg: 1.50, of B 1.50"), std::string::npos) << r.out;
  r = RunCli({"evaluate", "positioning", "-", "--drift-range-arcsec", "1.5", "--json"}, data);
  const auto doc = tools::ParseJson(r.out, "stdout");
  ASSERT_TRUE(doc.ok()) << r.out;
  const tools::JsonValue& u = *doc->get("evaluations")->array.at(0).get("uncertainty");
  EXPECT_NEAR(u.get("span_deg")->number, 330.0, 1e-9);
  EXPECT_NEAR(u.get("span_U_arcsec")->number, 1.5, 1e-12);
  EXPECT_NEAR(u.get("local_U_arcsec")->number, 1.5, 1e-12);
  // A length input on a rotary axis is named, not silently used.
  r = RunCli({"evaluate", "positioning", SamplePath("metrology/rotary_table_positioning.csv"),
              "--instrument-u-um", "0.3"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("do not apply to a rotary axis"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("state the angle reference"), std::string::npos) << r.err;
}

// The largest range of one point's readings in a drift-test file, read here line by line (no
// code shared with the drift-test reader): columns time_s, axis, position_mm, deviation_um.
double LargestPointRange(const std::string& path) {
  std::map<std::string, std::pair<double, double>> span;  // "axis@position" → (min, max)
  std::istringstream lines(ReadText(path));
  std::string line;
  bool header = true;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::istringstream cells(line);
    std::string time, axis, position, deviation;
    std::getline(cells, time, ',');
    std::getline(cells, axis, ',');
    std::getline(cells, position, ',');
    std::getline(cells, deviation, ',');
    const double v = std::stod(deviation);
    auto [it, fresh] = span.emplace(axis + "@" + position, std::make_pair(v, v));
    it->second.first = std::min(it->second.first, v);
    it->second.second = std::max(it->second.second, v);
  }
  double largest = 0.0;
  for (const auto& [point, mm] : span) largest = std::max(largest, mm.second - mm.first);
  return largest;
}

// `--drift-test FILE` gives E_VE: the largest range of one point's readings; with a 0.5 ppm laser
// on the GOST example's 1500.41 mm (material temperature not stated): instrument 0.9004,
// thermometer 2.0706, environment 0.6·E_VE.
TEST(MetrologyCli, EvaluatePositioningTakesEveFromADriftTest) {
  const std::string drift = SamplePath("metrology/thermal_drift.csv");
  const double e_ve = LargestPointRange(drift);
  ASSERT_GT(e_ve, 1.0);
  auto r =
      RunCli({"evaluate", "positioning", SamplePath("metrology/gost27843_example_long.csv"),
              "--standard", "iso", "--instrument-ppm", "0.5", "--drift-test", drift, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto doc = tools::ParseJson(r.out, "stdout");
  ASSERT_TRUE(doc.ok()) << r.out;
  const tools::JsonValue& u = *doc->get("evaluations")->array.at(0).get("uncertainty");
  const double instrument = 0.6 * 2 * 0.5 * 1.50041, thermometer = 0.6 * 11.5 * 1.50041 * 0.2;
  EXPECT_NEAR(u.get("local_U_um")->number, 0.6 * e_ve, 1e-9);  // no calibration U stated
  EXPECT_NEAR(u.get("length_U_um")->number,
              std::sqrt(instrument * instrument + thermometer * thermometer + 0.36 * e_ve * e_ve),
              1e-3);
  EXPECT_NE(u.get("terms")->array.back().get("basis")->string.find("drift test " + drift + ": X"),
            std::string::npos);
  r = RunCli({"evaluate", "positioning", SamplePath("metrology/gost27843_example_long.csv"),
              "--instrument-ppm", "0.5", "--drift-test", drift, "--drift-range-um", "1"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("give --drift-range-um or --drift-test, not both"), std::string::npos);
  r = RunCli({"evaluate", "positioning", SamplePath("metrology/gost27843_example_long.csv"),
              "--instrument-ppm", "0.5", "--drift-test",
              SamplePath("metrology/gost27843_example_long.csv")});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("gost27843_example_long.csv"), std::string::npos) << r.err;
}

TEST(MetrologyCli, EvaluatePositioningBadOptionsAndInputs) {
  auto r = RunCli({"evaluate", "positioning", "x.csv", "--standard", "nope"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("volcomp evaluate positioning: --standard must be gost27843, iso230-2 or "
                       "both\n"),
            std::string::npos)
      << r.err;
  r = RunCli({"evaluate", "positioning", "x.csv", "--bogus"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--bogus"), std::string::npos) << r.err;
  r = RunCli({"evaluate", "positioning"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("give exactly one data file (or - for stdin)"), std::string::npos);
  r = RunCli({"evaluate", "positioning", "x.csv", "--axis-length-mm", "0"});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--axis-length-mm must be positive"), std::string::npos);
  r = RunCli({"evaluate", "positioning", "/nonexistent/file.csv"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("volcomp evaluate positioning: error: /nonexistent/file.csv: cannot open"),
            std::string::npos)
      << r.err;
  // With --json a failure is a JSON object on stdout too.
  r = RunCli({"evaluate", "positioning", "-", "--json"}, "target_mm,direction,run,deviation_um\n");
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("<stdin>:1: no data rows after the header"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("\"exit_code\": 1"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace volcomp
