// ISO 230-7 Annex F: the expanded uncertainties worked by hand from the formulas F.1–F.7.
#include "volcomp/metrology/error_motion_uncertainty.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"

namespace volcomp::metrology {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;

// A capacitive probe with a 0.05 µm calibration U, a 0.12 µm setup U, a 0.5 µm drift test range
// and 20 revolutions: U_DEVICE = sqrt(0.05² + 0.12²) = 0.13; U_EVE = 0.3;
// U_single = sqrt(0.13² + 0.3²) = sqrt(0.1069) = 0.326956; U_sync = sqrt(0.0169 + 0.09/20) =
// sqrt(0.0214) = 0.146287; values: 1.4 × those = 0.457738 and 0.204802.
TEST(ErrorMotionUncertainty, HandWorkedCalibratedProbe) {
  ErrorMotionUncertaintyInputs in;
  in.device_calibration_um = 0.05;
  in.setup_um = 0.12;
  in.drift_range_um = 0.5;
  const auto u = ValueOf(ErrorMotionU(in, 20, 1.0));
  EXPECT_TRUE(u.from_calibration);
  EXPECT_NEAR(u.device, 0.13, 1e-12);
  EXPECT_NEAR(u.eve, 0.3, 1e-12);
  EXPECT_NEAR(u.single_plot, 0.326956, 1e-6);
  EXPECT_NEAR(u.synchronous_plot, 0.146287, 1e-6);
  EXPECT_NEAR(u.single_value, 0.457738, 1e-6);
  EXPECT_NEAR(u.synchronous_value, 0.204802, 1e-6);
}

// F.2 with a maker's range of 0.5 µm: U_DEVICE = 0.3; no drift test: U_EVE = 0, so every plot
// has U = 0.3 and every value 0.42. The printed F.6 then gives 0.3 for a single-plot value.
TEST(ErrorMotionUncertainty, MakersRangeWithoutDriftTestAndTheLiteralF6) {
  ErrorMotionUncertaintyInputs in;
  in.device_range_um = 0.5;
  auto u = ValueOf(ErrorMotionU(in, 8, 1.0));
  EXPECT_FALSE(u.from_calibration);
  EXPECT_FALSE(u.drift_stated);
  EXPECT_NEAR(u.single_value, 0.42, 1e-12);
  EXPECT_NEAR(u.synchronous_value, 0.42, 1e-12);
  in.literal_f6 = true;
  in.drift_range_um = 1.0;  // U_EVE 0.6; U_single = sqrt(0.09 + 0.36) = 0.670820
  u = ValueOf(ErrorMotionU(in, 4, 1.0));
  EXPECT_NEAR(u.single_value, std::sqrt(0.45 + 0.36 / 4), 1e-12);  // F.6 as printed
  EXPECT_NEAR(u.synchronous_value, 1.4 * std::sqrt(0.09 + 0.36 / 4), 1e-12);
}

// Tilt from two sensors 80 mm apart: every µm term scales by √2·1000/80 into µrad.
TEST(ErrorMotionUncertainty, ScalesIntoTheMeasurementsUnit) {
  ErrorMotionUncertaintyInputs in;
  in.device_calibration_um = 0.1;
  const double s = std::sqrt(2.0) * 1000.0 / 80.0;
  const auto u = ValueOf(ErrorMotionU(in, 10, s));
  EXPECT_NEAR(u.device, 0.1 * s, 1e-12);
  EXPECT_NEAR(u.synchronous_value, 1.4 * 0.1 * s, 1e-12);
}

TEST(ErrorMotionUncertainty, RefusesWhatItCannotUse) {
  ErrorMotionUncertaintyInputs in;
  ExpectFailure(ErrorMotionU(in, 8, 1.0), Error::kInvalidArgument, {"needs the instrument"});
  in.device_calibration_um = 0.1;
  in.device_range_um = 0.2;
  ExpectFailure(ErrorMotionU(in, 8, 1.0), Error::kInvalidArgument, {"not both"});
  in.device_range_um.reset();
  in.drift_range_um = -1.0;
  ExpectFailure(ErrorMotionU(in, 8, 1.0), Error::kInvalidArgument, {"not negative"});
  in.drift_range_um = 0.1;
  ExpectFailure(ErrorMotionU(in, 0, 1.0), Error::kInvalidArgument, {"n >= 1"});
}

}  // namespace
}  // namespace volcomp::metrology
