// Model config files: the shipped sample equals the built-in model, overrides apply, and bad input
// gives file:line failures.
#include "volcomp/datasets/model_config.hpp"

#include <gtest/gtest.h>

#include <string>

#include "expected_value.hpp"
#include "sample_path.hpp"
#include "volcomp/datasets/s500.hpp"

namespace volcomp::datasets {
namespace {

using model::Model;
using model::Vec3;
using testing::SamplePath;
using testing::ValueOf;

// The failure's message (kInputInvalid), or "" when the config was read.
std::string ErrorOf(const std::string& text) {
  const auto m = ModelFromConfigText(text, "m.conf", ".");
  if (m.ok()) return "";
  EXPECT_EQ(m.error().code, Error::kInputInvalid) << m.error().message;
  return m.error().message;
}

TEST(datasets_model_config, SampleConfigEqualsTheBuiltInModel) {
  const Model f = ValueOf(LoadModelConfig(SamplePath("model/s500.conf")));
  const Model b = S500Model();
  EXPECT_EQ(f.squareness.c0y_urad, b.squareness.c0y_urad);
  EXPECT_EQ(f.squareness.b0z_urad, b.squareness.b0z_urad);
  EXPECT_EQ(f.squareness.a0z_urad, b.squareness.a0z_urad);
  EXPECT_EQ(f.chain.ToString(), b.chain.ToString());
  EXPECT_EQ(f.order, b.order);
  for (const Vec3& p : {Vec3{0, 0, 0}, Vec3{123, 45, 67}, Vec3{400, 280, 200}}) {
    EXPECT_NEAR(Norm(ToolPointError_um(f, p) - ToolPointError_um(b, p)), 0.0, 1e-9);
  }
}

TEST(datasets_model_config, ErrorsNameLineAndProblem) {
  EXPECT_EQ(ErrorOf("builtin = s500\n\nsquareness_c0y_urad = abc\n"),
            "m.conf:3: squareness_c0y_urad: \"abc\" is not a number");
  EXPECT_EQ(ErrorOf("builtin = s500\ncolour = red\n"), "m.conf:2: unknown key \"colour\"");
  EXPECT_EQ(ErrorOf("builtin = s500\norder = first\norder = exact\n"),
            "m.conf:3: key \"order\" repeats line 2");
  EXPECT_EQ(ErrorOf("builtin = s500\ntool_axes = XYZX\n"), "m.conf:2: chain: axis X appears twice");
  EXPECT_EQ(ErrorOf("builtin = s500\ntool_offset_mm = 1, 2\n"),
            "m.conf:2: tool_offset_mm needs three numbers: X, Y, Z");
  EXPECT_EQ(ErrorOf("name = nothing\n"),
            "m.conf: no table for axis X (key axis_x or builtin = s500)");
  EXPECT_EQ(ErrorOf("just words\n"), "m.conf:1: expected `key = value`, got \"just words\"");
  const auto missing_table = ModelFromConfigText("axis_x = /nonexistent/x.csv\n", "m.conf", ".");
  ASSERT_FALSE(missing_table.ok());
  EXPECT_EQ(missing_table.error().code, Error::kIoError);
  EXPECT_EQ(missing_table.error().message, "/nonexistent/x.csv: cannot open");
  const auto missing = LoadModelConfig("/nonexistent.conf");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().code, Error::kIoError);
  EXPECT_EQ(missing.error().message, "/nonexistent.conf: cannot open the model config");
}

TEST(datasets_model_config, OverridesOfTheBuiltInModel) {
  const Model m = ValueOf(ModelFromConfigText(
      "builtin = s500\norder = first\ntool_offset_mm = 0, 0, 100\nworkpiece_axes = Y\n"
      "tool_axes = XZ\n",
      "m.conf", "."));
  EXPECT_EQ(m.order, model::Order::kFirst);
  EXPECT_EQ(m.tool_offset_mm.z, 100);
  EXPECT_EQ(m.chain.ToString(), "Y|XZ");
}

}  // namespace
}  // namespace volcomp::datasets
