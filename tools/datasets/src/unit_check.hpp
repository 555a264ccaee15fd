// The plausibility check of a deviation column's unit (issue 25 item 3): a column of µm whose
// values are all below 0.1 µm in magnitude, but not all zero, is almost surely mm typed as µm
// (0.012 mm = 12 µm written under deviation_um evaluates silently to a few hundredths of a µm).
// No machine axis positions to better than 0.1 µm everywhere along its travel, so such a column is
// refused unless the caller accepts it. A column of µin (CSV deviation_uin, an .rtl read with
// --rtl-units in) gets the same physical threshold, 0.1 µm = 3.937 µin: inches typed as µin
// (0.0004 in = 10 µm written as 0.0004 µin) lie a million times below it, as mm typed as µm lie
// a thousand times below 0.1 µm.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/inch.hpp"

namespace volcomp::datasets {

/// Below this magnitude (µm) every value of a column is implausible.
inline constexpr double kImplausibleMicrometres = 0.1;

/// A column's micro-unit and the whole unit it is mistaken for.
struct MicroUnit {
  const char* name;    // "µm"
  const char* whole;   // "mm": what such a column holds when typed in the wrong unit
  double um_per_unit;  // 1 µin = 0.0254 µm exactly
};
inline constexpr MicroUnit kMicrometre{"µm", "mm", 1.0};
inline constexpr MicroUnit kMicroinch{"µin", "inches", metrology::kMicrometresPerMicroinch};

/// A failure (kInputInvalid) "source:line: column "NAME": every value is below 0.1 µm ... the
/// largest is V UNIT (line L) ...; FIX, or --accept-units" when every value of `values_um` (µm,
/// converted from `unit`) is below kImplausibleMicrometres in magnitude and one is not zero.
/// `lines[k]` is the line of value k (may be empty: no line per value).
Outcome CheckMicroColumn(const std::string& source,
                         std::size_t line,
                         const std::string& column,
                         const MicroUnit& unit,
                         const std::vector<double>& values_um,
                         const std::vector<std::size_t>& lines,
                         const std::string& fix);

}  // namespace volcomp::datasets
