// `volcomp build kmtpp`, run as main() runs it: the default (smooth) final step builds, the
// printed one is refused unless allowed, and the tables must be equally spaced.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "temp_paths.hpp"

namespace volcomp {
namespace {

using testing::Appended;
using testing::RunCli;
using testing::TempPath;

const std::vector<std::string> kBase = {"build",
                                        "kmtpp",
                                        "--model",
                                        "s500",
                                        "-o",
                                        TempPath("build_kmtpp_k.vctb"),
                                        "--resolution-nm",
                                        "X=1000,Y=1000,Z=1000"};

TEST(VolcompBuildKmtpp, DefaultAndDissertationForm) {
  auto r = RunCli(kBase);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("volcomp build kmtpp\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("  final_step: traced point\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  law: K=1.500000 l=0.100000\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  calibration: STAN S500 laser tracker, 315 mm cube (Tables 2.10-2.12), "
                       "interval 1, signed\n"),
            std::string::npos)
      << r.out;
  r = RunCli(Appended(kBase, {"--dissertation"}));
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--allow-discontinuous"), std::string::npos) << r.err;
  r = RunCli(Appended(kBase, {"--gain", "10", "--step", "1"}));
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_EQ(r.err,
            "volcomp build kmtpp: --gain times --step must lie in (0, 2)\n(`volcomp help build "
            "kmtpp` lists the options)\n");
}

TEST(VolcompBuildKmtpp, RefinedTablesAndTheirSpacing) {
  const auto r = RunCli(Appended(kBase, {"--refine-mm", "5", "--range", "X=0:40,Y=0:40,Z=0:40"}));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("spacing 5 mm (5000 steps)"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace volcomp
