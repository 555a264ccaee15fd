// RepRapFirmware M556 / M425 G-code (see reprap_gcode.hpp).
#include "volcomp/exporters/reprap_gcode.hpp"

namespace volcomp::exporters {
namespace {

constexpr const char* kSign =
    "; Skew sign: volcomp's squareness (X the reference; the angle from +X to +Y is 90 deg + C0Y,\n"
    ";   X to Z 90 deg - B0Z, Y to Z 90 deg + A0Z) becomes RRF's tangent tan(angle - 90 deg)\n"
    ";   (Move.cpp AxisTransform; Move.h \"90 degrees + angle gives angle between axes\"):\n"
    ";   XY = tan C0Y (M556 X), YZ = tan A0Z / cos B0Z (M556 Y), ZX = -tan B0Z (M556 Z); each\n"
    ";   written as the deviation tangent x S. Not checked on a machine: print a square after\n"
    ";   loading; if its skew doubled, export again with --negate.\n";

constexpr const char* kBacklash =
    "; Backlash: the lost motion b = -(ISO 230-2 mean reversal), the distance RRF adds when the\n"
    ";   axis reverses (Platform.cpp ApplyBacklashCompensation), mm, >= 0.\n";

}  // namespace

Expected<ReprapGcode> BuildReprapGcode(const HobbySquareness& squareness,
                                       const std::vector<AxisBacklash>& backlash,
                                       double length_mm,
                                       bool negate) {
  if (!squareness.any() && backlash.empty()) {
    return Fail(Error::kInvalidArgument,
                "RepRapFirmware: neither a squareness nor a backlash given");
  }
  if (!(length_mm > 0)) {
    return Fail(Error::kInvalidArgument, "RepRapFirmware M556 S" + FixedDecimals(length_mm, 3) +
                                             ": the length must be > 0 mm");
  }
  ReprapGcode r;
  r.tangents = ReprapTangents(squareness, negate);
  VOLCOMP_TRY_ASSIGN(const std::string m425,
                     BacklashWords(backlash, "XYZUVWABC", "RepRapFirmware's M425"));

  std::string& t = r.text;
  t = "; RepRapFirmware axis compensation and backlash (for config.g)\n";
  t += HobbyInputLines("; ", "export reprap", squareness, backlash);
  if (squareness.any()) {
    t += kSign;
    if (negate) t += "; NEGATED (--negate): every deviation has the opposite sign.\n";
    t += PlanesNotGiven("; ", r.tangents);
  }
  if (!backlash.empty()) t += kBacklash;
  if (squareness.any()) {
    // M556's words: X = XY, Y = YZ, Z = ZX, i.e. the order xy, yz, xz of SkewValues.
    SkewValues words;
    words.xy = r.tangents.xy;
    words.xz = r.tangents.yz;
    words.yz = r.tangents.xz;
    t += "M556 S" + FixedDecimals(length_mm, 3) + SkewWords(words, "XYZ", length_mm, 7) + "\n";
  }
  if (!backlash.empty()) t += "M425" + m425 + "\n";
  return r;
}

}  // namespace volcomp::exporters
