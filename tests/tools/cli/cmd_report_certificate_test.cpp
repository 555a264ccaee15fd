// `volcomp report certificate` run as main() runs it: figures from the evaluations' own JSON,
// tolerances and pass/fail, fields not given left empty, the table from an image or a saved
// status, and bad input refused with what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::SamplePath;

void Write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::string Read(const std::string& path) {
  std::ifstream f(path);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

tools::JsonValue Json(const std::string& text) {
  auto doc = tools::ParseJson(text, "test");
  EXPECT_TRUE(doc.ok()) << text;
  return doc.ok() ? *doc : tools::JsonValue();
}

const tools::JsonValue* Figure(const tools::JsonValue& doc, const std::string& id) {
  for (const auto& f : doc.get("figures")->array) {
    if (f.get("id")->string == id) return &f;
  }
  return nullptr;
}

// The same diagonal and circular readings before and after (each figure equal on both sides).
struct Results {
  testing::ScratchDir scratch{"report_certificate"};  // its own folder: test cases run in parallel
  std::string dir = scratch.path();
  tools::JsonValue diagonal;  // `evaluate diagonal --json`, the oracle of the figures
  Results() {
    for (const char* when : {"/before", "/after"}) {
      EXPECT_EQ(RunCli({"evaluate", "diagonal", SamplePath("metrology/diagonals.csv"), "--report",
                        dir + when})
                    .code,
                0);
      EXPECT_EQ(RunCli({"evaluate", "circular", SamplePath("metrology/circular_xy.csv"), "--report",
                        dir + when})
                    .code,
                0);
    }
    diagonal =
        Json(RunCli({"evaluate", "diagonal", SamplePath("metrology/diagonals.csv"), "--json"}).out);
  }
};

TEST(ReportCertificate, FiguresTolerancesAndVerdicts) {
  Results r;
  const double e_d = std::round(r.diagonal.get("body")->get("E_d")->number * 100.0) / 100.0;
  ASSERT_GT(e_d, 1.0);
  // E_d's tolerance just below the figure: fail; H's far above: pass; G_b none: no verdict.
  Write(r.dir + "/info.ini", "[machine]\nserial = SN-1\n[tolerance]\niso230-6.E_d.body = " +
                                 std::to_string(e_d - 0.01) + "\niso230-4.H = 1000\n");
  auto res =
      RunCli({"report", "certificate", r.dir + "/before", r.dir + "/after", "-o", r.dir + "/cert",
              "--info", r.dir + "/info.ini", "--date", "2026-02-28", "--json"});
  ASSERT_EQ(res.code, 0) << res.err;
  const tools::JsonValue doc = Json(res.out);
  EXPECT_EQ(doc.get("date")->string, "2026-02-28");
  EXPECT_FALSE(doc.get("tool_version")->string.empty());
  const tools::JsonValue* ed = Figure(doc, "iso230-6.E_d");
  ASSERT_NE(ed, nullptr);
  EXPECT_EQ(ed->get("scope")->string, "body");
  EXPECT_EQ(ed->get("before")->number, e_d);
  EXPECT_EQ(ed->get("after")->number, e_d);
  EXPECT_EQ(ed->get("before_result")->string, "fail");
  EXPECT_EQ(ed->get("after_result")->string, "fail");
  EXPECT_TRUE(ed->get("uncertainty")->is_null());
  EXPECT_EQ(Figure(doc, "iso230-4.H")->get("after_result")->string, "pass");
  // The face diagonals' E_d (scope XY_Z200) has no tolerance of its own: no verdict.
  int faces = 0;
  for (const auto& f : doc.get("figures")->array) {
    if (f.get("id")->string != "iso230-6.E_d" || f.get("scope")->string == "body") continue;
    ++faces;
    EXPECT_EQ(f.get("scope")->string, "XY_Z200");
    EXPECT_TRUE(f.get("after_result")->is_null());
  }
  EXPECT_EQ(faces, 1);
  EXPECT_TRUE(Figure(doc, "iso230-4.G_b")->get("tolerance")->is_null());
  EXPECT_TRUE(Figure(doc, "iso230-4.G_b")->get("after_result")->is_null());
  EXPECT_EQ(doc.get("verdict")->string, "fail");
  EXPECT_EQ(doc.get("toleranced")->integer, 2);
  EXPECT_EQ(doc.get("failed_after")->integer, 1);
  // The circular sample states its ballbar (preamble): G and H carry the shape's U,
  // √(0.5² + (0.6·0.4)²) = 0.5546 µm (docs/metrology.md, circular test); the diagonals none.
  EXPECT_EQ(doc.get("uncertainty")->string, "U (k = 2) where the evaluations state it");
  const tools::JsonValue* h_u = Figure(doc, "iso230-4.H")->get("uncertainty");
  ASSERT_TRUE(h_u != nullptr && !h_u->is_null());
  EXPECT_NEAR(h_u->get("after")->number, std::hypot(0.5, 0.24), 1e-9);
  // Fields not given are null, never invented; the table was not given either.
  EXPECT_EQ(doc.get("fields")->get("machine")->get("serial")->string, "SN-1");
  EXPECT_TRUE(doc.get("fields")->get("customer")->get("name")->is_null());
  EXPECT_TRUE(doc.get("table")->get("table_id")->is_null());
  // The file holds what stdout printed; the page says what was tested, not file names.
  EXPECT_EQ(Read(r.dir + "/cert/certificate.json"), res.out);
  const std::string html = Read(r.dir + "/cert/certificate.html");
  EXPECT_NE(html.find("@page{size:A4"), std::string::npos);
  EXPECT_NE(html.find("Circular test, XY plane (ISO 230-4)"), std::string::npos);
  EXPECT_EQ(html.find("diagonals.csv"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"n fail\">fail</td>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>name</td><td class=\"fill\"></td></tr>"), std::string::npos);
  EXPECT_EQ(html.find("<svg"), std::string::npos);  // no charts

  // Text: the verdict and the figure line.
  res = RunCli({"report", "certificate", r.dir + "/before", r.dir + "/after", "-o", r.dir + "/cert",
                "--info", r.dir + "/info.ini", "--date", "2026-02-28"});
  ASSERT_EQ(res.code, 0) << res.err;
  EXPECT_NE(res.out.find("verdict: fail (1 of 2 toleranced figures out of tolerance after)"),
            std::string::npos)
      << res.out;
  EXPECT_NE(res.err.find("certificate written to " + r.dir + "/cert/certificate.html"),
            std::string::npos);
}

TEST(ReportCertificate, NoToleranceNoVerdictAndUnusedToleranceWarned) {
  Results r;
  Write(r.dir + "/info.ini", "[tolerance]\niso230-2.A.X = 5\n");
  auto res = RunCli({"report", "certificate", r.dir + "/before", r.dir + "/after", "-o",
                     r.dir + "/cert", "--info", r.dir + "/info.ini", "--json"});
  ASSERT_EQ(res.code, 0) << res.err;
  const tools::JsonValue doc = Json(res.out);
  EXPECT_TRUE(doc.get("verdict")->is_null());
  EXPECT_EQ(doc.get("date")->string.size(), 10u);  // today
  EXPECT_NE(res.err.find("warning: tolerance iso230-2.A.X (" + r.dir +
                         "/info.ini:2) applies to no figure of the results"),
            std::string::npos)
      << res.err;
}

// A rotary axis's figures are in arc-seconds: the tolerance for every axis (µm) does not judge
// them; its own FIGURE.AXIS does.
TEST(ReportCertificate, RotaryAxisTakesOnlyItsOwnTolerance) {
  testing::ScratchDir scratch("report_certificate_rotary");
  const std::string dir = scratch.path();
  Write(dir + "/c.csv", "# axis: C\n" + Read(SamplePath("metrology/rotary_table_positioning.csv")));
  for (const char* when : {"/before", "/after"}) {
    ASSERT_EQ(RunCli({"evaluate", "positioning", dir + "/c.csv", "--standard", "both", "--report",
                      dir + when})
                  .code,
              0);
  }
  Write(dir + "/info.ini", "[tolerance]\niso230-2.A = 1000\niso230-2.E = 1000\niso230-2.E.C = 1\n");
  const auto res = RunCli({"report", "certificate", dir + "/before", dir + "/after", "-o",
                           dir + "/cert", "--info", dir + "/info.ini", "--json"});
  ASSERT_EQ(res.code, 0) << res.err;
  const tools::JsonValue doc = Json(res.out);
  const tools::JsonValue* a = Figure(doc, "iso230-2.A");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->get("scope")->string, "C");
  EXPECT_EQ(a->get("unit")->string, "″");
  EXPECT_TRUE(a->get("tolerance")->is_null());
  EXPECT_EQ(Figure(doc, "iso230-2.E")->get("tolerance")->number, 1.0);
  EXPECT_EQ(Figure(doc, "iso230-2.E")->get("after_result")->string, "fail");
  EXPECT_EQ(doc.get("tests")->array.at(0).get("title")->string,
            "Positioning accuracy, C axis (rotary)");
}

TEST(ReportCertificate, TableFromImageAndFromSavedStatus) {
  Results r;
  ASSERT_EQ(RunCli({"build", "grid", "--csv", SamplePath("grid_example.csv"), "-o",
                    r.dir + "/t.vct", "--resolution-nm", "X=1000,Y=1000,Z=500", "--table-id", "7"})
                .code,
            0);
  const tools::JsonValue image = Json(RunCli({"inspect", r.dir + "/t.vct", "--json"}).out);
  const std::string crc = image.get("crc32")->string;
  auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> words = {"report",         "certificate", r.dir + "/before",
                                      r.dir + "/after", "-o",          r.dir + "/cert",
                                      "--json"};
    words.insert(words.end(), extra.begin(), extra.end());
    return RunCli(words);
  };
  auto res = run({"--table", r.dir + "/t.vct"});
  ASSERT_EQ(res.code, 0) << res.err;
  tools::JsonValue doc = Json(res.out);
  EXPECT_EQ(doc.get("table")->get("table_id")->integer, 7);
  EXPECT_EQ(doc.get("table")->get("crc32")->string, crc);
  EXPECT_EQ(doc.get("table")->get("origin")->string, "image");

  Write(r.dir + "/status.json",
        "{\"active_table\": {\"present\": true, \"id\": 7, \"crc32\": \"" + crc + "\"}}");
  res = run({"--table", r.dir + "/t.vct", "--status", r.dir + "/status.json"});
  ASSERT_EQ(res.code, 0) << res.err;
  EXPECT_EQ(Json(res.out).get("table")->get("origin")->string, "status");
  EXPECT_EQ(Json(res.out).get("table")->get("same_as_image")->string, r.dir + "/t.vct");

  Write(r.dir + "/status.json",
        "{\"active_table\": {\"present\": true, \"id\": 8, \"crc32\": \"0x00000001\"}}");
  res = run({"--table", r.dir + "/t.vct", "--status", r.dir + "/status.json"});
  EXPECT_EQ(res.code, tools::kExitFailed);
  EXPECT_NE(res.err.find("the board's active table in " + r.dir +
                         "/status.json (id 8, CRC-32 0x00000001) is not " + r.dir +
                         "/t.vct (id 7, CRC-32 " + crc + ")"),
            std::string::npos)
      << res.err;

  Write(r.dir + "/status.json",
        "{\"active_table\": {\"present\": false, \"id\": 0, \"crc32\": \"0x00000000\"}}");
  res = run({"--status", r.dir + "/status.json"});
  EXPECT_EQ(res.code, tools::kExitFailed);
  EXPECT_NE(res.err.find("the board had no active table"), std::string::npos) << res.err;
}

TEST(ReportCertificate, BadInputRefused) {
  Results r;
  auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> words = {"report",         "certificate", r.dir + "/before",
                                      r.dir + "/after", "-o",          r.dir + "/cert"};
    words.insert(words.end(), extra.begin(), extra.end());
    return RunCli(words);
  };
  for (const char* date : {"2026-02-29", "28.11.2026", "2026-13-01", "2026-1-01"}) {
    const auto res = run({"--date", date});
    EXPECT_EQ(res.code, tools::kExitFailed) << date;
    EXPECT_NE(res.err.find(std::string("--date '") + date + "': expected a calendar date"),
              std::string::npos)
        << res.err;
  }
  EXPECT_EQ(run({"--date", "2024-02-29"}).code, 0);
  Write(r.dir + "/info.ini", "[machine]\nserial = 1\ncolour = red\n");
  auto res = run({"--info", r.dir + "/info.ini"});
  EXPECT_EQ(res.code, tools::kExitFailed);
  EXPECT_NE(res.err.find(r.dir + "/info.ini:3: unknown key 'colour' in [machine]"),
            std::string::npos)
      << res.err;
  // Results that do not pair: a diagonal before, only a circular test after.
  std::filesystem::create_directories(r.dir + "/other");
  std::filesystem::copy(r.dir + "/after/circular_circular_xy.json", r.dir + "/other/x.json");
  res = RunCli({"report", "certificate",
                r.dir + "/before/diagonal_NPP_PNP_PPN_PPP_XY_PN_Z200_XY_PP_Z200.json",
                r.dir + "/other", "-o", r.dir + "/c2"});
  EXPECT_EQ(res.code, tools::kExitFailed);
  EXPECT_NE(res.err.find("no result appears both before and after"), std::string::npos) << res.err;
  EXPECT_FALSE(std::filesystem::exists(r.dir + "/c2/certificate.html"));
  res = RunCli({"report", "certificate", r.dir + "/before", "-o", r.dir + "/c3"});
  EXPECT_EQ(res.code, tools::kExitUsage);
}

}  // namespace
}  // namespace volcomp
