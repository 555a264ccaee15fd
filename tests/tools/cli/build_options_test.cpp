// Options shared by the table builders: table ids start at 1 (0x2103 reports 0 for "no table
// active"), and the step size is given once (--resolution-nm or --steps-per-unit, not both).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "cli_runner.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::SamplePath;
using testing::TempPath;

std::vector<std::string> SmallModelBuild(const std::string& img) {
  return {"build",
          "model",
          "--model",
          "s500",
          "--range",
          "X=0:40,Y=0:20,Z=0:20",
          "--spacing-mm",
          "20",
          "--resolution-nm",
          "X=1000,Y=1000,Z=1000",
          "-o",
          img};
}

TEST(VolcompBuildOptions, TableIdDefaultsToOne) {
  const std::string img = TempPath("build_options_default_id.vct");
  const auto r = RunCli(SmallModelBuild(img));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto i = RunCli({"inspect", img, "--json"});
  EXPECT_NE(i.out.find("\"table_id\": 1,"), std::string::npos) << i.out;
  std::filesystem::remove(img);
}

TEST(VolcompBuildOptions, TableIdZeroIsRefused) {
  const std::string img = TempPath("build_options_zero_id.vct");
  auto words = SmallModelBuild(img);
  words.insert(words.end(), {"--table-id", "0"});
  const auto r = RunCli(words);
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--table-id must be 1..4294967295 (0 means no table active)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(img));
  const auto axis = RunCli({"build", "axis", "--x", SamplePath("model/positioning_x.csv"),
                            "--resolution-nm", "X=1000", "--table-id", "0", "-o", img});
  EXPECT_EQ(axis.code, tools::kExitUsage) << axis.err;
  EXPECT_FALSE(std::filesystem::exists(img));
}

TEST(VolcompBuildOptions, ResolutionAndStepsPerUnitTogetherAreAConflict) {
  const std::string img = TempPath("build_options_conflict.vct");
  auto model = SmallModelBuild(img);
  model.insert(model.end(), {"--steps-per-unit", "X=1000,Y=1000,Z=1000"});
  const std::string grid_csv = TempPath("build_options_conflict.csv");
  std::ofstream(grid_csv) << "x_mm,y_mm,z_mm,dx_um,dy_um,dz_um\n0,0,0,1,1,1\n1,0,0,1,1,1\n"
                             "0,1,0,1,1,1\n1,1,0,1,1,1\n0,0,1,1,1,1\n1,0,1,1,1,1\n0,1,1,1,1,1\n"
                             "1,1,1,1,1,1\n";
  for (const auto& words : std::vector<std::vector<std::string>>{
           model,
           {"build", "grid", "--csv", grid_csv, "-o", img, "--resolution-nm",
            "X=1000,Y=1000,Z=1000", "--steps-per-unit", "X=1000,Y=1000,Z=1000"},
           {"build", "axis", "--x", SamplePath("model/positioning_x.csv"), "-o", img,
            "--resolution-nm", "X=1000", "--steps-per-unit", "X=1000"}}) {
    const auto r = RunCli(words);
    EXPECT_EQ(r.code, tools::kExitUsage) << words[1];
    EXPECT_NE(r.err.find("give either --resolution-nm or --steps-per-unit, not both"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(img));
  }
  std::filesystem::remove(grid_csv);
}

}  // namespace
}  // namespace volcomp
