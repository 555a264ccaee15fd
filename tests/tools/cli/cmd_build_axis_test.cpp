// `volcomp build axis`, run as main() runs it: the report, the mean-deviation and raw-reading
// layouts (the raw readings give the table of their means, checked like the evaluation), and the
// refusals naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_runner.hpp"
#include "expected_value.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/image/image_reader.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::SamplePath;
using testing::TempPath;
using testing::ValueOf;

// Readings at targets 0, 50, ..., 300 mm: ↑ mean 3 + 0.01·t µm, ↓ mean 3 + 0.01·t − 4 µm; the five
// runs scatter by −2, −1, 0, +1, +2 µm around the mean, so the mean of each series is exact.
std::string RawReadings(int runs) {
  std::ostringstream s;
  s << "# axis: X\ntarget_mm,direction,run,deviation_um\n";
  for (int run = 1; run <= runs; ++run) {
    for (int t = 0; t <= 300; t += 50)
      s << t << ",up," << run << "," << 3 + 0.01 * t + (run - 3) << "\n";
    for (int t = 300; t >= 0; t -= 50) {
      s << t << ",down," << run << "," << 3 + 0.01 * t - 4 + (3 - run) << "\n";
    }
  }
  return s.str();
}

std::string Means() {
  std::ostringstream s;
  s << "position_mm,dev_forward_um,dev_reverse_um\n";
  for (int t = 0; t <= 300; t += 50)
    s << t << "," << 3 + 0.01 * t << "," << 3 + 0.01 * t - 4 << "\n";
  return s.str();
}

std::string Lookup(const std::string& image) {
  std::string points = "x_mm,dir_x\n";
  for (int t = 0; t <= 300; t += 7)
    points += std::to_string(t) + ",1\n" + std::to_string(t) + ",-1\n";
  const auto r = RunCli({"lookup", image}, points);
  EXPECT_EQ(r.code, 0) << r.err;
  return r.out;
}

TEST(VolcompBuildAxis, RawReadingsGiveTheTableOfTheirMeans) {
  const std::string raw = TempPath("build_axis_raw.csv"), means = TempPath("build_axis_means.csv");
  const std::string a = TempPath("build_axis_raw.vct"), b = TempPath("build_axis_means.vct");
  std::ofstream(raw) << RawReadings(5);
  std::ofstream(means) << Means();
  for (const auto& [in, out] : {std::pair{raw, a}, std::pair{means, b}}) {
    const auto r = RunCli({"build", "axis", "--x", in, "--resolution-nm", "X=1000", "-o", out});
    ASSERT_EQ(r.code, 0) << r.err;
  }
  const std::string la = Lookup(a);
  EXPECT_EQ(la, Lookup(b));
  EXPECT_NE(la.find("\n"), std::string::npos);
  for (const auto& f : {raw, means, a, b}) std::filesystem::remove(f);
}

TEST(VolcompBuildAxis, RawReadingsAreCheckedLikeTheEvaluation) {
  const std::string raw = TempPath("build_axis_few.csv"), img = TempPath("build_axis_few.vct");
  std::ofstream(raw) << RawReadings(3);
  const auto r = RunCli({"build", "axis", "--x", raw, "--resolution-nm", "X=1000", "-o", img});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find(raw + ":3: target 0 mm ↑ has 3 approaches"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(img));
  std::filesystem::remove(raw);
}

TEST(VolcompBuildAxis, FromAPositioningTest) {
  const std::string out = TempPath("build_axis_a.vct");
  const auto r =
      RunCli({"build", "axis", "--x", SamplePath("model/positioning_x.csv"), "-o", out,
              "--resolution-nm", "X=1000", "--reverse", "backlash", "--spacing", "X=20"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out,
            "volcomp build axis\n"
            "  axis X: 21 nodes from 0 every 20 mm, largest forward correction 42.662 µm, no "
            "reverse table, backlash 4.010 µm\n"
            "  wrote " +
                out + " (" + std::to_string(std::filesystem::file_size(out)) + " bytes)\n");
  EXPECT_EQ(ValueOf(image::ReadImageFile(out)).view().axis_count, 1u);
  // A rotary axis given a linear file is refused, naming the file.
  const auto rotary = RunCli({"build", "axis", "--a", SamplePath("model/positioning_x.csv"), "-o",
                              out, "--resolution-nm", "A=1000"});
  EXPECT_EQ(rotary.code, tools::kExitFailed);
  EXPECT_EQ(rotary.err, "volcomp build axis: error: " + SamplePath("model/positioning_x.csv") +
                            ": axis A is rotary: give position_deg and *_arcsec columns\n");
  EXPECT_EQ(rotary.out, "");
  const auto spacing = RunCli({"build", "axis", "--x", SamplePath("model/positioning_x.csv"), "-o",
                               out, "--resolution-nm", "X=1000", "--spacing", "Y=20"});
  EXPECT_EQ(spacing.code, tools::kExitUsage);
  EXPECT_NE(spacing.err.find("--spacing: no input file for axis Y"), std::string::npos);
}

// The builder says which measured deviations are smaller than the test's U: the sample .rtl's
// means (odd runs ↑, even ↓, from its DEVIATIONS block) are 0, 2, 4, 3, 1 and −1, 1, 2.5, 2, 0 µm;
// with a 0.5 ppm laser its U is 0.62 µm (cmd_evaluate_positioning_test.cpp works it by hand), so
// 2 of 10 are smaller.
TEST(VolcompBuildAxis, SaysWhichCorrectionsAreWithinTheUncertainty) {
  const std::string out = TempPath("build_axis_u.vct");
  const auto r = RunCli({"build", "axis", "--x", SamplePath("metrology/renishaw_x.rtl"), "-o", out,
                         "--steps-per-unit", "X=1000", "--instrument-ppm", "0.5"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("U (k = 2) of the test 0.62 µm: 2 of 10 measured deviations are smaller"),
            std::string::npos)
      << r.out;
  std::filesystem::remove(out);
}

// The same for a rotary table against an angle reference (±1″ stated, 1.5″ drift test: U 1.5″,
// worked in cmd_evaluate_positioning_test.cpp). The sample's per-target means (the GOST table of
// `evaluate positioning`) below 1.5″ in magnitude: ↑ 0.23, −0.82, −0.34, −0.92 and ↓ 0.90: 5 of 24.
TEST(VolcompBuildAxis, SaysWhichRotaryCorrectionsAreWithinTheUncertainty) {
  const std::string out = TempPath("build_axis_u_rotary.vct");
  const auto r =
      RunCli({"build", "axis", "--c", SamplePath("metrology/rotary_table_positioning.csv"), "-o",
              out, "--steps-per-unit", "C=1000", "--instrument-accuracy-arcsec", "1",
              "--drift-range-arcsec", "1.5"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("U (k = 2) of the test 1.50 arcsec: 5 of 24 measured deviations are "
                       "smaller"),
            std::string::npos)
      << r.out;
  std::filesystem::remove(out);
}

}  // namespace
}  // namespace volcomp
