// Mean positional deviations per target and direction (x̄↑_j, x̄↓_j) from the raw readings of a
// positioning test: the input of 1-D axis tables (`volcomp build axis`), computed from the same
// readings, with the same checks and warnings, as `volcomp evaluate positioning`.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/metrology/direction.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology {

struct MeanDeviations {
  AxisKind kind = AxisKind::kLinear;
  std::vector<double> target;     // P_j ascending, mm or degrees
  std::vector<double> mean_up;    // x̄↑_j, µm or arc-seconds
  std::vector<double> mean_down;  // x̄↓_j; empty when the test has ↑ approaches only
  int runs = 0;                   // largest number of approaches per target and direction
  std::vector<std::string> warnings;
};

/// Reads (positioning_csv.hpp), groups and checks (GroupReadings with `grouping`: by default ≥ 5
/// approaches per target and direction, same targets in every run; reading_checks.hpp) and
/// averages. A failure (kInputInvalid) naming the line, also when the test has no ↑ approaches
/// (the forward table needs them).
Expected<MeanDeviations> MeanDeviationsFromCsv(const tools::CsvTable& table,
                                               const GroupingOptions& grouping = GroupingOptions{});

/// The same from readings already read from a file of any format; `whole_line` is the line a
/// failure about the readings as a whole names (a CSV's header, an instrument file's section).
Expected<MeanDeviations> MeanDeviationsFromReadings(const PositioningData& data,
                                                    const GroupingOptions& grouping,
                                                    std::size_t whole_line);

}  // namespace volcomp::metrology
