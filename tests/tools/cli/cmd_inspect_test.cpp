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

}  // namespace
}  // namespace volcomp
