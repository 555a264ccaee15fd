// The circular test's budget (circular_uncertainty.hpp) worked by hand: reading U 0.4 µm, drift
// 0.5 µm, calibrator U 0.3 µm, R = 150 mm at 20 °C (no expansion-coefficient term), steel.
//   G, G(b), H: √(0.4² + (0.6 × 0.5)²) = √(0.16 + 0.09) = 0.5
//   F: instrument √(0.16 + 0.09) = 0.5, thermometer 0.6 × 11.5 × 0.15 × 0.2 = 0.207,
//      expansion coefficient 0, environment 0.3: √(0.25 + 0.042849 + 0.09) = √0.382849
#include "volcomp/metrology/circular_uncertainty.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;

CircularUncertaintyInputs Example() {
  CircularUncertaintyInputs in;
  in.reading.instrument_u_um = 0.4;
  in.reading.drift_range_um = 0.5;
  in.reading.material_temperature_C = 20.0;
  in.reading.expansion_um_per_m_K = 11.5;
  in.calibrator_u_um = 0.3;
  return in;
}

TEST(CircularUncertainty, ShapeAndRadialFiguresByHand) {
  std::vector<std::string> warnings;
  const auto u = ValueOf(CircularU(Example(), 150.0, &warnings));
  ASSERT_TRUE(u.has_value());
  EXPECT_NEAR(u->shape_u_um, 0.5, 1e-12);
  ASSERT_TRUE(u->radial.has_value());
  EXPECT_NEAR(u->radial->span_u, std::sqrt(0.382849), 1e-12);
  for (const auto& t : u->radial->terms) EXPECT_NE(t.name, "misalignment");
  EXPECT_TRUE(warnings.empty());
}

TEST(CircularUncertainty, WithoutARadiusFHasNoU) {
  std::vector<std::string> warnings;
  const auto u = ValueOf(CircularU(Example(), 0.0, &warnings));
  ASSERT_TRUE(u.has_value());
  EXPECT_NEAR(u->shape_u_um, 0.5, 1e-12);
  EXPECT_FALSE(u->radial.has_value());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("F has no U"), std::string::npos);
}

TEST(CircularUncertainty, Refusals) {
  std::vector<std::string> warnings;
  CircularUncertaintyInputs in = Example();
  in.calibrator_u_um = -0.1;
  ExpectFailure(CircularU(in, 150.0, &warnings), Error::kInvalidArgument, {"calibrator"});
  in = Example();
  in.reading.misalignment_mm = 1.0;
  ExpectFailure(CircularU(in, 150.0, &warnings), Error::kInvalidArgument, {"does not apply"});
  in = Example();
  in.reading.drift_range_um = -1.0;
  ExpectFailure(CircularU(in, 150.0, &warnings), Error::kInvalidArgument, {"not negative"});
}

}  // namespace
}  // namespace volcomp::metrology
