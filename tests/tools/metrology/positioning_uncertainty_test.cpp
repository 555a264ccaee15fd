// The simplified positioning budget against the worked example of
// ../shared/reference/thermal-rotary-uncertainty.md §3.2 (L = 1 m, steel): device ±0.5 ppm → 0.6,
// thermometer R_T 0.2 K → 1.4, expansion coefficient R_α 2 at 23 °C → 3.6 (0.6 at 20.5 °C),
// walk-off 0.5 mm → 0.07, drift test 2 µm → 1.2; U(E) 4.1 at 23 °C and 2.0 at 20.5 °C.
#include "volcomp/metrology/positioning_uncertainty.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;

PositioningUncertaintyInputs DigestExample(double material_C) {
  PositioningUncertaintyInputs in;
  in.instrument_ppm = 0.5;
  in.material_temperature_C = material_C;
  in.thermometer_range_K = 0.2;
  in.expansion_um_per_m_K = 11.5;
  in.expansion_range_um_per_m_K = 2.0;
  in.misalignment_mm = 0.5;
  in.drift_range_um = 2.0;
  return in;
}

double Term(const PositioningUncertainty& u, const std::string& name) {
  for (const auto& t : u.terms) {
    if (t.name == name) return t.u;
  }
  ADD_FAILURE() << "no term " << name;
  return -1.0;
}

TEST(PositioningUncertainty, TheDigestsWorkedExample) {
  const auto u = ValueOf(PositioningU(DigestExample(23.0), 1000.0));
  EXPECT_NEAR(Term(u, "instrument"), 0.6, 1e-12);
  EXPECT_NEAR(Term(u, "thermometer"), 1.38, 1e-12);
  EXPECT_NEAR(Term(u, "expansion coefficient"), 3.6, 1e-12);
  EXPECT_NEAR(Term(u, "misalignment"), 0.075, 1e-12);
  EXPECT_NEAR(Term(u, "environment"), 1.2, 1e-12);
  EXPECT_NEAR(u.span_u, 4.1, 0.05);    // printed to one decimal
  EXPECT_NEAR(u.local_u, 1.2, 1e-12);  // no calibration U: the drift alone
  EXPECT_TRUE(u.notes.empty());
  EXPECT_NEAR(ValueOf(PositioningU(DigestExample(20.5), 1000.0)).span_u, 2.0, 0.05);
}

TEST(PositioningUncertainty, WhatIsNotStatedIsNamed) {
  PositioningUncertaintyInputs in;
  in.instrument_u_um = 0.3;
  const auto u = ValueOf(PositioningU(in, 500.0));
  // Instrument 0.3; thermometer 0.6 × 11.5 × 0.5 × 0.2 = 0.69; nothing else.
  EXPECT_NEAR(u.span_u, std::hypot(0.3, 0.69), 1e-12);
  EXPECT_NEAR(u.local_u, 0.3, 1e-12);
  ASSERT_EQ(u.notes.size(), 3u);
  EXPECT_NE(u.notes[0].find("steel's 11.5"), std::string::npos);
  EXPECT_NE(u.notes[1].find("material temperature not stated"), std::string::npos);
  EXPECT_NE(u.notes[2].find("no drift test"), std::string::npos);
}

TEST(PositioningUncertainty, RefusesWhatItCannotUse) {
  ExpectFailure(PositioningU({}, 100.0), Error::kInvalidArgument, {"needs the instrument"});
  PositioningUncertaintyInputs in;
  in.instrument_u_um = 0.1;
  in.misalignment_mm = -1.0;
  ExpectFailure(PositioningU(in, 100.0), Error::kInvalidArgument, {"not negative"});
  in.misalignment_mm = 0.0;
  ExpectFailure(PositioningU(in, 0.0), Error::kInvalidArgument, {"length > 0"});
}

// A rotary axis against an angle reference (XR20-type, stated ±1″, certificate U 0.5″) with a
// 2″ drift test, by hand: device √(0.5² + (0.6 × 2 × 1)²) = √(0.25 + 1.44) = 1.3″;
// environment 0.6 × 2 = 1.2″; U = √(1.69 + 1.44) = √3.13 ≈ 1.769″ for E, A, M and B alike.
TEST(PositioningUncertainty, RotaryAxisAgainstAnAngleReference) {
  PositioningUncertaintyInputs in;
  in.instrument_u_arcsec = 0.5;
  in.instrument_accuracy_arcsec = 1.0;
  in.drift_range_arcsec = 2.0;
  const auto u = ValueOf(AngularPositioningU(in, 330.0));
  EXPECT_EQ(u.kind, AxisKind::kRotary);
  EXPECT_NEAR(Term(u, "instrument"), 1.3, 1e-12);
  EXPECT_NEAR(Term(u, "environment"), 1.2, 1e-12);
  EXPECT_EQ(Term(u, "thermometer"), 0.0);  // an angle does not scale with expansion
  EXPECT_EQ(Term(u, "expansion coefficient"), 0.0);
  EXPECT_NEAR(u.span_u, std::sqrt(3.13), 1e-12);
  EXPECT_NEAR(u.local_u, std::sqrt(3.13), 1e-12);
  EXPECT_NEAR(u.span, 330.0, 0.0);
  EXPECT_TRUE(u.notes.empty());
  ExpectFailure(AngularPositioningU({}, 330.0), Error::kInvalidArgument, {"angle reference"});
  in.drift_range_arcsec = -1.0;
  ExpectFailure(AngularPositioningU(in, 330.0), Error::kInvalidArgument, {"not negative"});
}

TEST(PositioningUncertainty, InputsOfTheOtherAxisKindAreNamed) {
  PositioningUncertaintyInputs in;
  in.instrument_u_um = 0.3;
  std::vector<std::string> warnings;
  const auto none = ValueOf(AxisUncertainty(in, AxisKind::kRotary, 360.0, &warnings));
  EXPECT_FALSE(none.has_value());
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("do not apply to a rotary axis"), std::string::npos);
  EXPECT_NE(warnings[1].find("state the angle reference"), std::string::npos);
  warnings.clear();
  in.drift_range_arcsec = 1.0;
  const auto linear = ValueOf(AxisUncertainty(in, AxisKind::kLinear, 500.0, &warnings));
  ASSERT_TRUE(linear.has_value());
  EXPECT_EQ(linear->kind, AxisKind::kLinear);
  EXPECT_NE(warnings[0].find("do not apply to a linear axis"), std::string::npos);
}

}  // namespace
}  // namespace volcomp::metrology
