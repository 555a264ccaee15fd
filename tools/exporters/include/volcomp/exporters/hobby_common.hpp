// What the hobby controller writers share (klipper_skew, marlin_gcode, reprap_gcode,
// grblhal_settings): the machine's squareness per plane in volcomp's convention with its two
// firmware forms, and the backlash of an axis from a two-direction positioning test.
//
// SQUARENESS, volcomp's one convention (the 21-parameter model, docs/table-builders.md §2, ISO
// 230-1 names), µrad: X is the reference. C0Y (plane XY) turns the Y line about +z: Y runs along
// (−sin C0Y, cos C0Y, 0), the angle between +X and +Y is 90° + C0Y. B0Z (XZ) and A0Z (YZ) turn
// the Z line about +y and +x: Z runs along Ry(B0Z)·Rx(A0Z)·(0, 0, 1)
// = (cos A0Z sin B0Z, −sin A0Z, cos A0Z cos B0Z), so the X–Z angle is about 90° − B0Z and the
// Y–Z angle about 90° + A0Z.
//
// KLIPPER / MARLIN skew factors (klippy/extras/skew_correction.py calc_skew / calc_unskew;
// Marlin planner.h skew(), from which Klipper's is ported). For a target (x, y, z) the firmware
// drives the motors to
//   x_m = x − y·xy − z·(xz − xy·yz),   y_m = y − z·yz,   z_m = z,
// whose inverse (calc_unskew) x = x_m + y_m·xy + z_m·xz, y = y_m + z_m·yz says the firmware takes
// the machine's Y to run along (xy, 1, 0) and its Z along (xz, yz, 1). Setting these parallel to
// volcomp's axis lines (each divided by its last non-zero component):
//   xy = −sin C0Y / cos C0Y = −tan C0Y,
//   xz = cos A0Z sin B0Z / (cos A0Z cos B0Z) = tan B0Z,
//   yz = −sin A0Z / (cos A0Z cos B0Z) = −tan A0Z / cos B0Z.
// Check with Klipper's calc_skew_factor(AC, BD, AD) = tan(π/2 − α): its docs/img/skew_lengths.png
// puts A at the lower left, B above it, D to its right (AD along +X), so α = ∠DAB, the printed
// angle between +X and +Y, = 90° + C0Y on a machine with that squareness, and the factor is
// tan(−C0Y) = −tan C0Y, as above. The axis lengths (cos C0Y ≈ 1 − 6·10⁻⁷ at 1100 µrad) are not
// corrected by either firmware.
//
// REPRAPFIRMWARE tangents (src/Movement/Move.cpp AxisTransform / InverseAxisTransform, M556 in
// src/GCodes/GCodes2.cpp; Move.h: "90 degrees + angle gives angle between axes"): the motors go
// to x_m = x + tXY·y + tXZ·z, y_m = y + tYZ·z; the inverse takes Y along (−tXY, 1, 0) and Z along
// (−tXZ, −tYZ, 1). So every RRF tangent is minus the Klipper/Marlin factor:
//   tXY = tan C0Y,   tXZ = −tan B0Z,   tYZ = tan A0Z / cos B0Z.
// (M556 P1 corrects Y by tXY·x instead of X by tXY·y: the same angle, X tilted instead of Y, so
// the same tangent serves both.)
//
// BACKLASH (lost motion) of an axis, from the mean deviations x̄↑_j, x̄↓_j (actual − target) of a
// two-direction test: a carriage that lags its motor by b/2 each way sits at target − b/2 moving
// up and target + b/2 moving down, so b = x̄↓_j − x̄↑_j = −B_j (ISO 230-2 reversal B_j = x̄↑_j −
// x̄↓_j). The firmware value is the mean over the targets, b = −B̄. Marlin (M425), RRF (M425) and
// grblHAL ($160…) add b in the new direction when an axis reverses, so b must be ≥ 0 (RRF reads it
// with GetNonNegativeFValue; Marlin and grblHAL do not check: inferred). A test whose reverse
// deviations lie below the forward ones has no lost motion to add and is refused (the laser may
// have counted the other way: negate the test).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/positioning.hpp"

namespace volcomp::exporters {

/// One plane's squareness in volcomp's convention and where it came from.
struct PlaneSquareness {
  double urad = 0;     // C0Y (xy), B0Z (xz) or A0Z (yz), µrad
  std::string source;  // e.g. "--squareness-xy-urad" or "model s500.conf (C0Y)"
};

/// The planes given; an absent plane is not written (or written 0 where the format needs all).
struct HobbySquareness {
  std::optional<PlaneSquareness> xy, xz, yz;
  bool any() const { return xy || xz || yz; }
};

/// Skew values per plane; absent where the squareness is absent.
struct SkewValues {
  std::optional<double> xy, xz, yz;
};

/// Klipper's / Marlin's factors: xy = −tan C0Y, xz = tan B0Z, yz = −tan A0Z / cos B0Z (B0Z = 0
/// when not given); every value negated when `negate`.
SkewValues KlipperMarlinFactors(const HobbySquareness& s, bool negate);

/// RepRapFirmware's tangents: the negated Klipper/Marlin factors (then `negate` flips them).
SkewValues ReprapTangents(const HobbySquareness& s, bool negate);

/// The backlash of one axis from its positioning test.
struct AxisBacklash {
  char axis = 'X';
  std::string source;           // the test file
  bool rotary = false;          // values in arcsec (deg in the files) instead of µm (mm)
  int targets = 0;              // targets with both directions
  double lost_motion_um = 0;    // b = mean of (x̄↓_j − x̄↑_j) = −B̄, µm (arcsec)
  double reversal_mean_um = 0;  // B̄ = mean of (x̄↑_j − x̄↓_j), ISO 230-2 signs
  double reversal_max_um = 0;   // B = max |B_j|
  double spread_um = 0;         // max |(x̄↓_j − x̄↑_j) − b|: what a constant b leaves
  bool test_negated = false;    // the test's deviations were negated first
};

/// kInvalidArgument naming the file: a one-direction test (no reversal). `negate_test` flips the
/// deviations first (an instrument that counted the other way).
Expected<AxisBacklash> BacklashFromTest(char axis,
                                        const std::string& source,
                                        const model::PositioningData& data,
                                        bool negate_test);

/// Success, or kInvalidArgument when b < 0, naming the axis, b, B̄, the limit (≥ 0, `controller`'s
/// rule) and the fix.
Expected<void> RequireLostMotion(const AxisBacklash& b, const std::string& controller);

/// Success, or kInvalidArgument naming the axis and `controller`'s axes: an axis not in `axes`
/// (e.g. "XYZ") or a rotary axis where `rotary_ok` is false (the unit is not in the sources).
Expected<void> RequireBacklashAxis(const AxisBacklash& b,
                                   const std::string& axes,
                                   bool rotary_ok,
                                   const std::string& controller);

/// b in the file's unit: mm (deg on a rotary axis).
double BacklashInFileUnits(const AxisBacklash& b);

/// " X<b> Y<b> ..." of a G-code backlash command (M425), mm with 4 decimals, each axis checked
/// with RequireBacklashAxis(`axes`, linear only) and RequireLostMotion for `controller`.
Expected<std::string> BacklashWords(const std::vector<AxisBacklash>& backlash,
                                    const std::string& axes,
                                    const std::string& controller);

/// " I<xy> J<xz> K<yz>" of the planes given: `letters` name the words of xy, xz, yz (e.g. "IJK"),
/// each value times `scale` with `decimals` decimals.
std::string SkewWords(const SkewValues& v, const char* letters, double scale, int decimals);

/// The planes not given, as a comment line ("<comment>XZ, YZ: not given, not written ...").
std::string PlanesNotGiven(const std::string& comment, const SkewValues& v);

/// `value` with `decimals` decimals ("%.*f"), never "-0.000".
std::string FixedDecimals(double value, int decimals);

/// The header comment lines every hobby file starts with (each prefixed by `comment`, e.g. "; "):
/// the command, the squareness per plane with its source, the backlash per axis with its test.
std::string HobbyInputLines(const std::string& comment,
                            const std::string& command,
                            const HobbySquareness& squareness,
                            const std::vector<AxisBacklash>& backlash);

}  // namespace volcomp::exporters
