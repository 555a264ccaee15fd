// Reading positioning test data from CSV (see docs/metrology.md for the full description).
//
// Long layout, one approach per row; the header names the columns and their units:
//   target_mm,direction,run,deviation_um
//   150.71,up,1,0.2
// - target: `target_mm` (linear axis) or `target_deg` (rotary axis);
// - direction: + - up down ↑ ↓ (also pos/neg);
// - run: approach index i, 1-based integer;
// - exactly one measurement column: linear `deviation_um`, `deviation_mm` or `measured_mm`;
//   rotary `deviation_arcsec`, `deviation_deg` or `measured_deg` (measured − target is wrapped
//   into (−180°, 180°]).
// Other columns are ignored.
//
// Wide layout, the table of the GOST 27843-88 appendix: the header's first cell is the
// measurement column name, the other header cells name position j and direction ("1+", "1-",
// "2+", ...; also "1up", "1↑"); the first data row starts with `target_mm`/`target_deg` and
// gives P_j under each column; every following row starts with the run index i and gives the
// readings (an empty cell is a missing reading):
//   deviation_um,1+,1-,2+,2-
//   target_mm,0,0,150.71,150.71
//   1,-2.6,2.3,0.2,5.4
//
// Internal units: targets in mm or degrees, deviations in µm (linear) or arc-seconds (rotary).
#pragma once

#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology {

/// Detects the layout and converts the rows; a failure (kInputInvalid) naming the line and the
/// problem for a missing or conflicting column, a bad number, direction or run index.
Expected<PositioningData> ReadPositioningCsv(const tools::CsvTable& table);

/// True when `table` has the header of raw positioning readings (either layout above).
bool HoldsPositioningReadings(const tools::CsvTable& table);

}  // namespace volcomp::metrology
