// The unit plausibility check of the positioning loader: a µm deviation column whose values are
// all below 0.1 µm in magnitude (not all zero) is mm typed as µm and refused, naming the column,
// the largest value and the fix, unless accepted; CSV readings, CSV means and .rtl alike; a µin
// column (inches typed as µin) against the same 0.1 µm.
#include <gtest/gtest.h>

#include <string>

#include "expected_value.hpp"
#include "volcomp/datasets/positioning_file.hpp"

namespace volcomp::datasets {
namespace {

using testing::ValueOf;

// 12 µm and −13 µm typed in mm under deviation_um (line 5 holds the largest magnitude).
const std::string kMmAsUm =
    "target_mm,direction,run,deviation_um\n0,up,1,0.002\n100,up,1,0.012\n0,up,2,0.003\n"
    "100,up,2,-0.013\n";

std::string ErrorOf(const std::string& text, const std::string& source) {
  const auto r = ReadPositioningText(text, source);
  return r.ok() ? "(accepted)" : r.error().message;
}

TEST(datasets_unit_check, CsvReadingsInMmUnderAMicrometreColumnAreRefused) {
  EXPECT_EQ(ErrorOf(kMmAsUm, "p.csv"),
            "p.csv:1: column \"deviation_um\": every value is below 0.1 µm in magnitude (the "
            "largest is -0.013 µm on line 5): these look like mm typed as µm; if they are mm, name "
            "the column deviation_mm, or give --accept-units if the axis really is this good");
  PositioningReadOptions accept;
  accept.accept_units = true;
  const PositioningFile f = ValueOf(ReadPositioningText(kMmAsUm, "p.csv", accept));
  EXPECT_EQ(f.readings->readings.size(), 4u);
  // The same numbers under their own unit: 2..13 µm, plausible.
  std::string as_mm = kMmAsUm;
  as_mm.replace(as_mm.find("deviation_um"), 12, "deviation_mm");
  EXPECT_EQ(ErrorOf(as_mm, "p.csv"), "(accepted)");
}

TEST(datasets_unit_check, ZeroColumnAndOneTenthAreNotRefused) {
  EXPECT_EQ(ErrorOf("target_mm,direction,run,deviation_um\n0,up,1,0\n100,up,1,0\n", "z.csv"),
            "(accepted)");
  EXPECT_EQ(ErrorOf("target_mm,direction,run,deviation_um\n0,up,1,0.01\n100,up,1,-0.1\n", "b.csv"),
            "(accepted)");
}

TEST(datasets_unit_check, CsvMeansAreChecked) {
  const std::string e =
      ErrorOf("position_mm,dev_forward_um,dev_reverse_um\n0,1.5,0.004\n100,2.5,0.008\n", "m.csv");
  EXPECT_EQ(e.rfind("m.csv:1: column \"dev_reverse_um\": every value is below 0.1 µm", 0), 0u) << e;
  EXPECT_NE(e.find("the largest is 0.008 µm)"), std::string::npos) << e;
  EXPECT_NE(e.find("multiply them by 1000"), std::string::npos) << e;
  // Rotary means are in arc-seconds: not this check's business.
  EXPECT_EQ(ErrorOf("position_deg,dev_forward_arcsec\n0,0.01\n90,0.02\n", "r.csv"), "(accepted)");
}

// An inch machine's means: checked in their own µin (0.1 µm = 3.94 µin), named by their column.
TEST(datasets_unit_check, InchMeansAreCheckedInMicroinches) {
  const std::string e =
      ErrorOf("position_in,dev_forward_uin,dev_reverse_uin\n0,0.0002,120\n2,0.0004,80\n", "i.csv");
  EXPECT_EQ(e.rfind("i.csv:1: column \"dev_forward_uin\"", 0), 0u) << e;
  EXPECT_NE(e.find("the largest is 0.0004 µin"), std::string::npos) << e;
  EXPECT_NE(e.find("multiply them by 1000000"), std::string::npos) << e;
  EXPECT_EQ(ErrorOf("position_in,dev_forward_uin\n0,4\n2,-6\n", "i.csv"), "(accepted)");
}

TEST(datasets_unit_check, RtlDeviationsAreChecked) {
  const std::string rtl =
      "HEADER::\nTARGET DATA::\nTarget-count: 2\nTargets :\n0 100\nRUNS::\nRun-count: 1\n"
      "DEVIATIONS::\n1 1 0.004\n1 2 0.009\n";
  const std::string e = ErrorOf(rtl, "t.rtl");
  EXPECT_EQ(e.rfind("t.rtl:8: column \"DEVIATIONS\": every value is below 0.1 µm in magnitude "
                    "(the largest is 0.009 µm on line 10)",
                    0),
            0u)
      << e;
  EXPECT_NE(e.find("an .rtl holds µm"), std::string::npos) << e;
}

// A µin column gets the same physical threshold, 0.1 µm = 0.1/0.0254 = 3.93701 µin. Inches typed
// as µin (10 µm = 0.0004 in written as 0.0004 µin) lie far below it.
TEST(datasets_unit_check, InchesTypedAsMicroinchesAreRefused) {
  const std::string rtl =
      "HEADER::\nTARGET DATA::\nTarget-count: 2\nTargets :\n0 4\nRUNS::\nRun-count: 1\n"
      "DEVIATIONS::\n1 1 0.0004\n1 2 -0.0003\n";
  PositioningReadOptions in;
  in.rtl.units = RtlUnits::kIn;
  const auto r = ReadPositioningText(rtl, "t.rtl", in);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message,
            "t.rtl:8: column \"DEVIATIONS\": every value is below 0.1 µm (3.93701 µin) in "
            "magnitude (the largest is 0.0004 µin on line 9): these look like inches typed as µin; "
            "an .rtl read with --rtl-units in holds µin, so check the test in the laser software, "
            "or give --accept-units if the axis really is this good");
  in.accept_units = true;
  EXPECT_TRUE(ReadPositioningText(rtl, "t.rtl", in).ok());
  // 4 µin = 0.1016 µm: at the threshold's edge, plausible.
  std::string four = rtl;
  four.replace(four.find("0.0004"), 6, "4");
  in.accept_units = false;
  EXPECT_TRUE(ReadPositioningText(four, "t.rtl", in).ok());
  // The CSV's µin column alike.
  const std::string e =
      ErrorOf("target_in,direction,run,deviation_uin\n0,up,1,0.0002\n4,up,1,-0.0005\n", "i.csv");
  EXPECT_EQ(e.rfind("i.csv:1: column \"deviation_uin\": every value is below 0.1 µm (3.93701 "
                    "µin) in magnitude (the largest is -0.0005 µin on line 3)",
                    0),
            0u)
      << e;
  EXPECT_NE(e.find("if they are inches, name the column deviation_in"), std::string::npos) << e;
}

}  // namespace
}  // namespace volcomp::datasets
