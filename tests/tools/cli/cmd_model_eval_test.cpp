// `volcomp model eval`, run as main() runs it: the forward error and the inverse command of a
// model at points, CSV in (a file or stdin) and out (stdout or -o FILE).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "temp_paths.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::TempPath;

TEST(VolcompModelEval, ForwardAndInverse) {
  const std::string points = TempPath("model_eval_points.csv");
  std::ofstream(points) << "x_mm,y_mm,z_mm\n300,150,50\n";
  // Appendix А in the dissertation formulation: 54.789039 µm (printed δ).
  auto r = RunCli({"model", "eval", "--model", "s500", "--formulation", "dissertation", "--order",
                   "first", "--tool-offset-mm", "10,10,10", points});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(
      r.out.rfind("x_mm,y_mm,z_mm,ex_um,ey_um,ez_um,e_um\n300.000000,150.000000,50.000000,", 0), 0u)
      << r.out;
  EXPECT_NE(r.out.find(",54.789039\n"), std::string::npos) << r.out;
  r = RunCli({"model", "eval", "--model", "s500", "--inverse", "-"}, "x_mm,y_mm,z_mm\n1,2,3\n");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("x_mm,y_mm,z_mm,cmd_x_mm,cmd_y_mm,cmd_z_mm,dx_um,dy_um,dz_um,residual_um\n"
                        "1.000000,2.000000,3.000000,",
                        0),
            0u)
      << r.out;
}

TEST(VolcompModelEval, WritesTheFileGiven) {
  const std::string points = TempPath("model_eval_p2.csv"), out = TempPath("model_eval_out.csv");
  std::ofstream(points) << "x_mm,y_mm,z_mm,label\n0,0,0,a\n400,280,200,b\n";
  const auto r = RunCli({"model", "eval", "--model", "s500", points, "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  std::ifstream f(out);
  std::stringstream text;
  text << f.rdbuf();
  int lines = 0;
  for (char c : text.str()) lines += c == '\n';
  EXPECT_EQ(lines, 3);
}

TEST(VolcompModelEval, BadInputIsNamed) {
  const std::string points = TempPath("model_eval_bad.csv");
  std::ofstream(points) << "x_mm,y_mm\n1,2\n";
  auto r = RunCli({"model", "eval", "--model", "s500", points});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_EQ(r.err, "volcomp model eval: error: " + points + ":1: missing column \"z_mm\"\n");
  r = RunCli({"model", "eval", "--model", "/nonexistent.conf", points});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_EQ(r.err, "volcomp model eval: error: /nonexistent.conf: cannot open the model file\n");
  r = RunCli({"model", "eval", "--model", "s500", points, points});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("expected one points file (or - for stdin)"), std::string::npos);
}

}  // namespace
}  // namespace volcomp
