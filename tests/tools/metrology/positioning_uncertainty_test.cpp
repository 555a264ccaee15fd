// The simplified positioning budget against the worked example of
// ../shared/reference/thermal-rotary-uncertainty.md §3.2 (L = 1 m, steel): device ±0.5 ppm → 0.6,
// thermometer R_T 0.2 K → 1.4, expansion coefficient R_α 2 at 23 °C → 3.6 (0.6 at 20.5 °C),
// walk-off 0.5 mm → 0.07, drift test 2 µm → 1.2; U(E) 4.1 at 23 °C and 2.0 at 20.5 °C.
#include "volcomp/metrology/positioning_uncertainty.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

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
    if (t.name == name) return t.u_um;
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
  EXPECT_NEAR(u.length_u_um, 4.1, 0.05);  // printed to one decimal
  EXPECT_NEAR(u.local_u_um, 1.2, 1e-12);  // no calibration U: the drift alone
  EXPECT_TRUE(u.notes.empty());
  EXPECT_NEAR(ValueOf(PositioningU(DigestExample(20.5), 1000.0)).length_u_um, 2.0, 0.05);
}

TEST(PositioningUncertainty, WhatIsNotStatedIsNamed) {
  PositioningUncertaintyInputs in;
  in.instrument_u_um = 0.3;
  const auto u = ValueOf(PositioningU(in, 500.0));
  // Instrument 0.3; thermometer 0.6 × 11.5 × 0.5 × 0.2 = 0.69; nothing else.
  EXPECT_NEAR(u.length_u_um, std::hypot(0.3, 0.69), 1e-12);
  EXPECT_NEAR(u.local_u_um, 0.3, 1e-12);
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

}  // namespace
}  // namespace volcomp::metrology
