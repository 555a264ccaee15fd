// `volcomp inspect IMAGE --report DIR`: the map page and its summary in text and JSON; a
// malformed or unreadable image is refused with nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_runner.hpp"
#include "expected_value.hpp"
#include "file_contents.hpp"
#include "node_grid_csv.hpp"
#include "temp_paths.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::ReadText;
using testing::RunCli;
using testing::ScratchDir;
using testing::ValueOf;
using testing::WriteText;

// The small grid (every node (1, 2, 3) steps) at 1 µm per step, built in `dir`.
std::string SmallGridImage(const ScratchDir& dir) {
  WriteText(dir / "grid.csv", testing::kSmallGridCsv);
  const auto r = RunCli({"build", "grid", "--csv", dir / "grid.csv", "-o", dir / "grid.vct",
                         "--steps-per-unit", "X=1000,Y=1000,Z=1000"});
  EXPECT_EQ(r.code, 0) << r.err;
  return dir / "grid.vct";
}

TEST(cli_inspect, ReportWritesTheMapAndItsSummary) {
  ScratchDir dir("inspect_report");
  const std::string img = SmallGridImage(dir);
  const auto r = RunCli({"inspect", img, "--report", dir / "map", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  const tools::JsonValue* map = j.get("map");
  ASSERT_NE(map, nullptr);
  EXPECT_EQ(map->get("report")->string, dir / "map/index.html");
  EXPECT_EQ(map->get("crc32")->string, j.get("crc32")->string);
  const auto& comps = map->get("grid3")->get("components")->array;
  ASSERT_EQ(comps.size(), 3u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_DOUBLE_EQ(comps[c].get("max_abs")->number, c + 1.0);
    EXPECT_EQ(comps[c].get("unit")->string, "um");
  }
  const std::string html = ReadText(dir / "map/index.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("Correction map: " + img), std::string::npos);

  const auto text = RunCli({"inspect", img, "--report", dir / "map"});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("map: " + dir / "map/index.html\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("largest |dz| 3 um at X = 0 mm, Y = 0 mm, Z = 0 mm\n"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("plane XY: slices at Z = 0 mm (lower), Z = 0.01 mm (upper), vectors x"),
            std::string::npos)
      << text.out;
}

TEST(cli_inspect, WithoutReportNothingChanges) {
  ScratchDir dir("inspect_plain");
  const std::string img = SmallGridImage(dir);
  const auto r = RunCli({"inspect", img, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(ValueOf(tools::ParseJson(r.out, "stdout")).get("map"), nullptr);
}

TEST(cli_inspect, BadImageWritesNothing) {
  ScratchDir dir("inspect_bad");
  WriteText(dir / "bad.vct", "this is not a table image");
  auto r = RunCli({"inspect", dir / "bad.vct", "--report", dir / "out"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("volcomp inspect: error: " + dir / "bad.vct" + ": invalid table image"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));

  r = RunCli({"inspect", dir / "missing.vct", "--report", dir / "out"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(dir / "missing.vct"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(cli_inspect, ShowsTheThermalModelInTextAndJson) {
  ScratchDir dir("inspect_thermal");
  image::ImageRequest r;
  r.table_id = 9;
  r.axes = {{'X', table::AxisKind::kLinear, 1000000}, {'Z', table::AxisKind::kLinear, 500000}};
  image::AxisCorrections x;
  x.axis = 0;
  x.lattice = {2, 0, 1000};
  x.forward_steps = {0, 1};
  r.axis_tables = {x};
  thermal::ThermalModel m;
  m.axis_count = 2;
  m.channel_mask = 0x02;  // channel 1
  m.slew_um_s = 0.5f;
  m.hold_ms = 90000;
  m.reference_cC[1] = 2000;
  m.calibrated_low_cC[1] = 1800;
  m.calibrated_high_cC[1] = 3500;
  m.axis[0].reach_mm = 400;
  m.axis[0].slope_um_per_K_m[1] = -11.5f;
  m.axis[1].offset_um_per_K[1] = 2.25f;
  r.thermal = m;
  const std::vector<uint8_t> bytes = ValueOf(image::BuildImage(r));
  WriteText(dir / "t.vct", std::string(bytes.begin(), bytes.end()));

  const auto j = RunCli({"inspect", dir / "t.vct", "--json"});
  ASSERT_EQ(j.code, 0) << j.err;
  const tools::JsonValue d = ValueOf(tools::ParseJson(j.out, "stdout"));
  EXPECT_EQ(d.get("format_version")->string, "1.1");
  const tools::JsonValue* t = d.get("thermal");
  ASSERT_NE(t, nullptr);
  EXPECT_DOUBLE_EQ(t->get("slew_um_s")->number, 0.5);
  EXPECT_EQ(t->get("hold_ms")->integer, 90000);
  ASSERT_EQ(t->get("channels")->array.size(), 1u);
  EXPECT_EQ(t->get("channels")->array[0].get("channel")->integer, 1);
  EXPECT_DOUBLE_EQ(t->get("channels")->array[0].get("calibrated_high_C")->number, 35.0);
  const auto& axes = t->get("axes")->array;
  ASSERT_EQ(axes.size(), 2u);
  EXPECT_EQ(axes[1].get("axis")->string, "Z");
  EXPECT_DOUBLE_EQ(axes[1].get("offset_um_per_K")->array[0].number, 2.25);
  EXPECT_DOUBLE_EQ(axes[0].get("slope_um_per_K_m")->array[0].number, -11.5);

  const auto text = RunCli({"inspect", dir / "t.vct"});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(
      text.out.find("THERMAL: slew 0.5 um/s, hold 90 s after a channel fault\n"
                    "  channel 1: reference 20 C, calibrated 18 .. 35 C\n"
                    "  X: p0 0 mm, reach 400 mm; per channel offset um/K 0, slope um/(K m) "
                    "-11.5\n"
                    "  Z: p0 0 mm, reach 0 mm; per channel offset um/K 2.25, slope um/(K m) 0\n"),
      std::string::npos)
      << text.out;
}

}  // namespace
}  // namespace volcomp
