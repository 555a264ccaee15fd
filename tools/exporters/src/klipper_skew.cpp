// Klipper skew correction profile and SET_SKEW command (see klipper_skew.hpp).
#include "volcomp/exporters/klipper_skew.hpp"

#include <cmath>

namespace volcomp::exporters {
namespace {

constexpr const char* kSign =
    "# Sign: volcomp's squareness (X the reference; the angle from +X to +Y is 90 deg + C0Y, X to "
    "Z\n"
    "#   90 deg - B0Z, Y to Z 90 deg + A0Z) becomes Klipper's factor tan(90 deg - angle):\n"
    "#   xy = -tan C0Y, xz = tan B0Z, yz = -tan A0Z / cos B0Z (klippy/extras/skew_correction.py\n"
    "#   calc_skew and calc_skew_factor; docs/Skew_Correction.md). Not checked on a machine: "
    "print\n"
    "#   a square after loading; if its skew doubled, export again with --negate.\n";

constexpr const char* kAutosaveHeader =
    "#*# <---------------------- SAVE_CONFIG ---------------------->\n"
    "#*# DO NOT EDIT THIS BLOCK OR BELOW. The contents are auto-generated.\n"
    "#*#\n";

std::string Lengths(const SquareLengths& l) {
  return FixedDecimals(l.ac, 6) + "," + FixedDecimals(l.bd, 6) + "," + FixedDecimals(l.ad, 6);
}

}  // namespace

SquareLengths SquareForFactor(double factor, double side_mm) {
  // cos α with α = π/2 − atan f: sin(atan f) = f / √(1 + f²).
  const double c = factor / std::sqrt(1 + factor * factor);
  return {side_mm * std::sqrt(2 + 2 * c), side_mm * std::sqrt(2 - 2 * c), side_mm};
}

Expected<KlipperSkew> BuildKlipperSkew(const HobbySquareness& squareness,
                                       const KlipperOptions& options) {
  if (!squareness.any()) {
    return Fail(Error::kInvalidArgument, "Klipper: no squareness given, nothing to write");
  }
  if (options.profile.empty() || options.profile.find_first_of(" \t\r\n") != std::string::npos) {
    return Fail(Error::kInvalidArgument,
                "Klipper profile name \"" + options.profile +
                    "\": one word without blanks (it is SKEW_PROFILE's LOAD= value)");
  }
  if (!(options.square_mm > 0)) {
    return Fail(Error::kInvalidArgument,
                "Klipper square side " + FixedDecimals(options.square_mm, 3) + " mm: must be > 0");
  }
  KlipperSkew k;
  k.factors = KlipperMarlinFactors(squareness, options.negate);
  std::string set_skew = "SET_SKEW";
  const struct {
    const char* plane;
    const std::optional<double>* factor;
    std::optional<SquareLengths>* lengths;
  } planes[] = {
      {"XY", &k.factors.xy, &k.xy}, {"XZ", &k.factors.xz, &k.xz}, {"YZ", &k.factors.yz, &k.yz}};
  for (const auto& p : planes) {
    if (!*p.factor) continue;
    *p.lengths = SquareForFactor(**p.factor, options.square_mm);
    set_skew += std::string(" ") + p.plane + "=" + Lengths(**p.lengths);
  }

  std::string& t = k.text;
  t = "# Klipper skew correction\n";
  t += HobbyInputLines("# ", "export klipper", squareness, {});
  t += kSign;
  if (options.negate) t += "# NEGATED (--negate): every factor has the opposite sign.\n";
  t += "# printer.cfg needs a [skew_correction] section. Then either run at the console (the\n"
       "# lengths of a " +
       FixedDecimals(options.square_mm, 3) +
       " mm square with exactly these factors):\n"
       "#   " +
       set_skew + "\n#   SKEW_PROFILE SAVE=" + options.profile +
       "\n"
       "#   SAVE_CONFIG\n"
       "# or append the block below to printer.cfg (into an existing SAVE_CONFIG block: its four\n"
       "# section lines only) and run SKEW_PROFILE LOAD=" +
       options.profile + " (e.g. in the start G-code).\n";
  for (const auto& p : planes) {
    if (!*p.factor) t += std::string("# ") + p.plane + ": no squareness given, written as 0.\n";
  }
  t += kAutosaveHeader;
  t += "#*# [skew_correction " + options.profile + "]\n";
  const char* keys[] = {"xy_skew", "xz_skew", "yz_skew"};
  for (int i = 0; i < 3; ++i) {
    t += std::string("#*# ") + keys[i] + " = " + FixedDecimals(planes[i].factor->value_or(0), 9) +
         "\n";
  }
  return k;
}

}  // namespace volcomp::exporters
