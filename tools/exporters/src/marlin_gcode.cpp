// Marlin M852 / M425 G-code (see marlin_gcode.hpp).
#include "volcomp/exporters/marlin_gcode.hpp"

namespace volcomp::exporters {
namespace {

constexpr const char* kSign =
    "; Skew sign: volcomp's squareness (X the reference; the angle from +X to +Y is 90 deg + C0Y,\n"
    ";   X to Z 90 deg - B0Z, Y to Z 90 deg + A0Z) becomes Marlin's factor tan(90 deg - angle):\n"
    ";   I = -tan C0Y, J = tan B0Z, K = -tan A0Z / cos B0Z (Marlin planner.h skew(), the same as\n"
    ";   Klipper's skew_correction.py). Not checked on a machine: print a square after loading;\n"
    ";   if its skew doubled, export again with --negate.\n";

constexpr const char* kBacklash =
    "; Backlash: the lost motion b = -(ISO 230-2 mean reversal), the distance Marlin adds when\n"
    ";   the axis reverses (Marlin/src/gcode/calibrate/M425.cpp), mm; F1 applies all of it.\n";

}  // namespace

Expected<MarlinGcode> BuildMarlinGcode(const HobbySquareness& squareness,
                                       const std::vector<AxisBacklash>& backlash,
                                       bool negate) {
  if (!squareness.any() && backlash.empty()) {
    return Fail(Error::kInvalidArgument, "Marlin: neither a squareness nor a backlash given");
  }
  MarlinGcode m;
  m.factors = KlipperMarlinFactors(squareness, negate);
  const struct {
    const char* word;
    const std::optional<double>* f;
  } words[] = {{"I (XY)", &m.factors.xy}, {"J (XZ)", &m.factors.xz}, {"K (YZ)", &m.factors.yz}};
  for (const auto& w : words) {
    if (*w.f && !(**w.f >= kMarlinSkewFactorMin && **w.f <= kMarlinSkewFactorMax)) {
      return Fail(Error::kInvalidArgument, "Marlin M852 " + std::string(w.word) + " = " +
                                               FixedDecimals(**w.f, 6) +
                                               " is outside SKEW_FACTOR_MIN..MAX = -1..1");
    }
  }
  VOLCOMP_TRY_ASSIGN(const std::string m425, BacklashWords(backlash, "XYZ", "Marlin's M425"));

  std::string& t = m.text;
  t = "; Marlin skew and backlash correction\n";
  t += HobbyInputLines("; ", "export marlin", squareness, backlash);
  if (squareness.any()) {
    t += kSign;
    if (negate) t += "; NEGATED (--negate): every skew factor has the opposite sign.\n";
    t += PlanesNotGiven("; ", m.factors);
    t += "; M852 needs SKEW_CORRECTION_GCODE; J and K also SKEW_CORRECTION_FOR_Z.\n";
  }
  if (!backlash.empty()) t += kBacklash + std::string("; M425 needs BACKLASH_GCODE.\n");
  t += "G21 ; millimetres: M852 and M425 read their values as lengths (G20 would scale them)\n";
  if (squareness.any()) t += "M852" + SkewWords(m.factors, "IJK", 1.0, 9) + "\n";
  if (!backlash.empty()) t += "M425 F1" + m425 + "\n";
  t += "M500 ; store the settings (EEPROM_SETTINGS)\n";
  return m;
}

}  // namespace volcomp::exporters
