// Plausibility checks of positioning readings that warn without stopping the evaluation: a
// magnitude implausible for the axis (likely a unit slip; one warning per file naming the column
// and the likely unit) and Grubbs outliers per target and direction (named with line, run and G).
// Bounds and test: docs/metrology.md "Input checks". A reading that cannot be one at all is
// refused by the reader (positioning_csv.hpp).
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
