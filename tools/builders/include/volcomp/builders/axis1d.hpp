// 1-D axis tables (AXIS1D) from the mean deviations of a positioning test (model/positioning.hpp).
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

#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/positioning.hpp"

namespace volcomp::builders {

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

/// kInvalidArgument with the reason: too few positions, a reverse mode without reverse data, a
/// first position that is not a whole number of steps.
Expected<Axis1dTable> BuildAxis1d(const model::PositioningData& data, const Axis1dOptions& options);

}  // namespace volcomp::builders
