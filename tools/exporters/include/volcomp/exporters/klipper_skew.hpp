// Klipper skew correction from volcomp's squareness (hobby_common.hpp has the conversion and its
// derivation): a printer.cfg SAVE_CONFIG block `[skew_correction PROFILE]` with xy_skew, xz_skew,
// yz_skew, and the SET_SKEW console command that gives the same factors.
//
// Format (Klipper3d/klipper @84104bbb, klippy/extras/skew_correction.py, klippy/configfile.py,
// docs/Skew_Correction.md; shared reference data-formats.md §B9):
//   * SKEW_PROFILE SAVE=name stores `[skew_correction name]` with `xy_skew`, `xz_skew`, `yz_skew`
//     (the factors; read back with getfloat, all three required); SAVE_CONFIG writes it behind
//     the `#*# ` prefix under the AUTOSAVE_HEADER lines; SKEW_PROFILE LOAD=name applies it.
//   * SET_SKEW XY=AC,BD,AD [XZ=...] [YZ=...] takes the lengths of a printed square (A lower left,
//     B above A, D right of A) and sets factor = calc_skew_factor(AC, BD, AD) = tan(π/2 − α), α the
//     angle at A (law of cosines with the parallelogram's side from AC² + BD² = 2(AB² + AD²)).
//     The lengths written are those of an ideal square of side L = `square_mm` whose angle at A is
//     α = π/2 − atan(f): AD = L, AC = L·√(2 + 2 cos α), BD = L·√(2 − 2 cos α) (then AB = L and
//     cos ∠A = (AC² − AB² − AD²)/(2·AB·AD) = cos α exactly).
// Sign: factor = tan(90° − angle between the axes) (hobby_common.hpp): xy = −tan C0Y, xz = tan B0Z,
// yz = −tan A0Z / cos B0Z. Confirmed from Klipper's code and docs; not checked on a machine, so
// the file says to print a square after loading and --negate flips every factor.
// Limits: Klipper checks no range for the factors; a plane's squareness beyond ±0.1 rad is
// refused by the callers as implausible. The profile name must be one word (it is a G-code
// parameter value); L > 0. Values: factors 9 decimals, lengths 6 decimals (mm).
#pragma once

#include <optional>
#include <string>

#include "volcomp/exporters/hobby_common.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::exporters {

struct KlipperOptions {
  std::string profile = "volcomp";  // [skew_correction PROFILE]
  double square_mm = 100;           // L, side of the square of SET_SKEW's lengths, mm
  bool negate = false;              // flip every factor
};

/// SET_SKEW's lengths for one plane, mm.
struct SquareLengths {
  double ac = 0, bd = 0, ad = 0;
};

struct KlipperSkew {
  std::string text;
  SkewValues factors;  // the planes given
  std::optional<SquareLengths> xy, xz, yz;
};

/// The square's lengths whose calc_skew_factor is `factor`.
SquareLengths SquareForFactor(double factor, double side_mm);

/// kInvalidArgument naming the value and the rule: no plane given, a profile name that is empty or
/// holds a blank, `square_mm` ≤ 0.
Expected<KlipperSkew> BuildKlipperSkew(const HobbySquareness& squareness,
                                       const KlipperOptions& options);

}  // namespace volcomp::exporters
