// ISO 230-7 Annex F uncertainty of error-motion values.
#include "volcomp/metrology/error_motion_uncertainty.hpp"

#include <cmath>
#include <string>

namespace volcomp::metrology {
namespace {

constexpr double kExtremesFactor = 1.4;  // F.7: max and min at different angles, independent

bool Bad(const std::optional<double>& v) { return v && !(std::isfinite(*v) && *v >= 0.0); }

}  // namespace

Expected<ErrorMotionUncertainty> ErrorMotionU(const ErrorMotionUncertaintyInputs& in,
                                              int revolutions,
                                              double scale) {
  if (!in.stated()) {
    return Fail(Error::kInvalidArgument,
                "error-motion uncertainty needs the instrument: its calibration U (F.1) or the "
                "maker's error range (F.2)");
  }
  if (in.device_calibration_um && in.device_range_um) {
    return Fail(Error::kInvalidArgument,
                "give the instrument's calibration U (F.1) or its error range (F.2), not both");
  }
  if (Bad(in.device_calibration_um) || Bad(in.device_range_um) || Bad(in.drift_range_um) ||
      Bad(std::optional<double>(in.setup_um))) {
    return Fail(Error::kInvalidArgument, "uncertainty inputs must be finite and not negative");
  }
  if (revolutions < 1 || !(scale > 0.0)) {
    return Fail(Error::kInvalidArgument, "uncertainty needs n >= 1 revolutions and a scale > 0");
  }
  ErrorMotionUncertainty u;
  u.from_calibration = in.device_calibration_um.has_value();
  u.device_basis =
      scale * (u.from_calibration ? *in.device_calibration_um : 0.6 * *in.device_range_um);
  u.setup = scale * in.setup_um;
  u.device = std::hypot(u.device_basis, u.setup);
  u.drift_stated = in.drift_range_um.has_value();
  u.drift_source = in.drift_source;
  u.eve = u.drift_stated ? scale * 0.6 * *in.drift_range_um : 0.0;
  u.revolutions = revolutions;
  const double n = static_cast<double>(revolutions);
  u.single_plot = std::hypot(u.device, u.eve);
  u.synchronous_plot = std::sqrt(u.device * u.device + u.eve * u.eve / n);
  u.literal_f6 = in.literal_f6;
  u.single_value = in.literal_f6 ? std::sqrt(u.single_plot * u.single_plot + u.eve * u.eve / n)
                                 : kExtremesFactor * u.single_plot;
  u.synchronous_value = kExtremesFactor * u.synchronous_plot;
  return u;
}

}  // namespace volcomp::metrology
