// Renishaw LaserXL / Laser10 linear data files (`.rtl`, XL-80 / ML10 lasers): one linear axis
// test with all its runs, targets, deviations, the user text and the environment record, read
// into the positioning readings the CSV path produces (metrology/positioning_data.hpp) and the
// test conditions of the reports (metrology/test_conditions.hpp).
//
// Source and confidence (../shared/reference/data-formats.md §A1): no Renishaw document and no
// real sample file were found; the layout is reconstructed from four independent public parsers
// that agree ([code ×4]). Syntax as they read it:
//   - ASCII lines (CRLF or LF); blank lines ignored; keys ASCII, values opaque bytes (operator
//     and machine names may be GBK: a value that is not UTF-8 is kept with '?' for the bad bytes,
//     and a warning says so);
//   - sections open with a line `NAME::`: HEADER, TARGET DATA, USER-TEXT, RUNS, DEVIATIONS,
//     ENVIRONMENT (and EQUIPMENT, skipped); inside them `Key: value` or `Key : value` lines, split
//     at the first colon;
//   - `Target-count: N`, then `Targets :` and N numbers over one or more lines (any count per
//     line);
//   - `Run-count: R`;
//   - DEVIATIONS: an optional `Run Target Data:` line, then R × N rows "run target deviation",
//     run and target 1-based;
//   - ENVIRONMENT: `Air temp`, `Air press`, `Air humid`, `Mat temp 1..3`, `Env factor`,
//     `Exp coeff`: a start and an end value and an optional third integer of unknown meaning;
//     `Date Time`: two quoted times. `Mat temp n` -10.000000 at both ends is read as "no sensor"
//     [infer].
// Units: targets in mm, deviations in µm ([code], three parsers say µm, a fourth divides by 1000
// for controller tables in mm); temperatures in °C, pressure in kPa [infer], humidity in %RH,
// expansion coefficient in ppm/°C [infer]. The file records no unit that any parser knows.
//
// Inch files (RtlUnits::kIn, --rtl-units in) [unconfirmed: no inch sample exists in public]:
// LaserXL run in imperial units is taken to write the same file with other units: targets in
// inches and deviations in microinches (µin). They are converted exactly (1 in = 25.4 mm,
// 1 µin = 0.0254 µm) into the mm/µm test the rest of the tool uses, here and nowhere else. Check
// a first real file once against the laser software's display: one target (e.g. 4.000000 in
// on screen = 101.6 mm in `evaluate positioning`) and one deviation (e.g. 78.74 µin on screen
// = 2.000 µm).
// Environment units are recognised by range in both unit systems (environment_units.hpp), said
// aloud in a warning: a temperature above 45 is °F (converted to °C); a pressure in kPa, hPa,
// mmHg or inHg (converted to kPa); when the temperatures are °F, `Exp coeff` is read as ppm/°F
// (×1.8 to ppm/°C) unless RtlOptions::expansion_per says otherwise (6.4 ppm/°F steel and
// 6.4 ppm/°C granite are both plausible, so its range cannot tell). °F temperatures in a file
// read as mm (or °C in one read as inches) are warned about: it was probably written in the
// other unit system. The test conditions get a "units as read" entry when anything was
// converted.
//
// Sign: volcomp's convention is error E = actual − nominal in µm. The parsers' writers put the
// stored deviation unchanged into controller tables that hold E (Heidenhain, Siemens), so the
// stored deviation is taken as E unchanged [infer]; one parser has an "invert sign" switch since
// the sign depends on the laser setup, hence RtlOptions::negate (deviation → −deviation).
//
// Directions: run parity (odd runs ↑, even runs ↓; one parser's rule) by default, with a warning
// when the row order within a run contradicts it (an odd run listed from the last target down) or
// does not confirm it (even runs listed in target order). RtlRuns::kForward / kReverse read a
// unidirectional test (every run ↑ / ↓). Run numbers within a direction are renumbered 1, 2, ...
//
// Refused (kInputInvalid, "source:line: what is wrong"): text before the first section; a
// section given twice (several axes or tests in one file: one axis per file); a CARTO dynamic
// capture (.rtx); a missing Target-count, Targets, Run-count or DEVIATIONS section; a Targets
// list longer or shorter than Target-count, or a target given twice; a deviation row that is not
// three numbers, whose run or target is beyond the counts or repeats an earlier row; fewer rows
// than R × N (a truncated file: the missing run/targets are named); a non-number where a number
// belongs; a deviation beyond metrology::kMaxReadingMagnitude; a temperature neither °C nor °F
// of a shop, or a pressure in none of the recognised ranges (the ranges are named). A missing
// ENVIRONMENT section is a warning (no temperatures in the test conditions).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/metrology/test_conditions.hpp"

namespace volcomp::datasets {

/// How runs map to directions.
enum class RtlRuns {
  kAlternate,  // odd runs ↑, even runs ↓ (bidirectional test)
  kForward,    // every run ↑ (unidirectional test)
  kReverse,    // every run ↓
};

/// The length units the laser software wrote the file in (the file does not say).
enum class RtlUnits {
  kMm,  // targets mm, deviations µm
  kIn,  // targets inches, deviations µin [unconfirmed]: converted to mm and µm
};

/// "mm" or "in".
const char* RtlUnitsName(RtlUnits units);

/// The temperature unit of `Exp coeff`'s ppm.
enum class RtlExpansionPer {
  kAuto,        // per °F when the file's temperatures are °F (warned), else per °C
  kCelsius,     // ppm/°C as written
  kFahrenheit,  // ppm/°F: ×1.8 to ppm/°C
};

struct RtlOptions {
  RtlRuns runs = RtlRuns::kAlternate;
  bool negate = false;  // the laser setup measured nominal − actual: flip every deviation
  RtlUnits units = RtlUnits::kMm;
  RtlExpansionPer expansion_per = RtlExpansionPer::kAuto;
};

/// One environment record: value at the start and at the end of the test.
struct RtlReading {
  double start = 0.0;
  double end = 0.0;
  std::size_t line = 0;
};

/// As read, converted to these units (the units the file was written in are in the warnings and
/// the condition "units as read").
struct RtlEnvironment {
  std::optional<RtlReading> air_temperature_c;
  std::optional<RtlReading> air_pressure_kpa;
  std::optional<RtlReading> humidity_pct;
  std::optional<RtlReading> material_temperature_c[3];  // sensors 1..3; nullopt: not fitted
  std::optional<RtlReading> expansion_ppm_per_c;
  std::optional<RtlReading> environment_factor;  // meaning unknown
  std::string date_time;                         // "start to end", as written
};

struct RtlTest {
  metrology::PositioningData readings;   // linear axis, targets mm, deviations µm (E)
  metrology::TestConditions conditions;  // user text, then the environment
  RtlEnvironment environment;
  std::vector<double> targets_mm;  // in Targets order, converted to mm
  int run_count = 0;
  std::size_t deviations_line = 0;    // the DEVIATIONS:: line
  std::vector<std::string> warnings;  // "source:line: ..." or "source: ..."
};

/// True when the first non-blank line of `text` is a section line `NAME::` (after a UTF-8 BOM).
bool LooksLikeRtl(const std::string& text);

/// Reads the whole file text; `source` names it in messages.
Expected<RtlTest> ParseRtl(const std::string& text,
                           const std::string& source,
                           const RtlOptions& options = RtlOptions{});

}  // namespace volcomp::datasets
