// SpatialAnalyzer (SA) point exports: laser-tracker points as SA writes them (data-formats.md §A5;
// SA user manual, "Exporting ASCII Formatted Points" and "Importing Predefined ASCII Formatted
// Files").
//
// ASCII export, one point per line: `[name parts] x y z [extra...]`.
//   - Fields are separated by spaces, tabs or commas (a run of them is one separator).
//   - The name is up to 3 parts (`Collection Group Target`, `Group Target` or `Target`); SA lets
//     the export leave it out, but volcomp pairs points by name, so a line without one is refused.
//   - By default the name parts are the leading fields that are not numbers and x y z are the
//     three numbers after them; a name part that is a bare number (target "12") needs
//     `name_fields` (the count of name parts, 0..3) to be given.
//   - Fields after z (tolerances, uncertainties, time stamps, comments) are ignored.
//   - Lines starting with `//` (SA version, frame, axis comments) and blank lines are skipped.
//   - Numbers are fixed-decimal or scientific (`1.5E+02`).
//   The point's name is its name parts joined by one space ("Coll Grp P1").
// XML: `<POINT NAME="..."><NOMINAL X=".." Y=".." Z=".."/><ACTUAL X=".." Y=".." Z=".."/></POINT>`
//   nominal/actual pairs. Tag and attribute names are matched without regard to case; other
//   elements, `<?...?>` and `<!--...-->` are skipped; the entities &amp; &lt; &gt; &quot; &apos;
//   are decoded in names.
//
// Units: SA writes the working frame's unit; `unit` says which (mm, inch or metre) and every
// coordinate returned is in mm.
//
// Refused (kInputInvalid, "source:line: ..."): a line without three numbers, or without a name;
// a name given twice (naming both lines); a non-finite number; a POINT without NAME, NOMINAL or
// ACTUAL, or with one of X, Y, Z missing or not a number; a second NOMINAL or ACTUAL in a POINT,
// or one outside a POINT; a POINT inside a POINT; an unclosed tag;
// a file with no points.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/vec3.hpp"

namespace volcomp::datasets {

/// The unit of SA's working frame.
enum class SaUnit { kMillimetre, kInch, kMetre };

/// mm per unit (1, 25.4, 1000).
double MillimetresPer(SaUnit unit);

/// One named point of an ASCII export.
struct SaPoint {
  std::string name;
  model::Vec3 position_mm;
  std::size_t line = 0;  // 1-based
};

/// One nominal/actual pair of the XML.
struct SaPointPair {
  std::string name;
  model::Vec3 nominal_mm;
  model::Vec3 actual_mm;
  std::size_t line = 0;  // of the POINT tag
};

/// Points of an ASCII export, in file order. `name_fields`: the number of name parts (0..3) when
/// given, else the leading non-number fields.
Expected<std::vector<SaPoint>> SaPointsFromAscii(const std::string& text,
                                                 const std::string& source,
                                                 SaUnit unit,
                                                 std::optional<int> name_fields = std::nullopt);

/// Nominal/actual pairs of the XML, in file order.
Expected<std::vector<SaPointPair>> SaPairsFromXml(const std::string& text,
                                                  const std::string& source,
                                                  SaUnit unit);

/// Content recognition: the first non-blank character is '<' (after a UTF-8 BOM).
bool LooksLikeSaXml(const std::string& text);
/// Content recognition: the first non-blank line starts with `//` or ends its fields with ≥ 3
/// numbers after a name (a CSV header has no numbers).
bool LooksLikeSaAscii(const std::string& text);

}  // namespace volcomp::datasets
