// The plausibility check of a deviation column's unit (issue 25 item 3): a column of µm whose
// values are all below 0.1 µm in magnitude, but not all zero, is almost surely mm typed as µm
// (0.012 mm = 12 µm written under deviation_um evaluates silently to a few hundredths of a µm).
// No machine axis positions to better than 0.1 µm everywhere along its travel, so such a column is
// refused unless the caller accepts it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::datasets {

/// Below this magnitude (µm) every value of a column is implausible.
inline constexpr double kImplausibleMicrometres = 0.1;

/// A failure (kInputInvalid) "source:line: column "NAME": every value is below 0.1 µm ... the
/// largest is V (line L) ...; FIX, or --accept-units" when every value of `values` is below
/// kImplausibleMicrometres in magnitude and one is not zero. `lines[k]` is the line of value k
/// (may be empty: no line per value).
Outcome CheckMicrometreColumn(const std::string& source,
                              std::size_t line,
                              const std::string& column,
                              const std::vector<double>& values,
                              const std::vector<std::size_t>& lines,
                              const std::string& fix);

}  // namespace volcomp::datasets
