// ISO 230-7 evaluation of a rotary-axis or spindle error-motion record: builds the polar
// profiles from the sensor channels (§5.3, §5.4, §6) and analyses each with AnalyseErrorMotion().
//
// Profiles (u in µm unless noted; θ the rotation angle, θ_f the fixed sensitive direction):
//   radial, rotating sensitive direction (RSD), formula (1)/(6): u = ΔX·cos θ + ΔY·sin θ
//   radial, fixed sensitive direction (FSD), formulas (3)/(4):   u = ΔX·cos θ_f + ΔY·sin θ_f
//   tilt (two planes a distance L apart, A.6 / formula (5), §5.3.3 method 2): the radial
//     profile of the difference plane2 − plane1, divided by L; in µrad (= µm/m)
//   tilt from axial and face (A.5): (z − face)/R, µrad
//   axial: u = Δz;  face: u = face channel
// Preferred centres (Table 1): radial and tilt LSC, axial and face PC. The fundamental axial
// value (§3.8.5) is reported for axial and face. For radial data from two sensors, the positive
// and negative fundamentals c₊, c₋ of ΔX + iΔY (A.10, ref. Lu & Jamalian) describe the 2D effect.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "volcomp/metrology/error_motion.hpp"
#include "volcomp/metrology/polar_fit.hpp"
#include "volcomp/metrology/rotary_data.hpp"
#include "volcomp/metrology/test_conditions.hpp"

namespace volcomp::metrology {

enum class SensitiveDirection { kRotating, kFixed };

struct RotaryOptions {
  SensitiveDirection sensitive = SensitiveDirection::kRotating;
  double fsd_angle_deg = 0.0;              // θ_f for a fixed sensitive direction
  std::optional<double> tilt_distance_mm;  // L between the planes of x/y and x2/y2
  std::optional<double> face_radius_mm;    // R of the face channel
  bool min_zone = false;                   // also compute the MZ (MRS) centre and values
};

struct RotaryMeasurement {
  std::string name;     // "radial", "radial, plane 2", "tilt", "axial", "face", ...
  std::string key;      // JSON key: radial, radial_plane2, tilt, axial, face, tilt_axial_face
  std::string unit;     // "µm" or "µrad"
  std::string profile;  // how the profile was formed, with the clause
  CentreKind preferred = CentreKind::kLsc;  // Table 1
  bool report_fundamental = false;          // axial and face
  ErrorMotion motion;
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
  std::vector<RotaryMeasurement> measurements;
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
