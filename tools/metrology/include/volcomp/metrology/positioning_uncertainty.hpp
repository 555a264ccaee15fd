// Measurement uncertainty of a linear positioning test (E, A, M, B of ISO 230-2:2014 and A, B of
// GOST 27843-88), U at k = 2, by a simplified budget in the manner of ISO/TR 230-9 (root sum of
// squares of uncorrelated terms; a full error range R of a rectangular distribution gives
// U = 0.6·R; ISO 230-7 F.1–F.3 apply the same conventions). ISO 230-2:2014 Annex A's own equations
// were not available (../shared/reference/thermal-rotary-uncertainty.md §3.2): the terms are those
// of that digest, each with its basis, and the report says the budget is simplified.
//   instrument        U_cal (certificate, k = 2), and/or 0.6·2·a·L for a stated accuracy ±a ppm
//   thermometer       0.6·α·L·R_T          (the material temperature's full error range R_T)
//   expansion coeff.  0.6·L·|T − 20 °C|·R_α (R_α: full plausible range of α)
//   misalignment      0.6·d²/(2L)          (cosine error of a lateral beam walk-off d over L)
//   environment       0.6·E_VE             (range of a drift test, ISO 230-3 / TR 230-9 C.9)
// E, A, M and E↑/E↓/A↑/A↓ span the travel L: U_length = √Σ of all. B and B̄ compare the two
// approach directions at the same target, where the length terms cancel: U_local =
// √(U_cal² + U_env²). Repeatability R is the machine's scatter itself (no term). Units: µm, mm.
//
// A rotary axis (angles in ″, targets in deg) measured against an angle reference (an XR20-type
// rotary calibrator, a polygon and autocollimator, an indexing table): the same conventions with
// the terms that exist for an angle:
//   instrument        U_cal (″, k = 2), and/or 0.6·2·a for a stated accuracy ±a″ (full range 2a)
//   environment       0.6·E_VE            (range of a drift test of the angle reading, ″)
// A uniform expansion of the machine or the reference does not change an angle, so the
// thermometer, expansion-coefficient and cosine terms do not arise (listed as 0 with that basis);
// E, A, M and B all carry U = √(U_cal² + U_env²) (nothing cancels between directions).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/direction.hpp"
#include "volcomp/metrology/test_conditions.hpp"

namespace volcomp::metrology {

struct PositioningUncertaintyInputs {
  std::optional<double> instrument_u_um;         // calibration U (k = 2), length-independent
  std::optional<double> instrument_ppm;          // stated accuracy ±ppm of the measured length
  std::optional<double> material_temperature_C;  // mean material (machine) temperature
  double thermometer_range_K = 0.2;              // full error range R_T of that thermometer
  std::optional<double> expansion_um_per_m_K;    // α; not stated: 11.5 (steel), and a note
  double expansion_range_um_per_m_K = 2.0;       // R_α, the full plausible range of α
  double misalignment_mm = 0.0;                  // lateral beam walk-off d over the length
  std::optional<double> drift_range_um;          // E_VE of a drift test
  std::string drift_source;                      // where E_VE comes from, for the basis ("" none)
  // Rotary axes (angles):
  std::optional<double> instrument_u_arcsec;         // calibration U (k = 2) of the reference
  std::optional<double> instrument_accuracy_arcsec;  // its stated accuracy ±a″
  std::optional<double> drift_range_arcsec;          // E_VE of a drift test of the angle

  bool stated() const { return instrument_u_um || instrument_ppm; }
  bool angular_stated() const { return instrument_u_arcsec || instrument_accuracy_arcsec; }
  bool any_length_input() const {
    return stated() || material_temperature_C || drift_range_um || misalignment_mm != 0.0;
  }
  bool any_angle_input() const { return angular_stated() || drift_range_arcsec; }
};

struct UncertaintyTerm {
  std::string name;   // "instrument", "thermometer", ...
  double u = 0.0;     // U at k = 2, in the budget's unit (µm linear, ″ rotary)
  std::string basis;  // how it was found, with the inputs
};

struct PositioningUncertainty {
  AxisKind kind = AxisKind::kLinear;   // the unit of every U: µm (linear) or ″ (rotary)
  double span = 0.0;                   // the targets' span: mm (linear) or deg (rotary)
  std::vector<UncertaintyTerm> terms;  // every term, also those that are zero
  double span_u = 0.0;                 // U of E, A, M (and the one-direction spans)
  double local_u = 0.0;                // U of B, B̄
  std::vector<std::string> notes;      // inputs not stated and what that leaves out
};

/// The JSON keys of a budget, units in the names: length_mm / length_U_um / local_U_um / U_um
/// for a linear axis, span_deg / span_U_arcsec / local_U_arcsec / U_arcsec for a rotary one.
struct UncertaintyJsonKeys {
  const char* span;
  const char* span_u;
  const char* local_u;
  const char* term_u;
};
UncertaintyJsonKeys UncertaintyKeys(AxisKind kind);

/// The environment term's basis: "0.6 × E_VE 2 µm", with " (source)" when E_VE came from a file.
std::string EnvironmentBasis(double drift_range_um, const std::string& source);

/// `in` with what it leaves unset taken from the readings file's preamble: instrument_u_um,
/// instrument_ppm, "material temperature C" (decimal comma allowed), drift_range_um,
/// instrument_u_arcsec, instrument_accuracy_arcsec, drift_range_arcsec,
/// expansion_um_per_m_K or "expansion coefficient ppm/C" (the .rtl reader's key). A preamble value
/// that is not a number: kInputInvalid naming it.
Expected<PositioningUncertaintyInputs> CompleteFromPreamble(PositioningUncertaintyInputs in,
                                                            const TestConditions& conditions);

/// The budget of a linear test over `length_mm`, or nullopt with a warning in `warnings` when no
/// instrument is stated; the budget's notes also go into `warnings`.
Expected<std::optional<PositioningUncertainty>> LengthUncertainty(
    const PositioningUncertaintyInputs& in, double length_mm, std::vector<std::string>* warnings);

/// kInvalidArgument when no instrument is stated, an input is negative or not finite, or the
/// length is not positive.
Expected<PositioningUncertainty> PositioningU(const PositioningUncertaintyInputs& in,
                                              double length_mm);

/// The budget of a rotary axis's test over `span_deg` (≥ 0: a full-circle test may return to its
/// start), or nullopt with a warning when no angle reference is stated. Length inputs given for
/// a rotary axis are named in a warning (they do not apply).
Expected<std::optional<PositioningUncertainty>> AngleUncertainty(
    const PositioningUncertaintyInputs& in, double span_deg, std::vector<std::string>* warnings);

/// kInvalidArgument when no angle reference is stated or an input is negative or not finite.
Expected<PositioningUncertainty> AngularPositioningU(const PositioningUncertaintyInputs& in,
                                                     double span_deg);

/// The budget for the axis kind (LengthUncertainty or AngleUncertainty); inputs of the other
/// kind are named in a warning.
Expected<std::optional<PositioningUncertainty>> AxisUncertainty(
    const PositioningUncertaintyInputs& in,
    AxisKind kind,
    double span,
    std::vector<std::string>* warnings);

}  // namespace volcomp::metrology
