// The integrator's workflow through the metrology commands, as `volcomp` runs them (RunCli): no
// measurement is lost, reports are named after what they evaluate, test conditions reach the
// reports, data in the shapes users have (';' and decimal comma) evaluate like plain CSV.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <sstream>

#include "cli_runner.hpp"
#include "file_contents.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"

namespace volcomp::tools {
namespace {

using volcomp::testing::ReadText;
using volcomp::testing::SamplePath;
using volcomp::testing::ScratchDir;
using volcomp::testing::WriteText;

using Result = volcomp::testing::CliResult;

Result Volcomp(const std::vector<std::string>& words) { return volcomp::testing::RunCli(words); }

// The GOST 27843 worked example (samples/metrology) with the first `from` replaced by `to`.
std::string GostExampleWith(const std::string& from, const std::string& to) {
  std::string csv = ReadText(SamplePath("metrology/gost27843_example_long.csv"));
  csv.replace(csv.find(from), from.size(), to);
  return csv;
}

// Fills the empty last cell of every data row of a template with a reading from `value`
// (target, direction, run), and the empty `# key:` lines with `conditions`.
std::string Fill(const std::string& text,
                 const std::function<double(double, const std::string&, int)>& value,
                 const std::map<std::string, std::string>& conditions = {}) {
  std::istringstream in(text);
  std::ostringstream out;
  bool header_seen = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("#", 0) == 0) {
      for (const auto& [k, v] : conditions) {
        if (line == "# " + k + ":") line += " " + v;
      }
      out << line << "\n";
      continue;
    }
    if (!header_seen) {
      header_seen = true;
      out << line << "\n";
      continue;
    }
    std::vector<std::string> f;
    std::stringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) f.push_back(c);
    const std::size_t n = f.size();  // the empty last field is not returned by getline
    const double v = value(std::stod(f[n - 3]), f[n - 2], std::stoi(f[n - 1]));
    std::ostringstream cell;
    cell.precision(6);
    cell << v;
    out << line << cell.str() << "\n";
  }
  return out.str();
}

double Reading(double target, const std::string& dir, int run) {
  const double scatter[] = {0.1, -0.3, 0.2, 0.0, -0.1};
  return 0.02 * target + (dir == "up" ? 1.5 : -1.5) + scatter[run % 5];
}

// X, Y and Z evaluated into one directory: each keeps its report (named by its axis).
TEST(MetrologyWorkflow, ReportsOfSeveralAxesShareADirectory) {
  ScratchDir s("workflow_axes");
  for (const char* axis : {"X", "Y", "Z"}) {
    const std::string csv = s / (std::string(axis) + "_readings.csv");
    ASSERT_EQ(Volcomp({"program", "positioning", "--axis", axis, "--start", "10", "--end", "390",
                       "--pitch", "5", "-o", s / "p.ngc", "--targets-csv", csv})
                  .code,
              0);
    WriteText(csv, Fill(ReadText(csv), Reading));
    const Result r = Volcomp({"evaluate", "positioning", csv, "--report", s / "before"});
    ASSERT_EQ(r.code, 0) << r.err;
  }
  for (const char* axis : {"X", "Y", "Z"}) {
    EXPECT_TRUE(std::filesystem::exists(s / ("before/positioning_" + std::string(axis) + ".html")));
    EXPECT_TRUE(std::filesystem::exists(s / ("before/positioning_" + std::string(axis) + ".json")));
  }
}

// Issue defect 6: re-running `program positioning --targets-csv F` overwrote F with its readings.
TEST(MetrologyWorkflow, ATemplateWithReadingsIsNotOverwritten) {
  ScratchDir s("workflow_overwrite");
  const std::string csv = s / "x_readings.csv";
  const std::vector<std::string> program = {"program", "positioning", "--axis",        "X",
                                            "--end",   "390",         "--pitch",       "5",
                                            "-o",      s / "x.ngc",   "--targets-csv", csv};
  ASSERT_EQ(Volcomp(program).code, 0);
  ASSERT_EQ(Volcomp(program).code, 0);  // an empty template may be written again
  const std::string filled = Fill(ReadText(csv), Reading);
  WriteText(csv, filled);
  const Result again = Volcomp(program);
  EXPECT_EQ(again.code, kExitFailed);
  EXPECT_NE(again.err.find(csv + " already holds readings (line "), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("--force"), std::string::npos);
  EXPECT_EQ(ReadText(csv), filled);
  auto forced = program;
  forced.push_back("--force");
  EXPECT_EQ(Volcomp(forced).code, 0);
  EXPECT_NE(ReadText(csv), filled);

  // The same protection for diagonal templates.
  const std::string diag = s / "diag.csv";
  WriteText(diag, "diagonal,target_mm,direction,run,deviation_um\nNNN,0,up,1,2.5\n");
  const Result d = Volcomp({"program", "diagonal", "--p1", "0,0,0", "--p2", "100,100,100",
                            "--increment-mm", "20", "-o", s / "d.ngc", "--targets-csv", diag});
  EXPECT_EQ(d.code, kExitFailed);
  EXPECT_NE(d.err.find("already holds readings (line 2)"), std::string::npos) << d.err;
  EXPECT_FALSE(std::filesystem::exists(s / "d.ngc"));  // nothing written before the refusal
}

// Issue defect 6: `program diagonal --name` was not checked against P1/P2.
TEST(MetrologyWorkflow, DiagonalNameIsCheckedAndDerived) {
  Result r = Volcomp({"program", "diagonal", "--p1", "10,10,10", "--p2", "390,270,190",
                      "--increment-mm", "50", "--name", "+X+Y+Z"});
  EXPECT_EQ(r.code, kExitUsage);
  EXPECT_NE(r.err.find("does not name the diagonal from P1 to P2, which starts at the -X-Y-Z"),
            std::string::npos)
      << r.err;
  ScratchDir s("workflow_name");
  r = Volcomp({"program", "diagonal", "--p1", "390,10,10", "--p2", "10,270,190", "--increment-mm",
               "50", "-o", s / "d.ngc", "--targets-csv", s / "d.csv"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(ReadText(s / "d.ngc").find("diagonal test +X-Y-Z"), std::string::npos);
  EXPECT_NE(ReadText(s / "d.csv").find("\nPNN,0.000,up,1,\n"), std::string::npos)
      << ReadText(s / "d.csv");
}

TEST(MetrologyWorkflow, BoxGivesFourDiagonalsAndATemplateEvaluateReads) {
  ScratchDir s("workflow_box");
  const Result r =
      Volcomp({"program", "diagonal", "--box", "10,10,10:390,270,190", "--increment-mm", "50", "-o",
               s / "diag.ngc", "--targets-csv", s / "diagonals.csv"});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* token : {"NNN", "PNN", "NPN", "PPN"}) {
    EXPECT_TRUE(std::filesystem::exists(s / ("diag_" + std::string(token) + ".ngc"))) << token;
  }
  // The title comment names the diagonal and its ends (brackets: RS274NGC comments do not nest).
  EXPECT_NE(ReadText(s / "diag_PPN.ngc")
                .find("diagonal test +X+Y-Z from [390, 270, 10] to [10, 10, 190]"),
            std::string::npos);
  WriteText(s / "diagonals.csv",
            Fill(ReadText(s / "diagonals.csv"), Reading, {{"machine", "MILL-7"}}));
  const Result e = Volcomp({"evaluate", "diagonal", s / "diagonals.csv", "--report", s / "before"});
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_NE(e.out.find("body diagonals (4)"), std::string::npos) << e.out;
  EXPECT_EQ(e.err.find("of the 4 body diagonals measured"), std::string::npos) << e.err;
  EXPECT_NE(e.out.find("conditions: machine MILL-7"), std::string::npos) << e.out;
  EXPECT_TRUE(std::filesystem::exists(s / "before/diagonal_NNN_NPN_PNN_PPN.html"));
  // E = (x̄max − x̄min) along each diagonal: 0.02·D + 3 µm of reversal, the same on all four.
  EXPECT_NE(e.out.find("E_d = "), std::string::npos);
}

// The program's feed and dwell are test conditions of its template, so the reports (and the
// certificate) state them.
TEST(MetrologyWorkflow, FeedAndDwellAreConditionsOfTheTemplate) {
  ScratchDir s("workflow_feed");
  ASSERT_EQ(
      Volcomp({"program", "positioning", "--axis", "Z", "--end", "190", "--pitch", "5", "--feed",
               "800", "--dwell-s", "1.5", "--targets-csv", s / "z.csv", "-o", s / "z.ngc"})
          .code,
      0);
  EXPECT_NE(ReadText(s / "z.csv").find("# feed mm per min: 800\n# dwell s: 1.5\n"),
            std::string::npos)
      << ReadText(s / "z.csv").substr(0, 600);
  ASSERT_EQ(Volcomp({"program", "positioning", "--rotary", "--axis", "C", "--pitch", "30", "--feed",
                     "3600", "--targets-csv", s / "c.csv", "-o", s / "c.ngc"})
                .code,
            0);
  EXPECT_NE(ReadText(s / "c.csv").find("# feed deg per min: 3600\n# dwell s: 2\n"),
            std::string::npos)
      << ReadText(s / "c.csv").substr(0, 600);
  ASSERT_EQ(Volcomp({"program", "diagonal", "--box", "10,10,10:390,270,190", "--increment-mm", "50",
                     "--dwell-s", "0.5", "-o", s / "d.ngc", "--targets-csv", s / "d.csv"})
                .code,
            0);
  const std::string d = ReadText(s / "d.csv");
  EXPECT_NE(d.find("# feed mm per min: 1000\n# dwell s: 0.5\n"), std::string::npos)
      << d.substr(0, 600);
  WriteText(s / "z.csv", Fill(ReadText(s / "z.csv"), Reading, {}));
  ASSERT_EQ(Volcomp({"evaluate", "positioning", s / "z.csv", "--report", s / "r"}).code, 0);
  const std::string json = ReadText(s / "r/positioning_Z.json");
  EXPECT_NE(json.find("\"feed mm per min\": \"800\""), std::string::npos) << json.substr(0, 800);
}

TEST(MetrologyWorkflow, TestConditionsReachTheReports) {
  ScratchDir s("workflow_conditions");
  const std::string csv = s / "x.csv";
  ASSERT_EQ(Volcomp({"program", "positioning", "--axis", "X", "--end", "390", "--pitch", "5",
                     "--targets-csv", csv, "-o", s / "x.ngc"})
                .code,
            0);
  const std::string tmpl = ReadText(csv);
  for (const char* key :
       {"# machine:\n", "# axis: X\n", "# date:\n", "# operator:\n", "# instrument:\n",
        "# air temperature C:\n", "# material temperature C:\n"}) {
    EXPECT_NE(tmpl.find(key), std::string::npos) << key << tmpl.substr(0, 600);
  }
  WriteText(csv, Fill(tmpl, Reading,
                      {{"machine", "MILL-7"},
                       {"operator", "N. N."},
                       {"instrument", "XL-80 #1234"},
                       {"air temperature C", "20.4"},
                       {"material temperature C", "20.9"}}));
  const Result r = Volcomp({"evaluate", "positioning", csv, "--report", s / "r"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("conditions: machine MILL-7; axis X;"), std::string::npos) << r.out;
  const std::string html = ReadText(s / "r/positioning_X.html");
  EXPECT_NE(html.find("<td>air temperature C</td><td>20.4</td>"), std::string::npos);
  EXPECT_NE(html.find("XL-80 #1234"), std::string::npos);
  const std::string json = ReadText(s / "r/positioning_X.json");
  EXPECT_NE(json.find("\"material temperature C\": \"20.9\""), std::string::npos) << json;

  // The same for a rotary error-motion record.
  WriteText(s / "spindle.csv", "# machine: MILL-7\n# instrument: capacitive probes\n" +
                                   ReadText(SamplePath("metrology/spindle_error_motion.csv")));
  const Result rot = Volcomp({"evaluate", "rotary", s / "spindle.csv", "--report", s / "r"});
  ASSERT_EQ(rot.code, 0) << rot.err;
  EXPECT_NE(rot.out.find("conditions: machine MILL-7; instrument capacitive probes"),
            std::string::npos);
  EXPECT_NE(ReadText(s / "r/rotary_spindle.json").find("\"instrument\": \"capacitive probes\""),
            std::string::npos);
}

// ';' separated with decimal commas (Russian/European Excel) evaluates like the plain file.
TEST(MetrologyWorkflow, SemicolonAndDecimalCommaEvaluateLikePlainCsv) {
  ScratchDir s("workflow_comma");
  const std::string plain = ReadText(SamplePath("metrology/gost27843_example_long.csv"));
  std::string eu;
  for (char c : plain) eu += c == ',' ? ';' : c == '.' ? ',' : c;
  WriteText(s / "eu.csv", eu);
  const Result a = Volcomp(
      {"evaluate", "positioning", SamplePath("metrology/gost27843_example_long.csv"), "--json"});
  const Result b = Volcomp({"evaluate", "positioning", s / "eu.csv", "--json"});
  ASSERT_EQ(b.code, 0) << b.err;
  const auto strip = [](std::string j) {
    return std::regex_replace(j, std::regex("\"(source|name)\": \"[^\"]*\""), "");
  };
  EXPECT_EQ(strip(a.out), strip(b.out));
  EXPECT_NE(b.out.find("\"value\": 18.003"), std::string::npos) << b.out.substr(0, 800);
}

// Issue defect 7: a reading of 1e300 gave exit 0 and "n/a" in the report.
TEST(MetrologyWorkflow, ANonFiniteResultIsARefusalNamingTheLine) {
  ScratchDir s("workflow_huge");
  WriteText(s / "huge.csv", GostExampleWith("0,up,1,-2.6", "0,up,1,1e300"));
  const Result r = Volcomp({"evaluate", "positioning", s / "huge.csv", "--report", s / "r"});
  EXPECT_EQ(r.code, kExitFailed);
  EXPECT_NE(r.err.find("huge.csv:3: column \"deviation_um\""), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(s / "r"));
}

// Issue defect 7: µm readings in a deviation_mm column gave A = 18,004 µm without a warning.
TEST(MetrologyWorkflow, ImplausibleMagnitudeIsWarnedInStderrAndTheReport) {
  ScratchDir s("workflow_mm");
  WriteText(s / "mm.csv", GostExampleWith("deviation_um", "deviation_mm"));
  const Result r = Volcomp({"evaluate", "positioning", s / "mm.csv", "--report", s / "r"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.err.find("warning: " + (s / "mm.csv") + ":3: column \"deviation_mm\""),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("name the column deviation_um"), std::string::npos);
  EXPECT_NE(ReadText(s / "r/positioning_mm.html").find("name the column deviation_um"),
            std::string::npos);
}

// The before/after page: every deviation scaled by 0.1 after the compensation scales every
// positioning parameter by 0.1, so each reduction is 90.0 %; a result without a partner is named.
TEST(MetrologyWorkflow, ReportCompareShowsReductions) {
  ScratchDir s("workflow_compare");
  for (const char* axis : {"X", "Y"}) {
    const std::string csv = s / (std::string(axis) + ".csv");
    ASSERT_EQ(Volcomp({"program", "positioning", "--axis", axis, "--end", "390", "--pitch", "5",
                       "-o", s / "p.ngc", "--targets-csv", csv, "--force"})
                  .code,
              0);
    const std::string tmpl = ReadText(csv);
    WriteText(csv, Fill(tmpl, Reading, {{"air temperature C", "20.1"}}));
    ASSERT_EQ(
        Volcomp({"evaluate", "positioning", csv, "--standard", "both", "--report", s / "before"})
            .code,
        0);
    if (std::string(axis) == "Y") continue;  // Y is not measured after
    WriteText(
        csv,
        Fill(tmpl, [](double t, const std::string& d, int run) { return 0.1 * Reading(t, d, run); },
             {{"air temperature C", "20.6"}}));
    ASSERT_EQ(
        Volcomp({"evaluate", "positioning", csv, "--standard", "both", "--report", s / "after"})
            .code,
        0);
  }
  const Result r = Volcomp({"report", "compare", s / "before", s / "after", "-o", s / "cmp"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("positioning_Y (" + (s / "before/positioning_Y.json") +
                       "): no after result of that name"),
            std::string::npos)
      << r.err;
  std::istringstream lines(r.out);
  int rows = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.find(" -> ") == std::string::npos) continue;
    ++rows;
    if (line.find("B̄") != std::string::npos || line.find("0.00 ->") != std::string::npos) continue;
    EXPECT_NE(line.find("90.0 %"), std::string::npos) << line;
  }
  EXPECT_EQ(rows, 9 + 12);  // GOST 27843 and ISO 230-2 parameters
  const std::string html = ReadText(s / "cmp/compare.html");
  EXPECT_NE(html.find("<td>air temperature C</td><td>20.1</td><td>20.6</td>"), std::string::npos);
  EXPECT_EQ(Volcomp({"report", "compare", s / "before", s / "nothing", "-o", s / "c2"}).code,
            kExitFailed);
}

}  // namespace
}  // namespace volcomp::tools
