// The plausibility check of a µm or µin column (unit_check.hpp).
#include "unit_check.hpp"

#include <cmath>
#include <sstream>

namespace volcomp::datasets {

Outcome CheckMicroColumn(const std::string& source,
                         std::size_t line,
                         const std::string& column,
                         const MicroUnit& unit,
                         const std::vector<double>& values_um,
                         const std::vector<std::size_t>& lines,
                         const std::string& fix) {
  std::size_t largest = 0;
  for (std::size_t k = 0; k < values_um.size(); ++k) {
    if (!(std::fabs(values_um[k]) < kImplausibleMicrometres)) return Outcome::Ok();
    if (std::fabs(values_um[k]) > std::fabs(values_um[largest])) largest = k;
  }
  if (values_um.empty() || values_um[largest] == 0.0) return Outcome::Ok();  // all zero: real?
  std::ostringstream s;
  s << source << ":" << line << ": column \"" << column << "\": every value is below "
    << kImplausibleMicrometres << " µm";
  if (unit.um_per_unit != 1.0) {
    s << " (" << kImplausibleMicrometres / unit.um_per_unit << " " << unit.name << ")";
  }
  s << " in magnitude (the largest is " << values_um[largest] / unit.um_per_unit << " "
    << unit.name;
  if (largest < lines.size()) s << " on line " << lines[largest];
  s << "): these look like " << unit.whole << " typed as " << unit.name << "; " << fix
    << ", or give --accept-units if the axis really is this good";
  return Fail(Error::kInputInvalid, s.str());
}

}  // namespace volcomp::datasets
