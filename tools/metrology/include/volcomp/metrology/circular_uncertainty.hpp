// Measurement uncertainty of an ISO 230-4 circular test (circular.hpp), U at k = 2, by the same
// simplified budget as the positioning test (positioning_uncertainty.hpp; ISO/TR 230-9
// conventions, a full range R giving U = 0.6·R). ISO 230-4's own uncertainty annex was not
// available; the terms follow from what each figure is:
//   G, G(b), H   ranges of radial readings about a fitted centre (or between the two paths at one
//                angle): an error common to every reading (the calibrator's length, the bar's or
//                the machine's uniform expansion) cancels; what remains is the reading itself
//                (the sensor's calibration U) and the drift during the runs (0.6·E_VE):
//                U_shape = √(U_reading² + U_env²).
//   F max, F min against the nominal radius R: every term of the positioning budget over L = R,
//                the instrument term being √(U_reading² + U_calibrator²) (the calibrator sets the
//                absolute length), no cosine term.
// Units: µm, mm. Without a nominal radius (a file of deviations and no preamble
// nominal_radius_mm) F gets no U, with a warning.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/positioning_uncertainty.hpp"
#include "volcomp/metrology/test_conditions.hpp"

namespace volcomp::metrology {

struct CircularUncertaintyInputs {
  /// instrument_u_um = U (k = 2) of one radial reading; material temperature, thermometer,
  /// expansion coefficient and drift as in the positioning budget (ppm and misalignment unused).
  PositioningUncertaintyInputs reading;
  std::optional<double> calibrator_u_um;  // U (k = 2) of the calibrator's length
};

struct CircularUncertainty {
  double shape_u_um = 0.0;  // U of G, G(b), H
  std::vector<UncertaintyTerm> shape_terms;
  std::optional<PositioningUncertainty> radial;  // F's budget over the nominal radius, if known
};

/// `in` with what it leaves unset from the preamble: the positioning keys and calibrator_u_um.
Expected<CircularUncertaintyInputs> CompleteFromPreamble(CircularUncertaintyInputs in,
                                                         const TestConditions& conditions);

/// The budget, or nullopt with a warning when the reading's U is not stated. radius_mm ≤ 0: not
/// known (F without U, warned). kInvalidArgument for a negative or non-finite input, or a
/// length-only input (instrument ppm, misalignment) that the circular test cannot use.
Expected<std::optional<CircularUncertainty>> CircularU(const CircularUncertaintyInputs& in,
                                                       double radius_mm,
                                                       std::vector<std::string>* warnings);

}  // namespace volcomp::metrology
