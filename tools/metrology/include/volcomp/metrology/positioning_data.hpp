// Positioning test data (GOST 27843-88, ISO 230-2:2014, and each diagonal of ISO 230-6): the raw
// readings as read from a file, and the same readings grouped per target position and direction
// after the input checks.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/direction.hpp"

namespace volcomp::metrology {

/// One measured approach: the deviation X_ij = P_ij − P_j (GOST formula (1)).
struct PositioningReading {
  double target = 0.0;  // P_j: mm (linear) or degrees (rotary)
  Direction direction = Direction::kUp;
  int run = 0;             // i, 1-based approach index within the direction
  double deviation = 0.0;  // X_ij: µm (linear) or arc-seconds (rotary)
  std::size_t line = 0;    // 1-based line in the source file, for messages
};

/// Largest deviation magnitude a reading may have, in µm or arc-seconds (1 km; 2.8e5 degrees):
/// beyond it a value is not a measurement and the statistics would lose all precision, so the
/// reader refuses it (as it refuses non-finite values).
inline constexpr double kMaxReadingMagnitude = 1e9;

struct PositioningData {
  std::string source;  // file name, for messages
  AxisKind kind = AxisKind::kLinear;
  std::vector<PositioningReading> readings;
  std::string column = "deviation_um";  // the measurement column as named in the file
  double column_scale = 1.0;            // one unit of that column in µm or arc-seconds
  bool read_in_inches = false;  // a target or measurement column in inches (or µin): converted
};

/// The approaches to one target position in one direction, ordered by run.
struct ApproachSeries {
  std::vector<double> deviations;  // µm or arc-seconds
  std::vector<int> runs;
  std::vector<std::size_t> lines;
  bool empty() const { return deviations.empty(); }
  std::size_t size() const { return deviations.size(); }
};

struct TargetPosition {
  double target = 0.0;  // mm or degrees
  ApproachSeries up;
  ApproachSeries down;
};

/// Readings grouped by target (ascending) with the checks of GroupReadings() passed.
struct PositioningSet {
  std::string source;
  AxisKind kind = AxisKind::kLinear;
  std::vector<TargetPosition> positions;
  bool has_up = false;    // some position has ↑ approaches (then every position has)
  bool has_down = false;  // likewise for ↓
  std::vector<std::string> warnings;
};

struct GroupingOptions {
  /// GOST 27843 §2.10 and ISO 230-2 require at least 5 approaches per position and direction.
  int min_approaches = 5;
  /// Report fewer approaches than min_approaches as a warning instead of an error (at least 2
  /// are always needed for a standard deviation).
  bool allow_few_approaches = false;
};

/// Groups the readings and checks them; a failure (kInputInvalid, "source:line: problem") for:
///   - no readings;
///   - the same target, direction and run given twice (names both lines);
///   - target positions that differ between runs (a run has a target that the other runs do not
///     have while it lacks one of theirs);
///   - a direction present at some positions but missing at others ("missing direction");
///   - fewer than min_approaches (or fewer than 2) approaches at a position and direction.
/// Readings of one run missing at a position are reported as warnings when enough remain.
/// Data with only one direction throughout are accepted (unidirectional evaluation).
Expected<PositioningSet> GroupReadings(const PositioningData& data, const GroupingOptions& options);

}  // namespace volcomp::metrology
