// `volcomp build model`, run as main() runs it: the image is valid, the report says what it must
// (text and JSON from the same data), and bad input is refused with a clear message and exit code.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "expected_value.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/tools/file_io.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::Appended;
using testing::RunCli;
using testing::TempPath;
using testing::ValueOf;

TEST(VolcompBuildModel, WritesAValidImageAndReports) {
  const std::string out = TempPath("build_model_s500.vctb");
  const auto r = RunCli({"build", "model", "--model", testing::SamplePath("model/s500.conf"), "-o",
                         out, "--resolution-nm", "X=1000,Y=1000,Z=1000", "--table-id", "7"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("volcomp build model\n  builder: volcomp build model\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("  lattice X: 0 .. 400 mm, spacing 20 mm (20000 steps), 21 nodes\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("predicted interpolation error between nodes"), std::string::npos);
  EXPECT_NE(r.out.find("inverse at the nodes: worst residual"), std::string::npos);
  EXPECT_NE(r.out.find("(bound 1000 µm)"), std::string::npos);
  EXPECT_NE(r.out.find("  wrote " + out + " ("), std::string::npos);
  const image::LoadedImage img = ValueOf(image::ReadImageFile(out));
  EXPECT_EQ(img.view().table_id, 7u);
  EXPECT_EQ(img.view().axis_count, 3u);
}

TEST(VolcompBuildModel, JsonHoldsEveryFigureOfTheText) {
  const std::string out = TempPath("build_model_small.vctb");
  const auto r = RunCli({"build", "model", "--model", "s500", "-o", out, "--resolution-nm",
                         "X=1000,Y=1000,Z=1000", "--range", "X=0:40,Y=0:20,Z=0:20", "--spacing-mm",
                         "20", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const tools::JsonValue d = ValueOf(tools::ParseJson(r.out, "stdout"));
  EXPECT_EQ(d.get("image")->string, out);
  EXPECT_EQ(d.get("source")->get("builder")->string, "volcomp build model");
  const tools::JsonValue& x = d.get("lattice")->array[0];
  EXPECT_EQ(x.get("nodes")->integer, 3);
  EXPECT_EQ(x.get("spacing_steps")->integer, 20000);
  EXPECT_DOUBLE_EQ(x.get("end_mm")->number, 40);
  EXPECT_DOUBLE_EQ(d.get("max_correction_bound_um")->number, 1000);
  EXPECT_DOUBLE_EQ(d.get("max_inverse_residual_limit_um")->number, 0.01);
  EXPECT_LT(d.get("max_inverse_residual_um")->number, 0.01);
  EXPECT_GT(d.get("interpolation")->get("samples")->integer, 0);
  EXPECT_EQ(d.get("element")->string, "int16");
  EXPECT_EQ(d.get("lsb_um")->array.size(), 3u);
  EXPECT_EQ(d.get("spacings_tried")->array.size(), 1u);
}

TEST(VolcompBuildModel, RefusesCorrectionsBeyondTheBound) {
  const std::string out = TempPath("build_model_bound.vctb");
  const auto r = RunCli({"build", "model", "--model", "s500", "-o", out, "--resolution-nm",
                         "X=1000,Y=1000,Z=1000", "--max-correction-um", "100"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_EQ(r.err,
            "volcomp build model: error: correction of 421.9 µm at (400, 280, 200) mm exceeds the "
            "configured bound of 100.0 µm; check the input units or raise the bound "
            "(--max-correction-um)\n");
  EXPECT_EQ(r.out, "");
  // With --json the failure is a JSON object on stdout too.
  const auto j = RunCli({"build", "model", "--model", "s500", "-o", out, "--resolution-nm",
                         "X=1000,Y=1000,Z=1000", "--max-correction-um", "100", "--json"});
  EXPECT_EQ(j.code, tools::kExitFailed);
  const tools::JsonValue d = ValueOf(tools::ParseJson(j.out, "stdout"));
  EXPECT_EQ(d.get("exit_code")->integer, 1);
  EXPECT_NE(d.get("error")->string.find("(--max-correction-um)"), std::string::npos);
}

TEST(VolcompBuildModel, GridOptionsAreChecked) {
  const std::vector<std::string> base = {"build", "model", "--model",
                                         "s500",  "-o",    TempPath("build_model_x.vctb")};
  const auto usage = [](const std::vector<std::string>& words, const std::string& message) {
    const auto r = RunCli(words);
    EXPECT_EQ(r.code, tools::kExitUsage) << message;
    EXPECT_EQ(r.err, "volcomp build model: " + message +
                         "\n(`volcomp help build model` lists the options)\n");
  };
  usage(base, "axis X needs --resolution-nm or --steps-per-unit");
  usage(Appended(base, {"--resolution-nm", "X=300,Y=1000,Z=1000", "--spacing-mm",
                        "X=20.00005,Y=10,Z=10"}),
        "axis X: spacing 20.00005 mm is not a whole number of steps (0.0003 mm/step)");
  usage(Appended(base, {"--resolution-nm", "X=1000,Y=1000,Z=1000", "--spacing-mm", "10",
                        "--max-interp-error-um", "1"}),
        "give either --spacing-mm or --max-interp-error-um, not both");
  usage(Appended(base, {"--resolution-nm", "X=1000,Y=1000,Z=1000", "--range", "X=5:1"}),
        "--range: expected AXIS=MIN:MAX with MIN < MAX (mm), got \"X=5:1\"");
  usage(Appended(base, {"--resolution-nm", "X=1000,Y=1000,Z=1000", "--order", "third"}),
        "--order must be first or exact (second)");
  usage(Appended(base, {"--resolution-nm", "X=1000,Y=1000,Z=1000", "--angle-scale", "big"}),
        "option --angle-scale: \"big\" is not a number");
  usage({"build", "model", "-o", TempPath("build_model_x.vctb")},
        "missing required option --model");
}

// `--board FILE` checks the image against the board's settings file before writing it. The S500
// table asks up to 421.9 steps on X (TableFit's figure), its lattice spans X 0..400 mm; the board
// file says X clamps at 20 steps and references at -5 mm: refused with nothing written, written
// with --allow-clamp and both said (text and JSON alike); another units per step is a mismatch
// that --allow-clamp does not pass; --bank-bytes below the image's size is refused.
TEST(VolcompBuildModel, BoardFileChecksTheImageBeforeItIsWritten) {
  const std::string board = TempPath("build_model_board.ini");
  ASSERT_TRUE(tools::WriteTextFile(board,
                                   "[board]\naxes = X Y Z\n[axis X]\nhome_position = -5000\n"
                                   "max_correction = 20\n[axis Y]\n[axis Z]\n")
                  .ok());
  const std::string out = TempPath("build_model_board.vct");
  std::filesystem::remove(out);
  const std::vector<std::string> build = {
      "build",   "model", "--model",         testing::SamplePath("model/s500.conf"),
      "-o",      out,     "--resolution-nm", "X=1000,Y=1000,Z=1000",
      "--board", board};
  const auto refused = RunCli(build);
  EXPECT_EQ(refused.code, 1) << refused.err;
  EXPECT_NE(refused.err.find("the image does not fit the board of " + board +
                             " (nothing written):\n  axis 1 (X): the table asks for up to 421.9 "
                             "steps of correction, the board's max correction (0x2015:1) is 20 "
                             "steps: it would be clamped"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  const auto allowed = RunCli(Appended(build, {"--allow-clamp", "--json"}));
  ASSERT_EQ(allowed.code, 0) << allowed.err;
  EXPECT_TRUE(std::filesystem::exists(out));
  const std::string home =
      "[axis X]: the home position -5000 steps (-5.0000 mm), where the board references, lies "
      "outside the table's X range 0.0000..400.0000 mm";
  EXPECT_NE(allowed.err.find("warning: axis 1 (X): the table asks for up to 421.9 steps"),
            std::string::npos)
      << allowed.err;
  EXPECT_NE(allowed.err.find("warning: " + home), std::string::npos) << allowed.err;
  const tools::JsonValue d = ValueOf(tools::ParseJson(allowed.out, "stdout"));
  const tools::JsonValue* check = d.get("board_check");
  ASSERT_NE(check, nullptr) << allowed.out;
  EXPECT_EQ(check->get("file")->string, board);
  EXPECT_TRUE(check->get("problems")->array.empty());
  ASSERT_EQ(check->get("warnings")->array.size(), 2u);
  EXPECT_EQ(check->get("warnings")->array[1].string.rfind(home, 0), 0u);
  EXPECT_EQ(check->get("image_bytes")->integer,
            static_cast<int64_t>(std::filesystem::file_size(out)));
  const auto small = RunCli(Appended(build, {"--allow-clamp", "--bank-bytes", "1000"}));
  EXPECT_EQ(small.code, 1);
  EXPECT_NE(small.err.find("does not fit the board's table bank of 1000 bytes (--bank-bytes)"),
            std::string::npos)
      << small.err;
  ASSERT_TRUE(tools::WriteTextFile(board,
                                   "[board]\naxes = X Y Z\n[axis X]\nunits_per_step = 0.0005\n"
                                   "[axis Y]\n[axis Z]\n")
                  .ok());
  const auto other = RunCli(Appended(build, {"--allow-clamp"}));
  EXPECT_EQ(other.code, 1);
  // 1000 nm/step is 1/0.001 mm = 1000 steps/mm; 0.0005 mm = 500 nm/step is 2000 steps/mm.
  EXPECT_NE(other.err.find("axis 1 (X): the table was built for 1000 steps/mm (1000 nm/step), the "
                           "board runs 2000 steps/mm (500 nm/step) (0x2012:1)"),
            std::string::npos)
      << other.err;
  const auto usage =
      RunCli({"build", "model", "--model", testing::SamplePath("model/s500.conf"), "-o", out,
              "--resolution-nm", "X=1000,Y=1000,Z=1000", "--allow-clamp"});
  EXPECT_EQ(usage.code, 2);
  EXPECT_NE(usage.err.find("--bank-bytes and --allow-clamp need --board FILE"), std::string::npos);
}

TEST(VolcompBuildModel, AModelFileThatCannotBeReadIsAFailure) {
  const auto r =
      RunCli({"build", "model", "--model", "/nonexistent.conf", "-o",
              TempPath("build_model_x.vctb"), "--resolution-nm", "X=1000,Y=1000,Z=1000"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_EQ(r.err, "volcomp build model: error: /nonexistent.conf: cannot open the model file\n");
}

}  // namespace
}  // namespace volcomp
