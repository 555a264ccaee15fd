// 1-D axis tables (AXIS1D) from bidirectional positioning tests (ISO 230-2 / GOST 27843-88).
//
// Input: per target position P_j the mean positional deviations x̄↑_j (approach in the positive
// direction) and x̄↓_j (negative), deviation = actual − target, either as a CSV of means:
//   linear axis: position_mm, dev_forward_um [, dev_reverse_um]
//   rotary axis: position_deg, dev_forward_arcsec [, dev_reverse_arcsec]
// (samples/model/positioning_x.csv), or as the raw readings `volcomp evaluate positioning` reads
// (target_mm|target_deg, direction, run, deviation_um ...; tools/metrology averages them with the
// same checks and warnings as the evaluation).
//
// Output: corrections on an equally spaced lattice (the image stores nodes at a fixed spacing,
// while test positions are usually irregular on purpose): the correction c(t) = q − t where the
// command q reaches t, i.e. q + dev(q) = t, solved by fixed-point iteration on the deviation
// interpolated linearly between the test positions (held constant beyond them).
// Reverse handling: kTables — forward table from x̄↑, reverse table from x̄↓, no backlash;
// kBacklash — forward table from x̄↑ plus one backlash value = mean reversal B̄ = mean(x̄↑ − x̄↓)
// (the correction added while moving negative); kMean — a single table from (x̄↑ + x̄↓)/2.
// Units: positions mm (deg), deviations and corrections µm (arcsec).
#pragma once

#include <string>
#include <vector>

#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::model {

struct PositioningData {
  bool rotary = false;
  std::vector<double> position;       // mm or deg, increasing
  std::vector<double> dev_forward;    // µm or arcsec
  std::vector<double> dev_reverse;    // empty when only one direction was measured
  std::vector<std::string> warnings;  // from the checks of raw readings (outliers, ...)
};

/// Either CSV layout above; raw readings are grouped and checked with `grouping` (by default
/// ≥ 5 approaches per target and direction). Throws tools::InputError naming the line.
PositioningData PositioningFromCsv(
    const tools::CsvTable& csv,
    const metrology::GroupingOptions& grouping = metrology::GroupingOptions{});
PositioningData LoadPositioningCsv(
    const std::string& path,
    const metrology::GroupingOptions& grouping = metrology::GroupingOptions{});

enum class ReverseMode { kTables, kBacklash, kMean };

struct Axis1dOptions {
  ReverseMode reverse = ReverseMode::kTables;
  double spacing = 0;        // lattice spacing (mm or deg); 0 = the test's if regular, else its
                             // smallest gap
  double unit_per_step = 0;  // when > 0: spacing and origin are snapped to whole steps
};

struct Axis1dTable {
  double origin = 0;  // mm or deg
  double spacing = 0;
  std::vector<double> forward;  // corrections, µm or arcsec
  std::vector<double> reverse;  // empty unless kTables with reverse data
  double backlash = 0;          // µm or arcsec, added while moving negative (kBacklash)
  double max_residual = 0;      // worst |q + dev(q) − t| at the nodes, µm or arcsec
};

/// Throws std::invalid_argument with the reason (too few positions, reverse mode without reverse
/// data, a spacing that is not a whole number of steps).
Axis1dTable BuildAxis1d(const PositioningData& data, const Axis1dOptions& options);

}  // namespace volcomp::model
