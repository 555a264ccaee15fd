// Plausibility checks of positioning readings that warn without stopping the evaluation (a
// reading that cannot be a measurement at all is refused by the reader, positioning_csv.hpp):
//
//  - implausible magnitude: a linear-axis deviation above the larger of 1 mm and 1 µm per mm of
//    travel (0.1 %), or a rotary deviation above 1° (3600″), is far beyond the errors of a
//    machine tool and usually a unit slip (µm readings in a `deviation_mm` column); a file whose
//    readings are all below 0.01 µm (0.001″) but not all zero likely holds mm in a µm column.
//    One warning per file, naming the column, the first line, the count, and the likely unit;
//  - outliers: Grubbs' test (two-sided, 99 %, statistics.hpp GrubbsCritical) on the approaches
//    of each target and direction with n ≥ 3; the most extreme reading of a series above the
//    critical value is named with its line, run and G. One pass per series (a second outlier
//    in the same series is masked by the first; the warning says to check the series).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "volcomp/metrology/positioning_data.hpp"

namespace volcomp::metrology {

struct ReadingCheckOptions {
  /// Axis travel for the magnitude bound; default: the span of the targets.
  std::optional<double> travel;
  /// Significance of Grubbs' test: 0.01 = 99 %.
  double outlier_alpha = 0.01;
};

/// Bound of the implausible-magnitude warning for `kind` and `travel` (mm; ignored for rotary):
/// µm for linear axes, arc-seconds for rotary axes.
double PlausibleDeviationBound(AxisKind kind, double travel);

/// Warnings "source:line: ..." for `data` (as read) and its grouped `set`.
std::vector<std::string> CheckReadings(const PositioningData& data,
                                       const PositioningSet& set,
                                       const ReadingCheckOptions& options);

}  // namespace volcomp::metrology
