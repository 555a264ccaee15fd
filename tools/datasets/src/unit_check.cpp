// The plausibility check of a µm column (unit_check.hpp).
#include "unit_check.hpp"

#include <cmath>
#include <sstream>

namespace volcomp::datasets {

Outcome CheckMicrometreColumn(const std::string& source,
                              std::size_t line,
                              const std::string& column,
                              const std::vector<double>& values,
                              const std::vector<std::size_t>& lines,
                              const std::string& fix) {
  std::size_t largest = 0;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!(std::fabs(values[k]) < kImplausibleMicrometres)) return Outcome::Ok();
    if (std::fabs(values[k]) > std::fabs(values[largest])) largest = k;
  }
  if (values.empty() || values[largest] == 0.0) return Outcome::Ok();  // all zero: a real axis?
  std::ostringstream s;
  s << source << ":" << line << ": column \"" << column << "\": every value is below "
    << kImplausibleMicrometres << " µm in magnitude (the largest is " << values[largest] << " µm";
  if (largest < lines.size()) s << " on line " << lines[largest];
  s << "): these look like mm typed as µm; " << fix
    << ", or give --accept-units if the axis really is this good";
  return Fail(Error::kInputInvalid, s.str());
}

}  // namespace volcomp::datasets
