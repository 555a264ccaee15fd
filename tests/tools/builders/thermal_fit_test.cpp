// The least-squares fit of the thermal model (builders/thermal_fit.hpp): a hand-worked exactly
// determined case (and its sign: a drift of +d is a correction of -d), exact recovery of known
// coefficients from drifts generated here by the model's formula, noise left as the residual,
// the refusals (collinear channels, a channel that does not change, a coefficient beyond the
// bound, unknown channels) and the image's model (channel numbers, ranges, axes by name).
#include "volcomp/builders/thermal_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "expected_value.hpp"

namespace volcomp::builders {
namespace {

using testing::ExpectFailure;
using testing::ValueOf;

metrology::DriftRecord Read(const std::string& text) {
  return ValueOf(metrology::ReadDriftCsv(ValueOf(tools::CsvTable::ReadString(text, "d.csv"))));
}

// X at 0 and 100 mm (p0 = 50, x = -0.05 and +0.05 m), channel "a" from 20 to 22 °C; drift +3 µm
// at 0 mm and +5 µm at 100 mm. Two equations, two unknowns:
//   -3 = 2·O + 2·S·(-0.05)     -5 = 2·O + 2·S·(+0.05)
//   sum: -8 = 4·O  → O = -2 µm/K;   difference: -2 = 0.2·S  → S = -10 µm/(K·m).
const char* const kHandCase =
    "time_s,axis,position_mm,deviation_um,T_a_C\n"
    "0,X,0,1.0,20\n"
    "10,X,100,-2.0,20\n"
    "3600,X,0,4.0,22\n"
    "3610,X,100,3.0,22\n";

TEST(ThermalFit, HandWorkedCaseAndItsSign) {
  const ThermalFit fit = ValueOf(FitThermalModel(Read(kHandCase), {}));
  ASSERT_EQ(fit.channels.size(), 1u);
  EXPECT_EQ(fit.channels[0].name, "a");
  EXPECT_DOUBLE_EQ(fit.channels[0].reference_C, 20.0);  // the first reading
  EXPECT_FALSE(fit.channels[0].reference_given);
  ASSERT_EQ(fit.axes.size(), 1u);
  const ThermalAxisFit& x = fit.axes[0];
  EXPECT_DOUBLE_EQ(x.p0_mm, 50);
  EXPECT_DOUBLE_EQ(x.reach_mm, 50);
  EXPECT_EQ(x.samples, 2u);
  EXPECT_NEAR(x.offset_um_per_K[0], -2.0, 1e-12);
  EXPECT_NEAR(x.slope_um_per_K_m[0], -10.0, 1e-12);
  EXPECT_NEAR(x.residual_rms_um, 0.0, 1e-12);
  EXPECT_NEAR(x.explained, 1.0, 1e-12);
  EXPECT_NEAR(x.drift_rms_um, std::sqrt((9.0 + 25.0) / 2), 1e-12);
  // The correction at 0 mm after the +2 K: -2·2 + (-10)·2·(-50)/1000 = -3 = -(the drift +3).
  EXPECT_NEAR(x.offset_um_per_K[0] * 2 + x.slope_um_per_K_m[0] * 2 * (0 - 50) / 1000, -3.0, 1e-12);
}

// Drifts generated from known coefficients with the model's formula, written here independently:
// drift = -(Σ_j O_j·ΔT_j + Σ_j S_j·ΔT_j·(p - p0)/1000), ΔT from each point's first reading.
struct Truth {
  double offset[2];
  double slope[2];
};

std::string SyntheticTest(const Truth& x, double noise_um) {
  std::ostringstream s;
  s.precision(15);
  s << "time_s,axis,position_mm,deviation_um,T_one_C,T_two_C\n";
  const double positions[3] = {100, 400, 700};  // p0 = 400
  unsigned lcg = 12345;
  auto noise = [&]() {  // uniform in [-noise, +noise]
    lcg = lcg * 1103515245u + 12345u;
    return noise_um * (2.0 * ((lcg >> 8) & 0xFFFF) / 65535.0 - 1.0);
  };
  for (int k = 0; k < 40; ++k) {
    for (int i = 0; i < 3; ++i) {
      const double t = 600.0 * k + 20.0 * i;
      const double h = t / 3600.0;
      const double t1 = 20 + 6 * (1 - std::exp(-h / 0.7));     // fast channel
      const double t2 = 20 + 2 * h + 0.5 * std::sin(h * 2.0);  // slow, wavy channel
      const double dt[2] = {t1 - 20, t2 - 20};  // every point's first reading is at k = 0, ~20 °C
      // The first readings are not exactly at 20 °C (i > 0 is 20 s later): use them as the base.
      const double h0 = 20.0 * i / 3600.0;
      const double base[2] = {6 * (1 - std::exp(-h0 / 0.7)), 2 * h0 + 0.5 * std::sin(h0 * 2.0)};
      const double xm = (positions[i] - 400) / 1000;
      double c = 0;
      for (int j = 0; j < 2; ++j) c += (x.offset[j] + x.slope[j] * xm) * (dt[j] - base[j]);
      const double geometric = 1.5 * i;  // the point's own deviation, removed by the drift
      s << t << ",Z," << positions[i] << "," << geometric - c + (k ? noise() : 0.0) << "," << t1
        << "," << t2 << "\n";
    }
  }
  return s.str();
}

TEST(ThermalFit, RecoversKnownCoefficientsExactly) {
  const Truth truth{{-2.5, 0.75}, {-11.5, 4.0}};
  const ThermalFit fit = ValueOf(FitThermalModel(Read(SyntheticTest(truth, 0.0)), {}));
  const ThermalAxisFit& z = fit.axes[0];
  EXPECT_DOUBLE_EQ(z.p0_mm, 400);
  EXPECT_DOUBLE_EQ(z.reach_mm, 300);
  EXPECT_EQ(z.samples, 3u * 39u);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(z.offset_um_per_K[j], truth.offset[j], 1e-8) << j;
    EXPECT_NEAR(z.slope_um_per_K_m[j], truth.slope[j], 1e-7) << j;
  }
  EXPECT_LT(z.residual_max_um, 1e-9);
  EXPECT_GT(z.condition, 1.0);
  EXPECT_LT(z.condition, kDefaultMaxCondition);
}

TEST(ThermalFit, NoiseIsLeftAsTheResidual) {
  const Truth truth{{-2.5, 0.75}, {-11.5, 4.0}};
  const double a = 0.2;  // uniform noise ±0.2 µm: RMS 0.2/√3 = 0.115 µm
  const ThermalFit fit = ValueOf(FitThermalModel(Read(SyntheticTest(truth, a)), {}));
  const ThermalAxisFit& z = fit.axes[0];
  EXPECT_GT(z.residual_rms_um, 0.8 * a / std::sqrt(3.0));
  EXPECT_LT(z.residual_rms_um, 1.1 * a / std::sqrt(3.0));
  EXPECT_LE(z.residual_max_um, 2 * a);  // the noise of two readings (the first has none)
  EXPECT_NEAR(z.offset_um_per_K[0], truth.offset[0], 0.05);
  EXPECT_NEAR(z.offset_um_per_K[1], truth.offset[1], 0.05);
  EXPECT_NEAR(z.slope_um_per_K_m[0], truth.slope[0], 0.5);
  EXPECT_NEAR(z.slope_um_per_K_m[1], truth.slope[1], 0.5);
  EXPECT_GT(z.explained, 0.999);
  EXPECT_LT(z.explained, 1.0);
}

TEST(ThermalFit, ChannelsThatMoveTogetherAreRefusedByName) {
  // T_b is T_a + 0.5 K: their rises are identical, the offsets and slopes cannot be told apart.
  const char* text =
      "time_s,axis,position_mm,deviation_um,T_a_C,T_ambient_C,T_b_C\n"
      "0,X,0,0,20,20,20.5\n1,X,100,0,20,20,20.5\n"
      "100,X,0,1,21,20.1,21.5\n101,X,100,2,21,20.2,21.5\n"
      "200,X,0,3,23,20.1,23.5\n201,X,100,4,23,20.0,23.5\n"
      "300,X,0,4,24,20.3,24.5\n301,X,100,6,24,20.1,24.5\n";
  ExpectFailure(FitThermalModel(Read(text), {}), Error::kInputInvalid,
                {"axis X", "ill-conditioned", "channels a and b move together", "offset a",
                 "offset b", "--channels"});
  // Without one of them the fit is well determined.
  ThermalFitOptions o;
  o.channels = {"a", "ambient"};
  EXPECT_TRUE(FitThermalModel(Read(text), o).ok());
}

TEST(ThermalFit, NearlyCollinearChannelsAreRefusedAboveTheLimit) {
  // b = a + a small wobble (±0.01 K on rises of 4 K): correlation beyond 0.9999.
  std::ostringstream s;
  s << "time_s,axis,position_mm,deviation_um,T_a_C,T_b_C\n";
  for (int k = 0; k < 20; ++k) {
    for (int i = 0; i < 2; ++i) {
      const double a = 20 + 0.2 * k;
      s << 10 * k + i << ",Y," << 100 * i << "," << 0.3 * k * (i + 1) << "," << a << ","
        << a + 0.01 * ((k % 3) - 1) << "\n";
    }
  }
  ExpectFailure(FitThermalModel(Read(s.str()), {}), Error::kInputInvalid,
                {"axis Y", "limit 1e+04", "channels a and b move together"});
  ThermalFitOptions lenient;
  lenient.max_condition = 1e12;
  EXPECT_TRUE(FitThermalModel(Read(s.str()), lenient).ok());
}

TEST(ThermalFit, AChannelThatDoesNotChangeIsRefused) {
  ExpectFailure(FitThermalModel(Read("time_s,axis,position_mm,deviation_um,T_a_C,T_still_C\n"
                                     "0,X,0,0,20,20\n1,X,10,0,20,20\n"
                                     "5,X,0,1,21,20\n6,X,10,1,22,20\n"),
                                {}),
                Error::kInputInvalid, {"axis X", "channel still does not change", "--channels"});
}

TEST(ThermalFit, ACoefficientBeyondTheModelsBoundIsRefused) {
  // 3000 µm over 2 K at both points: offset -1500 µm/K > 1000.
  ExpectFailure(FitThermalModel(Read("time_s,axis,position_mm,deviation_um,T_a_C\n"
                                     "0,X,0,0,20\n1,X,10,0,20\n"
                                     "5,X,0,3000,22\n6,X,10,3000,22\n"),
                                {}),
                Error::kInputInvalid, {"axis X", "offset -1500 µm/K of channel a", "bound 1000"});
}

TEST(ThermalFit, TooFewReadingsForTheUnknownsAreRefused) {
  // Two channels: 4 unknowns, 2 equations.
  ExpectFailure(FitThermalModel(Read("time_s,axis,position_mm,deviation_um,T_a_C,T_b_C\n"
                                     "0,X,0,0,20,20\n1,X,10,0,20,20\n"
                                     "5,X,0,1,21,20.5\n6,X,10,1,22,21\n"),
                                {}),
                Error::kInputInvalid, {"axis X", "2 readings", "4 unknowns"});
}

TEST(ThermalFit, ChannelsAndReferencesAreChosenByName) {
  ThermalFitOptions o;
  o.channels = {"nope"};
  ExpectFailure(FitThermalModel(Read(kHandCase), o), Error::kInputInvalid,
                {"--channels", "\"nope\" is not a channel", "(a)"});
  o.channels = {};
  o.reference_by["b"] = 20;
  ExpectFailure(FitThermalModel(Read(kHandCase), o), Error::kInputInvalid,
                {"--reference-C", "\"b\""});
  o.reference_by = {{"a", 19.5}};
  const ThermalFit fit = ValueOf(FitThermalModel(Read(kHandCase), o));
  EXPECT_DOUBLE_EQ(fit.channels[0].reference_C, 19.5);
  EXPECT_TRUE(fit.channels[0].reference_given);
  // The reference does not enter the fit (differences only).
  EXPECT_NEAR(fit.axes[0].offset_um_per_K[0], -2.0, 1e-12);
  ExpectFailure(FitThermalModel(Read("time_s,axis,position_mm,deviation_um\n0,X,0,0\n1,X,5,0\n"
                                     "2,X,0,1\n3,X,5,1\n"),
                                {}),
                Error::kInputInvalid, {"no temperature channel"});
}

TEST(ThermalFit, TheImagesTravelWidensTheReach) {
  ThermalFitOptions o;
  o.travel_mm['X'] = {-100.0, 120.0};  // p0 = 50: reach max(150, 70) = 150
  const ThermalFit fit = ValueOf(FitThermalModel(Read(kHandCase), o));
  EXPECT_DOUBLE_EQ(fit.axes[0].reach_mm, 150);
  EXPECT_TRUE(fit.axes[0].reach_from_image);
}

TEST(ThermalFit, TheImagesModelUsesTheChannelNumbersAndTheAxesByName) {
  // Channels b (number 1) and d (3) of four; the drift test's axis X is the image's second axis.
  const char* text =
      "time_s,axis,position_mm,deviation_um,T_a_C,T_b_C,T_c_C,T_d_C\n"
      "0,X,0,0,20,20.004,20,18\n1,X,100,0,20,20.004,20,18\n"
      "100,X,0,1,21,21,20,18.5\n101,X,100,2,21,21,20,18.5\n"
      "200,X,0,3,23,23,20,18.7\n201,X,100,5,23,23,20,18.7\n"
      "300,X,0,4,24,24.5,20,19.996\n301,X,100,6,24,24.5,20,19.996\n";
  ThermalFitOptions o;
  o.channels = {"d", "b"};
  const ThermalFit fit = ValueOf(FitThermalModel(Read(text), o));
  ASSERT_EQ(fit.channels.size(), 2u);
  EXPECT_EQ(fit.channels[0].number, 1u);
  EXPECT_EQ(fit.channels[1].number, 3u);
  table::AxisInfo axes[3] = {{'Y', table::AxisKind::kLinear, 1000000},
                             {'X', table::AxisKind::kLinear, 1000000},
                             {'C', table::AxisKind::kRotary, 1000000}};
  const thermal::ThermalModel m = ValueOf(ToThermalModel(fit, axes, 3));
  EXPECT_EQ(m.axis_count, 3);
  EXPECT_EQ(m.channel_mask, 0x0A);
  EXPECT_EQ(m.reference_cC[1], 2000);       // 20.004 rounds to 2000 cC
  EXPECT_EQ(m.calibrated_low_cC[1], 2000);  // floor(2000.4)
  EXPECT_EQ(m.calibrated_high_cC[1], 2450);
  EXPECT_EQ(m.reference_cC[3], 1800);
  EXPECT_EQ(m.calibrated_low_cC[3], 1800);
  EXPECT_EQ(m.calibrated_high_cC[3], 2000);  // ceil(1999.6)
  EXPECT_FLOAT_EQ(m.axis[1].offset_um_per_K[1], static_cast<float>(fit.axes[0].offset_um_per_K[0]));
  EXPECT_FLOAT_EQ(m.axis[1].slope_um_per_K_m[3],
                  static_cast<float>(fit.axes[0].slope_um_per_K_m[1]));
  EXPECT_FLOAT_EQ(m.axis[1].p0_mm, 50.0f);
  EXPECT_EQ(m.axis[0].offset_um_per_K[1], 0.0f);  // Y: not in the test
  EXPECT_EQ(m.axis[1].offset_um_per_K[0], 0.0f);  // channel a: not chosen

  table::AxisInfo rotary_x[1] = {{'X', table::AxisKind::kRotary, 1000000}};
  ExpectFailure(ToThermalModel(fit, rotary_x, 1), Error::kInputInvalid,
                {"axis X is a rotary axis", "no thermal term"});
  table::AxisInfo yz[2] = {{'Y', table::AxisKind::kLinear, 1000000},
                           {'Z', table::AxisKind::kLinear, 1000000}};
  ExpectFailure(ToThermalModel(fit, yz, 2), Error::kInputInvalid,
                {"axis X of the drift test is not an axis of the image (Y, Z)"});
}

TEST(ThermalFit, EigenvaluesOfAHandCase) {
  // [[2, 1], [1, 2]]: eigenvalues 1 and 3, eigenvectors (1, -1)/√2 and (1, 1)/√2.
  const SymmetricEigen e = EigenSymmetric({{2, 1}, {1, 2}});
  EXPECT_NEAR(e.values[0], 1.0, 1e-14);
  EXPECT_NEAR(e.values[1], 3.0, 1e-14);
  EXPECT_NEAR(std::fabs(e.vectors[0][0] + e.vectors[0][1]), 0.0, 1e-14);
  EXPECT_NEAR(std::fabs(e.vectors[1][0] - e.vectors[1][1]), 0.0, 1e-14);
  EXPECT_NEAR(std::fabs(e.vectors[1][0]), 1 / std::sqrt(2.0), 1e-14);
  // diag(4, 1, 9) with a rotation in the (0, 2) plane: eigenvalues 1, 4, 9 whatever the basis.
  const double c = std::cos(0.3), s = std::sin(0.3);
  const SymmetricEigen r = EigenSymmetric({{4 * c * c + 9 * s * s, 0, (9 - 4) * c * s},
                                           {0, 1, 0},
                                           {(9 - 4) * c * s, 0, 4 * s * s + 9 * c * c}});
  EXPECT_NEAR(r.values[0], 1, 1e-12);
  EXPECT_NEAR(r.values[1], 4, 1e-12);
  EXPECT_NEAR(r.values[2], 9, 1e-12);
}

}  // namespace
}  // namespace volcomp::builders
