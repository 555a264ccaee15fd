// ISO 230-7 evaluation of an error-motion record: the profiles formed from the sensor channels
// (radial for a rotating or fixed sensitive direction, tilt, axial, face), each analysed with
// AnalyseErrorMotion() and reported about its preferred centre of Table 1, and the Donaldson
// reversal; profiles and clauses in docs/metrology.md. Options the channels cannot serve are
// failures naming the file. With a direction column holding both senses, the values are given
// pooled and per direction (the standard does not say whether CW and CCW runs are pooled); the
// number of revolutions is checked against the rule for the kind of axis (a warning naming the
// clause); each value carries its Annex F uncertainty when the instrument is stated.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "volcomp/metrology/error_motion.hpp"
#include "volcomp/metrology/error_motion_uncertainty.hpp"
#include "volcomp/metrology/polar_fit.hpp"
#include "volcomp/metrology/rotary_data.hpp"
#include "volcomp/metrology/test_conditions.hpp"

namespace volcomp::metrology {

enum class SensitiveDirection { kRotating, kFixed };

/// What turns: the number-of-revolutions rules differ (5.3.2.2 footnote; 6.2.2, 6.3.2, 6.4.2).
enum class RotaryAxisKind { kSpindle, kTable, kHead };
const char* RotaryAxisKindName(RotaryAxisKind kind);  // "spindle", "table", "head"

struct RotaryOptions {
  SensitiveDirection sensitive = SensitiveDirection::kRotating;
  double fsd_angle_deg = 0.0;              // θ_f for a fixed sensitive direction
  std::optional<double> tilt_distance_mm;  // L between the planes of x/y and x2/y2
  std::optional<double> face_radius_mm;    // R of the face channel
  CentreSelection centres;                 // MRS, MIC, MCC besides PC and LSC
  RotaryAxisKind axis = RotaryAxisKind::kSpindle;
  bool static_test = false;                  // annex E: stops turned by hand, readings averaged
  ErrorMotionUncertaintyInputs uncertainty;  // annex F (none stated: no U, a warning)
};

struct RotaryMeasurement {
  std::string name;     // "radial", "radial, plane 2", "tilt", "axial", "face", ...
  std::string key;      // JSON key: radial, radial_plane2, tilt, axial, face, tilt_axial_face
  std::string unit;     // "µm" or "µrad"
  std::string profile;  // how the profile was formed, with the clause
  CentreKind preferred = CentreKind::kLsc;  // Table 1
  bool report_fundamental = false;          // axial and face
  ErrorMotion motion;
  std::optional<ErrorMotionUncertainty> u;  // in `unit`, when the instrument is stated
};

/// The values of the revolutions turned one way.
struct RotaryDirectionResult {
  RotationSense sense = RotationSense::kCw;
  int revolutions = 0;
  std::vector<RotaryMeasurement> measurements;
};

/// Positive and negative fundamentals of z = ΔX + iΔY of the synchronous radial motion:
/// c₊ = (1/N) Σ z e^{−iθ}, c₋ = (1/N) Σ z e^{+iθ} (equally spaced angles).
struct RadialFundamentals {
  double positive_um = 0.0;  // |c₊|: symmetric part, incl. artefact eccentricity
  double positive_phase_deg = 0.0;
  double negative_um = 0.0;  // |c₋|: structural asymmetry δ (A.9, A.10)
  double negative_phase_deg = 0.0;
};

struct RotaryEvaluation {
  std::string source;
  TestConditions conditions;  // of the main file's preamble (set by the caller)
  int revolutions = 0;
  int samples_per_revolution = 0;
  RotaryOptions options;
  int revolutions_cw = 0;  // with a direction column
  int revolutions_ccw = 0;
  std::vector<RotaryMeasurement> measurements;      // all revolutions (pooled when both senses)
  std::vector<RotaryDirectionResult> by_direction;  // CW then CCW, when both are present
  std::optional<RadialFundamentals> radial_fundamentals;
  std::vector<std::string> warnings;
};

/// A failure (kInputInvalid) naming the file when the options need channels the file lacks
/// (e.g. a rotating sensitive direction without both x_um and y_um). Tilt needs
/// options.tilt_distance_mm; without it x2/y2 give the second radial plane and a warning.
Expected<RotaryEvaluation> EvaluateRotary(const RotaryRecord& record, const RotaryOptions& options);

/// Sign conventions of the second record of a Donaldson reversal (ISO 230-7 annex B).
enum class ReversalProcedure {
  kP,  // same sign convention: T2P = P − S (B.2)
  kS,  // sign reversed:        T2S = −P + S (B.4)
};

struct ReversalResult {
  std::vector<double> angle_deg;
  std::vector<double> artefact;  // P(C), roundness of the artefact, µm (B.3)
  std::vector<double> spindle;   // S(C), radial error motion, µm (B.5)
  double artefact_value = 0.0;   // roundness of P about its LSC
  double spindle_value = 0.0;    // synchronous value of S about its LSC
  CentreFit artefact_lsc;
  CentreFit spindle_lsc;
};

/// Donaldson reversal (ISO 230-7 annex B) from the synchronous profiles T1 and T2 recorded in
/// setups 1 and 2 at the same angles: procedure P gives P = (T1 + T2P)/2, S = (T1 − T2P)/2;
/// procedure S gives S = (T1 + T2S)/2, P = (T1 − T2S)/2. A failure (kInvalidArgument) for
/// profiles of different lengths.
Expected<ReversalResult> DonaldsonReversal(const std::vector<double>& angle_deg,
                                           const std::vector<double>& t1,
                                           const std::vector<double>& t2,
                                           ReversalProcedure procedure);

/// The reversal of `channel` (e.g. "x_um") from its synchronous profiles in the two setups'
/// records; a failure (kInputInvalid, naming the file) when setup 2 is sampled at other angles than
/// setup 1 or a record lacks the channel.
Expected<ReversalResult> DonaldsonReversal(const RotaryRecord& setup1,
                                           const RotaryRecord& setup2,
                                           const std::string& channel,
                                           ReversalProcedure procedure);

}  // namespace volcomp::metrology
