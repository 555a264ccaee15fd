// `volcomp model export` and `--model` reading Etalon / ISG-CSV, run as main() runs them: round
// trips model → file → model equal within the written precision (12 decimals of mm and rad), what
// a file cannot carry is named, `build model` takes the hand-written samples (recognised by content
// or forced) and reports where the model came from in its JSON.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "comment_lines.hpp"
#include "expected_value.hpp"
#include "sample_path.hpp"
#include "temp_paths.hpp"
#include "volcomp/datasets/etalon_exchange.hpp"
#include "volcomp/datasets/model_file.hpp"
#include "volcomp/datasets/s500.hpp"
#include "volcomp/tools/file_io.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp {
namespace {

using testing::RunCli;
using testing::SamplePath;
using testing::TempPath;
using testing::ValueOf;
using testing::WithoutCommentLines;

// Written precision: 1e-12 mm = 1e-9 µm, 1e-12 rad = 1e-6 µrad; arguments 1e-6 mm.
void ExpectSameModel(const model::Model& a, const model::Model& b) {
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const model::AxisErrorTable& ta = a.axes[axis];
    const model::AxisErrorTable& tb = b.axes[axis];
    ASSERT_EQ(ta.size(), tb.size()) << axis;
    for (std::size_t i = 0; i < ta.size(); ++i) {
      EXPECT_NEAR(ta.position_mm(i), tb.position_mm(i), 5e-7);
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(ta.row(i).linear_um[k], tb.row(i).linear_um[k], 1e-8) << axis << i << k;
        EXPECT_NEAR(ta.row(i).angular_urad[k], tb.row(i).angular_urad[k], 1e-6) << axis << i;
      }
    }
  }
  EXPECT_NEAR(a.squareness.c0y_urad, b.squareness.c0y_urad, 1e-6);
  EXPECT_NEAR(a.squareness.b0z_urad, b.squareness.b0z_urad, 1e-6);
  EXPECT_NEAR(a.squareness.a0z_urad, b.squareness.a0z_urad, 1e-6);
}

TEST(VolcompModelExport, RoundTripsThroughBothFormats) {
  const model::Model s500 = datasets::S500Model();
  for (const char* format : {"etalon", "isg"}) {
    const std::string file = TempPath(std::string("model_export_s500.") + format);
    const auto r = RunCli({"model", "export", "--model", "s500", "--format", format, "-o", file});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");  // the S500 has the default chain and no tool offset: nothing lost
    const datasets::LoadedModel back = ValueOf(datasets::LoadModelFile(file));
    EXPECT_EQ(datasets::ModelFileFormatName(back.format), std::string(format));
    EXPECT_TRUE(back.warnings.empty());
    ExpectSameModel(s500, back.model);
    // And once more: the file read back and written again is the same text.
    const std::string again = TempPath(std::string("model_export_again.") + format);
    ASSERT_EQ(RunCli({"model", "export", "--model", file, "--format", format, "-o", again}).code,
              0);
    EXPECT_EQ(WithoutCommentLines(ValueOf(tools::ReadTextFile(file)), "//"),
              WithoutCommentLines(ValueOf(tools::ReadTextFile(again)), "//"));
  }
  // The hand-written samples: Etalon → ISG-CSV → the same model as the ISG sample.
  const std::string isg = TempPath("model_export_small.isg");
  ASSERT_EQ(RunCli({"model", "export", "--model", SamplePath("model/iso230/small.etalon"),
                    "--format", "isg", "-o", isg})
                .code,
            0);
  ExpectSameModel(ValueOf(datasets::LoadModelFile(isg)).model,
                  ValueOf(datasets::LoadModelFile(SamplePath("model/iso230/small_isg.csv"))).model);
}

TEST(VolcompModelExport, HeaderStatesSignUnitsAndSources) {
  const std::string file = TempPath("model_export_header.etalon");
  ASSERT_EQ(RunCli({"model", "export", "--model", "s500", "--format", "etalon", "-o", file}).code,
            0);
  const std::string text = ValueOf(tools::ReadTextFile(file));
  EXPECT_NE(text.find("// sign: error = actual - nominal"), std::string::npos) << text;
  EXPECT_NE(text.find("// units: errors mm, angles rad, arguments mm"), std::string::npos);
  EXPECT_NE(text.find("tf5280_volumetric_comp/296430091.html"), std::string::npos);
  // S500: C0Y = −1108.5 µrad (docs/table-builders.md §2) is −0.0011085 rad.
  EXPECT_NE(text.find("[C0Y]\nVALUE = -0.001108500000\n"), std::string::npos);
}

TEST(VolcompModelExport, NamesWhatTheFormatCannotCarry) {
  const std::string conf = TempPath("model_export_carriage.conf");
  ASSERT_TRUE(tools::WriteTextFile(conf,
                                   "builtin = s500\nworkpiece_axes = Y\ntool_axes = XZ\n"
                                   "workpiece_errors = carriage\nangle_scale = 2\n"
                                   "tool_offset_mm = 0, 0, 50\n")
                  .ok());
  const std::string file = TempPath("model_export_carriage.etalon");
  const auto r =
      RunCli({"model", "export", "--model", conf, "--format", "etalon", "-o", file, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: the errors of Y are the carriage's own"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("warning: angle_scale 2 applied"), std::string::npos);
  EXPECT_NE(r.err.find("warning: the kinematic chain Y|XZ is not written"), std::string::npos);
  EXPECT_NE(r.err.find("warning: the tool offset (0, 0, 50) mm is not written"), std::string::npos);
  const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
  EXPECT_EQ(j.get("not_carried")->array.size(), 4u);
  EXPECT_EQ(j.get("model")->get("format")->string, "conf");
  // In the file: Y's errors negated, the angles doubled (S500 rows from s500_data).
  const datasets::Iso230Set set =
      ValueOf(datasets::ParseEtalonExchange(ValueOf(tools::ReadTextFile(file)), file));
  const model::Model s500 = datasets::S500Model();
  for (const datasets::Iso230Parameter& p : set.parameters) {
    if (p.name == "EXY") {
      EXPECT_NEAR(p.values[3], -s500.axes[1].row(3).linear_um.x / 1000, 1e-12);
    }
    if (p.name == "EAX") {
      EXPECT_NEAR(p.values[2], 2 * s500.axes[0].row(2).angular_urad.x / 1e6, 1e-12);
    }
  }
}

TEST(VolcompModelExport, Refusals) {
  auto r = RunCli({"model", "export", "--model", "s500", "--format", "csv", "-o",
                   TempPath("model_export_bad")});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--format must be etalon or isg"), std::string::npos) << r.err;
  r = RunCli({"model", "export", "--model", "s500", "-o", TempPath("model_export_bad")});
  EXPECT_EQ(r.code, tools::kExitUsage);
  EXPECT_NE(r.err.find("--format"), std::string::npos) << r.err;
}

TEST(VolcompBuildModel, ReadsEtalonAndIsgCsv) {
  for (const char* sample : {"model/iso230/small.etalon", "model/iso230/small_isg.csv"}) {
    const std::string out = TempPath("build_model_iso230.vctb");
    const auto r = RunCli({"build", "model", "--model", SamplePath(sample), "-o", out,
                           "--resolution-nm", "X=1000,Y=1000,Z=1000", "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    const tools::JsonValue j = ValueOf(tools::ParseJson(r.out, "stdout"));
    const tools::JsonValue* m = j.get("model");
    ASSERT_NE(m, nullptr) << r.out;
    EXPECT_EQ(m->get("format")->string,
              std::string(sample).find(".etalon") != std::string::npos ? "etalon" : "isg");
    EXPECT_TRUE(m->get("detected")->boolean);
  }
  // Forced to the wrong format: refused with the line (exit 1).
  const auto r = RunCli({"build", "model", "--model", SamplePath("model/iso230/small.etalon"),
                         "--format", "isg", "-o", TempPath("build_model_forced.vctb"),
                         "--resolution-nm", "X=1000,Y=1000,Z=1000"});
  EXPECT_EQ(r.code, tools::kExitFailed);
  EXPECT_NE(r.err.find("small.etalon:6: "), std::string::npos) << r.err;
  // A parameter the model has no place for, zero: a warning naming it (stderr), not a silent drop.
  const std::string file = TempPath("build_model_extra.etalon");
  std::string text = ValueOf(tools::ReadTextFile(SamplePath("model/iso230/small.etalon")));
  text += "[C0B]\nVALUE = 0\n";
  ASSERT_TRUE(tools::WriteTextFile(file, text).ok());
  const auto w = RunCli({"model", "eval", "--model", file}, "x_mm,y_mm,z_mm\n100,0,0\n");
  ASSERT_EQ(w.code, 0) << w.err;
  EXPECT_NE(w.err.find("C0B is zero throughout and not part of the 21-parameter model: ignored"),
            std::string::npos)
      << w.err;
  // EXX = 4 µm at X = 100 (the sample's typed value), the other errors there add nothing in x.
  EXPECT_NE(w.out.find("100.000000,0.000000,0.000000,4.000000,"), std::string::npos) << w.out;
}

}  // namespace
}  // namespace volcomp
