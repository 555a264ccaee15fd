// Reading the readings of a positioning test from CSV: the long layout (one approach per row:
// target_mm|target_deg, direction, run and one measurement column) or the wide layout of the
// GOST 27843-88 appendix (a column per position and direction, a row per run); columns, units and
// conversions in docs/metrology.md "Input files". Internal units: targets in mm or degrees,
// deviations in µm (linear axis) or arc-seconds (rotary axis).
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
