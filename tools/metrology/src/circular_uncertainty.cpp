// Simplified uncertainty budget of a circular test.
#include "volcomp/metrology/circular_uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "volcomp/report/format.hpp"

namespace volcomp::metrology {

Expected<CircularUncertaintyInputs> CompleteFromPreamble(CircularUncertaintyInputs in,
                                                         const TestConditions& conditions) {
  VOLCOMP_TRY_ASSIGN(in.reading, CompleteFromPreamble(in.reading, conditions));
  if (!in.calibrator_u_um) {
    VOLCOMP_TRY_ASSIGN(in.calibrator_u_um, conditions.Number("calibrator_u_um"));
  }
  return in;
}

Expected<std::optional<CircularUncertainty>> CircularU(const CircularUncertaintyInputs& in,
                                                       double radius_mm,
                                                       std::vector<std::string>* warnings) {
  if (in.reading.instrument_ppm || in.reading.misalignment_mm != 0.0) {
    return Fail(Error::kInvalidArgument,
                "a circular test's instrument is stated as the U of one radial reading "
                "(--instrument-u-um); a ppm accuracy or a beam misalignment does not apply");
  }
  const double calibrator = in.calibrator_u_um.value_or(0.0);
  if (!(std::isfinite(calibrator) && calibrator >= 0.0)) {
    return Fail(Error::kInvalidArgument, "the calibrator's U must be finite and not negative");
  }
  if (!in.reading.instrument_u_um) {
    warnings->push_back(
        "no measurement uncertainty: state the U (k = 2) of one radial reading "
        "(--instrument-u-um or preamble instrument_u_um, from the ballbar's calibration)");
    return std::optional<CircularUncertainty>();
  }
  const double reading = *in.reading.instrument_u_um;
  const double drift = in.reading.drift_range_um.value_or(0.0);
  if (!(std::isfinite(reading) && reading >= 0.0 && std::isfinite(drift) && drift >= 0.0)) {
    return Fail(Error::kInvalidArgument, "uncertainty inputs must be finite and not negative");
  }
  CircularUncertainty u;
  const double env = 0.6 * drift;  // U (k = 2) of a full range, rectangular
  u.shape_terms = {{"reading", reading, "calibration U " + report::FormatNumber(reading) + " µm"},
                   {"environment", env, EnvironmentBasis(drift, in.reading.drift_source)}};
  u.shape_u_um = std::hypot(reading, env);
  if (!in.reading.drift_range_um) {
    warnings->push_back(
        "no drift test stated (--drift-range-um or preamble drift_range_um): the environmental "
        "variation term is not included");
  }
  if (radius_mm > 0.0) {
    PositioningUncertaintyInputs radial_in = in.reading;
    radial_in.instrument_u_um = std::hypot(*in.reading.instrument_u_um, calibrator);
    VOLCOMP_TRY_ASSIGN(PositioningUncertainty radial, PositioningU(radial_in, radius_mm));
    radial.terms.front().basis = "reading U " + report::FormatNumber(*in.reading.instrument_u_um) +
                                 " µm and calibrator U " + report::FormatNumber(calibrator) + " µm";
    radial.terms.erase(std::remove_if(radial.terms.begin(), radial.terms.end(),
                                      [](const UncertaintyTerm& t) {
                                        return t.name == "misalignment";  // no beam
                                      }),
                       radial.terms.end());
    for (const auto& n : radial.notes) {
      if (n.find("no drift test") == std::string::npos) warnings->push_back(n);
    }
    u.radial = std::move(radial);
  } else {
    warnings->push_back(
        "F has no U: the nominal radius is not known (radius_mm readings with --radius, or "
        "preamble nominal_radius_mm)");
  }
  return std::optional<CircularUncertainty>(std::move(u));
}

}  // namespace volcomp::metrology
