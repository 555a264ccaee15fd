// The result of a bidirectional positioning test (ISO 230-2 / GOST 27843-88) as a 1-D error model
// of one axis: the mean positional deviations x̄↑_j (approach in the positive direction) and x̄↓_j
// (negative) per target position P_j, deviation = actual − target.
// Units: positions mm (deg on a rotary axis), deviations µm (arcsec).
#pragma once

#include <string>
#include <vector>

namespace volcomp::model {

struct PositioningData {
  bool rotary = false;
  std::vector<double> position;       // mm or deg, increasing
  std::vector<double> dev_forward;    // µm or arcsec
  std::vector<double> dev_reverse;    // empty when only one direction was measured
  std::vector<std::string> warnings;  // from the checks of the raw readings (outliers, ...)
};

}  // namespace volcomp::model
