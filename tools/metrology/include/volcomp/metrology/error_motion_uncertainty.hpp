// Measurement uncertainty of ISO 230-7 error-motion values (Annex F, after ISO/TR 230-9): expanded
// uncertainties U at k = 2 from the instrument (F.1 calibration certificate, or F.2 0.6 × the
// maker's error range), the setup (artefact roundness and alignment, sensor alignment, combined by
// the user as one U at k = 2, added in quadrature to the device per F.2.2), the environmental
// variation error of a drift test (F.3: U_EVE = 0.6 × E_VE) and the averaging over n revolutions.
//   single plot (total, asynchronous, inner, outer)  U_single = sqrt(U_DEVICE² + U_EVE²)      (F.4)
//   synchronous plot over n revolutions             U_sync   = sqrt(U_DEVICE² + U_EVE²/n)   (F.5)
//   value of a single plot                         1.4 · U_single (two independent extremes)
//   value of the synchronous plot                  1.4 · U_sync                            (F.7)
// F.6 as printed, sqrt(U_single² + U_EVE²/n), contradicts its own argument of two independent
// extremes and F.7 (../shared/reference/iso230-7.md §7 note 32): 1.4 · U_single is the default,
// the printed formula an option that the report names.
// Units: µm for displacements; `scale` converts them into a measurement's own unit (1 for radial,
// axial and face; √2·1000/L_mm for tilt from two sensors L mm apart, µm → µrad).
#pragma once

#include <optional>
#include <string>

#include "volcomp/hosted/expected.hpp"

namespace volcomp::metrology {

struct ErrorMotionUncertaintyInputs {
  std::optional<double> device_calibration_um;  // U_CALIBRATION, k = 2 (F.1)
  std::optional<double> device_range_um;        // R_DEVICE, the maker's error range (F.2)
  double setup_um = 0.0;                        // setup contributors, one U at k = 2
  std::optional<double> drift_range_um;         // E_VE, range of a drift test (F.3)
  std::string drift_source;                     // where E_VE comes from ("" none): the file
  bool literal_f6 = false;                      // F.6 as printed for single-plot values

  /// True when the instrument is stated (the least an uncertainty needs).
  bool stated() const { return device_calibration_um || device_range_um; }
};

struct ErrorMotionUncertainty {
  double device = 0.0;           // U_DEVICE with the setup, in the measurement's unit
  double device_basis = 0.0;     // U_CALIBRATION or 0.6·R_DEVICE before the setup, same unit
  bool from_calibration = true;  // F.1 (else F.2)
  double setup = 0.0;
  double eve = 0.0;  // U_EVE = 0.6·E_VE (0 when no drift test is stated)
  bool drift_stated = false;
  std::string drift_source;        // as given
  int revolutions = 0;             // n
  double single_plot = 0.0;        // F.4
  double synchronous_plot = 0.0;   // F.5
  double single_value = 0.0;       // 1.4·U_single, or F.6 as printed
  double synchronous_value = 0.0;  // F.7
  bool literal_f6 = false;
};

/// kInvalidArgument for: no instrument stated, both F.1 and F.2 given, a negative or non-finite
/// input, n < 1 or scale ≤ 0.
Expected<ErrorMotionUncertainty> ErrorMotionU(const ErrorMotionUncertaintyInputs& in,
                                              int revolutions,
                                              double scale);

}  // namespace volcomp::metrology
