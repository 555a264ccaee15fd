// The commands that read a positioning test take a Renishaw .rtl as they take volcomp's CSV:
// samples/metrology/renishaw_x.rtl and tests/tools/datasets/data/renishaw_x_as_csv.csv hold the
// same readings, written by hand (↑ means {0, 2, 4, 3, 1} µm, ↓ means {−1, 1, 2.5, 2, 0} µm at
// 0..400 mm, each of the 5 runs per direction offset by −0.2, −0.1, 0, +0.1, +0.2 µm).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "file_contents.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/tools/exit_codes.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::FreshTempPath;
using testing::ReadBytes;
using testing::ReadText;
using testing::RunCli;
using testing::SamplePath;
using testing::SourcePath;

const std::string kRtl = SamplePath("metrology/renishaw_x.rtl");
const std::string kCsv = SourcePath("tests/tools/datasets/data/renishaw_x_as_csv.csv");

tools::JsonValue Json(const std::string& text) {
  auto doc = tools::ParseJson(text, "stdout");
  EXPECT_TRUE(doc.ok()) << text;
  return doc.ok() ? *doc : tools::JsonValue{};
}

std::string Compact(const tools::JsonValue& v) {
  std::ostringstream s;
  tools::WriteJson(v, s, true);
  return s.str();
}

double Param(const tools::JsonValue& evaluation, const char* name) {
  return evaluation.get("parameters")->get(name)->get("value")->number;
}

TEST(PositioningRtlCli, EvaluateGivesTheCsvTwinsResultAndTheHandWorkedValues) {
  const auto rtl = RunCli({"evaluate", "positioning", kRtl, "--standard", "both", "--json"});
  const auto csv = RunCli({"evaluate", "positioning", kCsv, "--standard", "both", "--json"});
  ASSERT_EQ(rtl.code, 0) << rtl.err;
  ASSERT_EQ(csv.code, 0) << csv.err;
  const tools::JsonValue a = Json(rtl.out), b = Json(csv.out);
  EXPECT_EQ(a.get("format")->string, "rtl");
  EXPECT_EQ(b.get("format")->string, "csv");
  EXPECT_EQ(Compact(*a.get("evaluations")), Compact(*b.get("evaluations")));
  EXPECT_EQ(a.get("conditions")->get("axis")->string, "X");
  EXPECT_EQ(a.get("conditions")->get("air temperature C")->string,
            "20.33728 at start, 20.384956 at end");

  // Independently: s of the offsets {−0.2, −0.1, 0, 0.1, 0.2} with the n − 1 divisor.
  const double s = std::sqrt((0.04 + 0.01 + 0 + 0.01 + 0.04) / 4);
  const std::vector<double> up = {0, 2, 4, 3, 1}, down = {-1, 1, 2.5, 2, 0};
  double hi = -1e9, lo = 1e9, mhi = -1e9, mlo = 1e9, b_max = 0;
  for (std::size_t j = 0; j < 5; ++j) {
    hi = std::max({hi, up[j], down[j]});
    lo = std::min({lo, up[j], down[j]});
    mhi = std::max(mhi, (up[j] + down[j]) / 2);
    mlo = std::min(mlo, (up[j] + down[j]) / 2);
    b_max = std::max(b_max, std::fabs(up[j] - down[j]));
  }
  const auto& evaluations = a.get("evaluations")->array;
  ASSERT_EQ(evaluations.size(), 2u);
  const tools::JsonValue& gost = evaluations[0];
  const tools::JsonValue& iso = evaluations[1];
  EXPECT_NEAR(Param(gost, "A"), (hi + 3 * s) - (lo - 3 * s), 1e-9);  // 5.9487
  EXPECT_NEAR(Param(gost, "B_max"), b_max, 1e-9);                    // 1.5
  EXPECT_NEAR(Param(iso, "E"), hi - lo, 1e-9);                       // 5.0
  EXPECT_NEAR(Param(iso, "M"), mhi - mlo, 1e-9);                     // 3.75
  EXPECT_NEAR(Param(iso, "A"), (hi + 2 * s) - (lo - 2 * s), 1e-9);   // 5.6325
  EXPECT_NEAR(Param(iso, "B"), b_max, 1e-9);
  // The text names the same figures.
  const auto text = RunCli({"evaluate", "positioning", kRtl, "--standard", "iso230-2"});
  EXPECT_NE(text.out.find("E       = 5.00"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("M       = 3.75"), std::string::npos) << text.out;
}

TEST(PositioningRtlCli, StdinIsRecognisedByContentToo) {
  const auto r = RunCli({"evaluate", "positioning", "-", "--json"}, ReadText(kRtl));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(Json(r.out).get("format")->string, "rtl");
}

TEST(PositioningRtlCli, FormatForcedOrRefused) {
  const auto forced = RunCli({"evaluate", "positioning", kRtl, "--format", "csv"});
  EXPECT_EQ(forced.code, tools::kExitFailed);
  EXPECT_NE(forced.err.find("(the file looks like a Renishaw .rtl: --format rtl or auto reads it)"),
            std::string::npos)
      << forced.err;
  const auto bad = RunCli({"evaluate", "positioning", kRtl, "--format", "ren"});
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("--format must be auto, csv or rtl"), std::string::npos) << bad.err;
  const auto runs = RunCli({"evaluate", "positioning", kRtl, "--rtl-runs", "both"});
  EXPECT_NE(runs.err.find("--rtl-runs must be alternate, forward or reverse"), std::string::npos)
      << runs.err;
  // Read forward, the sample's even runs (listed last target first) contradict the rule: warned,
  // and the 10 runs per target are then one direction.
  const auto forward = RunCli({"evaluate", "positioning", kRtl, "--rtl-runs", "forward", "--json"});
  ASSERT_EQ(forward.code, 0) << forward.err;
  EXPECT_NE(forward.err.find(kRtl + ":26: runs 2, 4, 6, 8 and 10 (read as ↑) list their targets"),
            std::string::npos)
      << forward.err;
}

TEST(PositioningRtlCli, MeansFileIsNotEvaluated) {
  const auto r = RunCli({"evaluate", "positioning", SamplePath("model/positioning_x.csv")});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("evaluate positioning needs the readings of every run"), std::string::npos)
      << r.err;
}

TEST(PositioningRtlCli, BuildAxisAndExportLinuxcncTakeTheRtlAsTheCsv) {
  // Each input copied to the same name (recognised by content): equal data give equal files,
  // byte for byte (the image's INFO names the source file).
  const std::string dir = FreshTempPath("positioning_rtl");
  std::filesystem::create_directories(dir);
  const std::string in = dir + "/x_axis_test";
  for (const auto& [name, source] : {std::pair{"rtl", kRtl}, std::pair{"csv", kCsv}}) {
    std::filesystem::copy_file(source, in, std::filesystem::copy_options::overwrite_existing);
    const std::string img = dir + "/" + name + ".img";
    const auto b = RunCli({"build", "axis", "--x", in, "--resolution-nm", "X=1000", "-o", img});
    ASSERT_EQ(b.code, 0) << b.err;
    const auto e = RunCli({"export", "linuxcnc", "--x", in, "-o", dir + "/" + name, "--json"});
    ASSERT_EQ(e.code, 0) << e.err;
    EXPECT_EQ(Json(e.out).get("axes")->array[0].get("format")->string, name);
  }
  EXPECT_EQ(ReadBytes(dir + "/rtl.img"), ReadBytes(dir + "/csv.img"));
  EXPECT_EQ(ReadText(dir + "/rtl/x.comp"), ReadText(dir + "/csv/x.comp"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace volcomp
