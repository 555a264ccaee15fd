// RepRapFirmware axis (skew) compensation and backlash as G-code for config.g (M556, M425), from
// volcomp's squareness and positioning tests (hobby_common.hpp has the conversions and their
// derivation).
//
// Format (Duet3D/RepRapFirmware @fc1cd16c; shared reference data-formats.md §B11):
//   * M556 S<length> X<dev> Y<dev> Z<dev>: for each of X, Y, Z given, tangent = dev / S
//     (src/GCodes/GCodes2.cpp, case 556; S read with GetPositiveFValue, so S > 0): X sets the XY
//     tangent, Y the YZ tangent, Z the ZX tangent (the reply reads "XY, YZ, ZX"). P0 (default) /
//     P1 choose whether X or Y is corrected for the XY skew; the same tangent serves both, so P is
//     not written.
//   * M425 X<mm> Y<mm> ... : backlash per axis letter, read with GetNonNegativeFValue (≥ 0); S (the
//     correction distance multiplier, 1..101) is left at the controller's value
//     (src/Platform/Platform.cpp ConfigureBacklashCompensation).
// Sign: the tangents of Move.cpp AxisTransform: XY = tan C0Y, YZ = tan A0Z / cos B0Z,
// ZX = −tan B0Z (the negated Klipper/Marlin factors); the deviation written is tangent × S. From
// the code; not checked on a machine (--negate flips every deviation). Backlash: b = −B̄ ≥ 0, mm.
// Rotary axes are refused (the backlash unit of a rotary axis is not in volcomp's sources).
// Values: deviations mm 7 decimals (tangent resolution 10⁻⁷ / S), backlash mm 4 decimals. A plane
// or axis not given is not written (the controller keeps its value).
#pragma once

#include <string>
#include <vector>

#include "volcomp/exporters/hobby_common.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::exporters {

struct ReprapGcode {
  std::string text;
  SkewValues tangents;  // XY, XZ (M556 Z), YZ (M556 Y): the planes given
};

/// kInvalidArgument naming the value and the limit: nothing given, `length_mm` ≤ 0, a rotary
/// backlash axis, a backlash < 0.
Expected<ReprapGcode> BuildReprapGcode(const HobbySquareness& squareness,
                                       const std::vector<AxisBacklash>& backlash,
                                       double length_mm,
                                       bool negate);

}  // namespace volcomp::exporters
