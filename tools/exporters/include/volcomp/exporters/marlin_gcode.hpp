// Marlin skew and backlash correction as G-code (M852, M425, M500) from volcomp's squareness and
// positioning tests (hobby_common.hpp has the conversions and their derivation).
//
// Format (MarlinFirmware/Marlin; shared reference data-formats.md §B10):
//   * M852 I<xy> J<xz> K<yz> (S is an alias of I): skew factors, each accepted only within
//     SKEW_FACTOR_MIN..SKEW_FACTOR_MAX = −1..1 (Marlin/src/inc/Conditionals_post.h; an out-of-range
//     value is ignored with a message); J and K need SKEW_CORRECTION_FOR_Z, M852 needs
//     SKEW_CORRECTION_GCODE (Marlin/src/gcode/calibrate/M852.cpp).
//   * M425 F<0..1> X<mm> Y<mm> Z<mm>: backlash distance per axis (0 disables) and the fraction
//     applied (F1 = full); needs BACKLASH_GCODE (Marlin/src/gcode/calibrate/M425.cpp); only X, Y,
//     Z.
//   * Both read their values with parser.value_linear_units(): in inch mode (G20) they would be
//     scaled, so the file starts with G21. M500 stores the values (EEPROM_SETTINGS).
// Sign: M852 factors = Klipper's (Klipper's skew_correction.py is a port of Marlin's planner.h
// skew()): xy = −tan C0Y, xz = tan B0Z, yz = −tan A0Z / cos B0Z, from the code; not checked on a
// machine (--negate flips every factor). Backlash: b = −B̄ ≥ 0, the distance Marlin adds when an
// axis reverses (Marlin checks no range: ≥ 0 is inferred from its meaning).
// Values: factors 9 decimals, backlash mm 4 decimals. A plane or axis not given is not written
// (the controller keeps its value), and the file says so.
#pragma once

#include <string>
#include <vector>

#include "volcomp/exporters/hobby_common.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::exporters {

inline constexpr double kMarlinSkewFactorMin = -1.0;  // SKEW_FACTOR_MIN
inline constexpr double kMarlinSkewFactorMax = 1.0;   // SKEW_FACTOR_MAX

struct MarlinGcode {
  std::string text;
  SkewValues factors;  // M852 I, J, K (the planes given)
};

/// kInvalidArgument naming the value and the limit: nothing given, a factor outside −1..1, a
/// backlash axis other than X, Y, Z or rotary, a backlash < 0.
Expected<MarlinGcode> BuildMarlinGcode(const HobbySquareness& squareness,
                                       const std::vector<AxisBacklash>& backlash,
                                       bool negate);

}  // namespace volcomp::exporters
