// ISO 230-1 component-error sets: the hand-written Etalon and ISG-CSV files of samples/model/iso230
// (written from the formats' syntax in data-formats.md A3/B6, not by the writers) read to the
// hand-typed values, the ISO 230-1 squareness sign worked by hand, and the refusals (unknown name,
// repeat, missing column, bad unit, a parameter the model has no place for).
#include <gtest/gtest.h>

#include <string>

#include "expected_value.hpp"
#include "sample_path.hpp"
#include "volcomp/datasets/etalon_exchange.hpp"
#include "volcomp/datasets/isg_csv.hpp"
#include "volcomp/datasets/iso230_set.hpp"
#include "volcomp/datasets/model_file.hpp"

namespace volcomp::datasets {
namespace {

using model::AxisErrorTable;
using model::Vec3;
using testing::SamplePath;
using testing::ValueOf;

struct Row {
  double position_mm;
  Vec3 linear_um;
  Vec3 angular_urad;
};

void ExpectTable(const AxisErrorTable& t, const std::vector<Row>& rows, const char* axis) {
  ASSERT_EQ(t.size(), rows.size()) << axis;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_NEAR(t.position_mm(i), rows[i].position_mm, 1e-12) << axis << i;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(t.row(i).linear_um[k], rows[i].linear_um[k], 1e-9) << axis << i << k;
      EXPECT_NEAR(t.row(i).angular_urad[k], rows[i].angular_urad[k], 1e-9) << axis << i << k;
    }
  }
}

// The numbers of small.etalon / small_isg.csv, typed in µm and µrad.
void ExpectSmallMachine(const model::Model& m) {
  ExpectTable(m.axes[0],
              {{0, {0, 0, 0}, {0, 0, 0}},
               {100, {4, -3, 2}, {5, -20, 20}},  // EYX, EAX, ECX interpolated at EXX's row
               {200, {10, -6, 1}, {10, -30, 40}}},
              "X");
  ExpectTable(m.axes[1],
              {{0, {0, 0, 0}, {0, 0, 0}},
               {75, {1.5, -2, 0.5}, {7.5, -2.5, 12.5}},
               {150, {3, -5, 1}, {15, -5, 25}}},
              "Y");
  ExpectTable(
      m.axes[2],
      {{0, {0, 0, 0}, {0, 0, 0}}, {50, {-1, 0.5, 3}, {-6, 4, 2}}, {100, {-2, 1, 7}, {-12, 8, 4}}},
      "Z");
  EXPECT_NEAR(m.squareness.c0y_urad, 50, 1e-9);
  EXPECT_NEAR(m.squareness.b0z_urad, -20, 1e-9);
  EXPECT_NEAR(m.squareness.a0z_urad, 30, 1e-9);
  EXPECT_EQ(m.chain.ToString(), "|XYZ");
}

TEST(datasets_iso230, EtalonSampleReadsToTheTypedValues) {
  const LoadedModel l = ValueOf(LoadModelFile(SamplePath("model/iso230/small.etalon")));
  EXPECT_EQ(l.format, ModelFileFormat::kEtalon);
  EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
  ExpectSmallMachine(l.model);
}

TEST(datasets_iso230, IsgCsvSampleReadsToTheTypedValues) {
  const LoadedModel l = ValueOf(LoadModelFile(SamplePath("model/iso230/small_isg.csv")));
  EXPECT_EQ(l.format, ModelFileFormat::kIsgCsv);
  EXPECT_TRUE(l.warnings.empty()) << l.warnings.front();
  ExpectSmallMachine(l.model);
}

TEST(datasets_iso230, ContentDecidesTheFormat) {
  EXPECT_EQ(DetectModelFileFormat("// c\n\n[EXX]\n"), ModelFileFormat::kEtalon);
  EXPECT_EQ(DetectModelFileFormat("# c\nbuiltin = s500\n"), ModelFileFormat::kConfig);
  EXPECT_EQ(DetectModelFileFormat("// c\nX EXX\n0 0\n"), ModelFileFormat::kIsgCsv);
  EXPECT_EQ(ValueOf(LoadModelFile(SamplePath("model/s500.conf"))).format, ModelFileFormat::kConfig);
  // Forced: the Etalon file read as ISG-CSV fails at its second line (the first is a header).
  const auto forced =
      LoadModelFile(SamplePath("model/iso230/small.etalon"), ModelFileFormat::kIsgCsv);
  ASSERT_FALSE(forced.ok());
  EXPECT_NE(forced.error().message.find("small.etalon:6: 3 fields, the header (line 5) has 1"),
            std::string::npos)
      << forced.error().message;
}

// ISO 230-1: C0Y is a right-handed rotation of the Y axis about +Z, so +Y leans towards −X:
// at Y = 100 mm with C0Y = +0.001 rad the tool is 100 mm · sin(0.001) = 99.99998 µm at −x.
// EXX = +0.010 mm at X = 50 mm: the tool is 10 µm beyond the command (actual − nominal).
TEST(datasets_iso230, SignsAreIso230OnesAndNoneIsChanged) {
  const std::string text =
      "[EXX]\nGridpoints = {\n 0 0\n 100 0.020\n}\n"
      "[EXY]\nGridpoints = {\n 0 0\n 100 0\n}\n"
      "[EXZ]\nGridpoints = {\n 0 0\n 100 0\n}\n"
      "[C0Y]\nVALUE = 0.001\n";
  const ModelFromIso230 r = ValueOf(ModelFromIso230Set(ValueOf(ParseEtalonExchange(text, "s"))));
  const Vec3 at_x = model::ToolPointError_um(r.model, {50, 0, 0});
  EXPECT_NEAR(at_x.x, 10.0, 1e-9);
  const Vec3 at_y = model::ToolPointError_um(r.model, {0, 100, 0});
  EXPECT_NEAR(at_y.x, -99.99998, 1e-5);
  EXPECT_NEAR(at_y.y, -0.05, 1e-6);  // 100 mm · (cos 0.001 − 1)
  // Every other component error and B0Z, A0Z were missing: named, taken as 0.
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0],
            "s: not in the file, taken as 0: EYX, EZX, EAX, EBX, ECX, EYY, EZY, EAY, EBY, ECY, "
            "EYZ, EZZ, EAZ, EBZ, ECZ, B0Z, A0Z");
}

const char* kAxesOnly =
    "[EXX]\nGridpoints = {\n 0 0\n 100 0\n}\n"
    "[EXY]\nGridpoints = {\n 0 0\n 100 0\n}\n"
    "[EXZ]\nGridpoints = {\n 0 0\n 100 0\n}\n";

std::string EtalonError(const std::string& text) {
  const auto set = ParseEtalonExchange(text, "m.etalon");
  if (!set.ok()) return set.error().message;
  const auto m = ModelFromIso230Set(*set);
  return m.ok() ? "" : m.error().message;
}

std::string IsgError(const std::string& text) {
  const auto set = ParseIsgCsv(text, "m.csv");
  if (!set.ok()) return set.error().message;
  const auto m = ModelFromIso230Set(*set);
  return m.ok() ? "" : m.error().message;
}

TEST(datasets_iso230, EtalonRefusals) {
  EXPECT_EQ(EtalonError(std::string(kAxesOnly) + "[EXQ]\nVALUE = 0\n"),
            "m.etalon:16: unknown parameter \"EXQ\" (ISO 230-1 names: E<err><axis> such as EXX, "
            "ECY; <err>0<axis> such as C0Y; err and axis one of X Y Z A B C)");
  EXPECT_EQ(EtalonError(std::string(kAxesOnly) + "[exx]\nVALUE = 0\n"),
            "m.etalon:16: parameter EXX repeats (first on line 1)");
  EXPECT_EQ(EtalonError("[EXX]\nGridpoints = {\n 0 0\n 100 12.5\n}\n"),
            "m.etalon:1: EXX = 12.5 mm is beyond the plausible 1 mm: the file must hold mm (a "
            "file in µm is not read; divide by 1000)");
  EXPECT_EQ(EtalonError(std::string(kAxesOnly) + "[C0Y]\nVALUE = 25\n"),
            "m.etalon:16: C0Y = 25 rad is beyond the plausible 0.01 rad: the file must hold rad "
            "(a file in µrad, mrad or arcsec is not read; convert it)");
  EXPECT_EQ(EtalonError("[EXX]\nGridpoints = {\n 0 0\n 100\n}\n"),
            "m.etalon:5: the Gridpoints of EXX end with an argument without its value (pairs "
            "`argument value`)");
  EXPECT_EQ(EtalonError("[EXX]\nGridpoints = {\n 0 0\n"),
            "m.etalon:2: the Gridpoints of EXX are not closed by }");
  EXPECT_EQ(EtalonError("[EXX]\nVALUE = 0.1\nGridpoints = {\n}\n"),
            "m.etalon:3: EXX has a value already (one VALUE or one Gridpoints per block)");
  EXPECT_EQ(EtalonError("[EXX]\nVALUE = 1 mm\n"), "m.etalon:2: VALUE: \"1 mm\" is not a number");
  EXPECT_EQ(EtalonError("VALUE = 1\n"), "m.etalon:1: \"VALUE = 1\" is outside a [PARAMETER] block");
  EXPECT_EQ(EtalonError("[EXX]\nOFFSET = 1\n"),
            "m.etalon:2: unknown key \"OFFSET\" (VALUE or Gridpoints)");
  EXPECT_EQ(EtalonError("[EXX]\n[EYX]\nVALUE = 0\n"),
            "m.etalon:1: [EXX] has neither VALUE nor Gridpoints");
  EXPECT_EQ(EtalonError("// nothing\n"), "m.etalon: no [PARAMETER] block");
  EXPECT_EQ(EtalonError("[EXX]\nGridpoints = {\n 100 0\n 0 0\n}\n"),
            "m.etalon:1: EXX: the arguments must increase, 0 follows 100");
}

TEST(datasets_iso230, AxisWithoutTableIsRefused) {
  EXPECT_EQ(
      EtalonError("[EXX]\nGridpoints = {\n 0 0\n 1 0\n}\n[EXY]\nVALUE = 0\n"),
      "m.etalon: no table of a component error of Y (EXY, EYY, EZY, ... with at least 2 rows): "
      "the model needs the axis's range");
}

TEST(datasets_iso230, ParametersOutsideTheModel) {
  // The manual's example block [C0B] (a rotary axis) with a value: refused, not dropped.
  EXPECT_EQ(EtalonError(std::string(kAxesOnly) + "[C0B]\nVALUE = 0.000022355737\n"),
            "m.etalon:16: C0B is not zero, and the 21-parameter model (X, Y, Z component "
            "errors, C0Y, B0Z, A0Z) has no place for it: refused rather than dropped");
  EXPECT_NE(EtalonError(std::string(kAxesOnly) + "[EXA]\nGridpoints = {\n 0 0\n 90 0.001\n}\n")
                .find("EXA is not zero"),
            std::string::npos);
  // Zero throughout: ignored with a warning naming it.
  const auto set = ValueOf(ParseEtalonExchange(std::string(kAxesOnly) + "[P0X]\nVALUE = 0\n", "z"));
  const ModelFromIso230 r = ValueOf(ModelFromIso230Set(set));
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(r.warnings[0],
            "z:16: P0X is zero throughout and not part of the 21-parameter model: "
            "ignored");
}

TEST(datasets_iso230, IsgCsvRefusals) {
  EXPECT_EQ(IsgError("X EXX EYX\n0 0 0\n100 0.01\n"),
            "m.csv:3: 2 fields, the header (line 1) has 3");
  EXPECT_EQ(IsgError("EXX EYX\n0 0\n100 0.01\n"),
            "m.csv:1: a block without an argument column holds one row of values, this one 2");
  EXPECT_EQ(IsgError("X Y EXX\n0 0 0\n"),
            "m.csv:1: a block over several arguments (X, Y) is a volumetric grid, not a "
            "21-parameter set: each component error depends on its own axis only");
  EXPECT_EQ(IsgError("X EXY\n0 0\n100 0\n"),
            "m.csv:1: EXY is a function of Y, but its argument is X");
  EXPECT_EQ(IsgError("X C0Y\n0 0\n100 0\n"),
            "m.csv:1: C0Y is a position error: one value, not a table");
  EXPECT_EQ(IsgError("X POS_ERR\n0 0\n"),
            "m.csv:1: unknown parameter \"POS_ERR\" (ISO 230-1 names: E<err><axis> such as EXX, "
            "ECY; <err>0<axis> such as C0Y; err and axis one of X Y Z A B C)");
  EXPECT_EQ(IsgError("X EXX\n0 0\n100 4.0\n"),
            "m.csv:1: EXX = 4 mm is beyond the plausible 1 mm: the file must hold mm (a file in "
            "µm is not read; divide by 1000)");
  EXPECT_EQ(IsgError("X EXX\n0 0\n100 0,004\n"), "m.csv:3: EXX: \"0,004\" is not a number");
  EXPECT_EQ(IsgError("X EXX\n0 0\n#\nX EXX\n0 0\n"),
            "m.csv:4: parameter EXX repeats (first on line 1)");
  EXPECT_EQ(IsgError("X EXX\n#\n"), "m.csv:1: the block has a header and no rows");
  EXPECT_EQ(IsgError("X\n0\n"), "m.csv:1: the header names no parameter after the argument X");
}

}  // namespace
}  // namespace volcomp::datasets
