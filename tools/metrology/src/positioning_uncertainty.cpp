// Simplified uncertainty budget of a linear positioning test.
#include "volcomp/metrology/positioning_uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "volcomp/report/format.hpp"

namespace volcomp::metrology {
namespace {

constexpr double kSteelExpansion = 11.5;  // µm/(m·K)
constexpr double kRange = 0.6;  // U (k = 2) of a full range R, rectangular: 2·R/(2√3) ≈ 0.6·R

std::string N(double v) { return report::FormatNumber(v); }

bool Bad(double v) { return !(std::isfinite(v) && v >= 0.0); }

// The budget when its instrument is stated, its notes into `warnings`; otherwise nullopt and a
// warning saying what to state.
template <typename Budget>
Expected<std::optional<PositioningUncertainty>> IfStated(bool stated,
                                                         const char* what_to_state,
                                                         Budget budget,
                                                         std::vector<std::string>* warnings) {
  if (!stated) {
    warnings->push_back(std::string("no measurement uncertainty: ") + what_to_state +
                        " for U at k = 2");
    return std::optional<PositioningUncertainty>();
  }
  VOLCOMP_TRY_ASSIGN(PositioningUncertainty u, budget());
  for (const auto& n : u.notes) warnings->push_back(n);
  return std::optional<PositioningUncertainty>(std::move(u));
}

}  // namespace

Expected<PositioningUncertaintyInputs> CompleteFromPreamble(PositioningUncertaintyInputs in,
                                                            const TestConditions& conditions) {
  for (auto [value, key] : {std::pair{&in.instrument_u_um, "instrument_u_um"},
                            std::pair{&in.instrument_ppm, "instrument_ppm"},
                            std::pair{&in.material_temperature_C, "material temperature C"},
                            std::pair{&in.drift_range_um, "drift_range_um"},
                            std::pair{&in.expansion_um_per_m_K, "expansion_um_per_m_K"},
                            // as a Renishaw .rtl's environment block gives it (ppm/°C)
                            std::pair{&in.expansion_um_per_m_K, "expansion coefficient ppm/C"},
                            std::pair{&in.instrument_u_arcsec, "instrument_u_arcsec"},
                            std::pair{&in.instrument_accuracy_arcsec, "instrument_accuracy_arcsec"},
                            std::pair{&in.drift_range_arcsec, "drift_range_arcsec"}}) {
    if (*value) continue;
    VOLCOMP_TRY_ASSIGN(*value, conditions.Number(key));
  }
  return in;
}

std::string EnvironmentBasis(double drift_range_um, const std::string& source) {
  return "0.6 × E_VE " + N(drift_range_um) + " µm" + (source.empty() ? "" : " (" + source + ")");
}

UncertaintyJsonKeys UncertaintyKeys(AxisKind kind) {
  if (kind == AxisKind::kRotary) return {"span_deg", "span_U_arcsec", "local_U_arcsec", "U_arcsec"};
  return {"length_mm", "length_U_um", "local_U_um", "U_um"};
}

Expected<std::optional<PositioningUncertainty>> LengthUncertainty(
    const PositioningUncertaintyInputs& in, double length_mm, std::vector<std::string>* warnings) {
  return IfStated(
      in.stated(),
      "state the instrument (--instrument-u-um from its calibration certificate or "
      "--instrument-ppm, or the preamble keys instrument_u_um / instrument_ppm)",
      [&] { return PositioningU(in, length_mm); }, warnings);
}

Expected<PositioningUncertainty> PositioningU(const PositioningUncertaintyInputs& in,
                                              double length_mm) {
  if (!in.stated()) {
    return Fail(Error::kInvalidArgument,
                "positioning uncertainty needs the instrument: its calibration U or its stated "
                "accuracy in ppm");
  }
  if (Bad(in.instrument_u_um.value_or(0.0)) || Bad(in.instrument_ppm.value_or(0.0)) ||
      Bad(in.thermometer_range_K) || Bad(in.expansion_um_per_m_K.value_or(0.0)) ||
      Bad(in.expansion_range_um_per_m_K) || Bad(in.misalignment_mm) ||
      Bad(in.drift_range_um.value_or(0.0)) ||
      (in.material_temperature_C && !std::isfinite(*in.material_temperature_C))) {
    return Fail(Error::kInvalidArgument, "uncertainty inputs must be finite and not negative");
  }
  if (!(length_mm > 0.0)) {
    return Fail(Error::kInvalidArgument, "uncertainty needs a measured length > 0");
  }
  PositioningUncertainty u;
  u.span = length_mm;
  const double l_m = length_mm / 1000.0;
  const double cal = in.instrument_u_um.value_or(0.0);
  const double ppm = in.instrument_ppm ? kRange * 2.0 * *in.instrument_ppm * l_m : 0.0;
  std::string basis;
  if (in.instrument_u_um) basis = "calibration U " + N(cal) + " µm";
  if (in.instrument_ppm) {
    basis += std::string(basis.empty() ? "" : " and ") + "0.6 × 2 × " + N(*in.instrument_ppm) +
             " ppm × " + N(l_m) + " m";
  }
  u.terms.push_back({"instrument", std::hypot(cal, ppm), basis});
  const double alpha = in.expansion_um_per_m_K.value_or(kSteelExpansion);
  if (!in.expansion_um_per_m_K) {
    u.notes.push_back(
        "expansion coefficient not stated (--expansion or preamble "
        "expansion_um_per_m_K): steel's 11.5 µm/(m·K) assumed");
  }
  u.terms.push_back(
      {"thermometer", kRange * alpha * l_m * in.thermometer_range_K,
       "0.6 × α " + N(alpha) + " µm/(m·K) × L × R_T " + N(in.thermometer_range_K) + " K"});
  if (in.material_temperature_C) {
    const double dt = std::fabs(*in.material_temperature_C - 20.0);
    u.terms.push_back({"expansion coefficient", kRange * l_m * dt * in.expansion_range_um_per_m_K,
                       "0.6 × L × |" + N(*in.material_temperature_C) + " °C − 20 °C| × R_α " +
                           N(in.expansion_range_um_per_m_K) + " µm/(m·K)"});
  } else {
    u.terms.push_back({"expansion coefficient", 0.0, "not included: no material temperature"});
    u.notes.push_back(
        "material temperature not stated (preamble \"material temperature C\" or "
        "--material-temperature-c): the expansion coefficient's term is not included");
  }
  const double cosine_um = in.misalignment_mm * in.misalignment_mm / (2.0 * length_mm) * 1000.0;
  u.terms.push_back({"misalignment", kRange * cosine_um,
                     "0.6 × d² / 2L with d = " + N(in.misalignment_mm) + " mm"});
  const double env = kRange * in.drift_range_um.value_or(0.0);
  if (in.drift_range_um) {
    u.terms.push_back({"environment", env, EnvironmentBasis(*in.drift_range_um, in.drift_source)});
  } else {
    u.terms.push_back({"environment", 0.0, "not included: no drift test"});
    u.notes.push_back(
        "no drift test stated (--drift-range-um or preamble drift_range_um): the environmental "
        "variation term is not included");
  }
  double sum = 0.0;
  for (const auto& t : u.terms) sum += t.u * t.u;
  u.span_u = std::sqrt(sum);
  u.local_u = std::hypot(cal, env);
  return u;
}

Expected<std::optional<PositioningUncertainty>> AngleUncertainty(
    const PositioningUncertaintyInputs& in, double span_deg, std::vector<std::string>* warnings) {
  return IfStated(
      in.angular_stated(),
      "state the angle reference (--instrument-u-arcsec from its calibration "
      "certificate or --instrument-accuracy-arcsec, or the preamble keys "
      "instrument_u_arcsec / instrument_accuracy_arcsec)",
      [&] { return AngularPositioningU(in, span_deg); }, warnings);
}

Expected<PositioningUncertainty> AngularPositioningU(const PositioningUncertaintyInputs& in,
                                                     double span_deg) {
  if (!in.angular_stated()) {
    return Fail(Error::kInvalidArgument,
                "rotary positioning uncertainty needs the angle reference: its calibration U or "
                "its stated accuracy in arc-seconds");
  }
  if (Bad(in.instrument_u_arcsec.value_or(0.0)) ||
      Bad(in.instrument_accuracy_arcsec.value_or(0.0)) ||
      Bad(in.drift_range_arcsec.value_or(0.0)) || Bad(span_deg)) {
    return Fail(Error::kInvalidArgument, "uncertainty inputs must be finite and not negative");
  }
  PositioningUncertainty u;
  u.kind = AxisKind::kRotary;
  u.span = span_deg;
  const double cal = in.instrument_u_arcsec.value_or(0.0);
  const double acc =
      in.instrument_accuracy_arcsec ? kRange * 2.0 * *in.instrument_accuracy_arcsec : 0.0;
  std::string basis;
  if (in.instrument_u_arcsec) basis = "calibration U " + N(cal) + "″";
  if (in.instrument_accuracy_arcsec) {
    basis += std::string(basis.empty() ? "" : " and ") + "0.6 × 2 × " +
             N(*in.instrument_accuracy_arcsec) + "″";
  }
  const double device = std::hypot(cal, acc);
  u.terms.push_back({"instrument", device, basis});
  for (const char* name : {"thermometer", "expansion coefficient", "misalignment"}) {
    u.terms.push_back({name, 0.0, "none for an angle: a uniform expansion does not change it"});
  }
  const double env = kRange * in.drift_range_arcsec.value_or(0.0);
  if (in.drift_range_arcsec) {
    u.terms.push_back({"environment", env, "0.6 × E_VE " + N(*in.drift_range_arcsec) + "″"});
  } else {
    u.terms.push_back({"environment", 0.0, "not included: no drift test"});
    u.notes.push_back(
        "no drift test stated (--drift-range-arcsec or preamble drift_range_arcsec): the "
        "environmental variation term is not included");
  }
  u.span_u = std::hypot(device, env);
  u.local_u = u.span_u;
  return u;
}

Expected<std::optional<PositioningUncertainty>> AxisUncertainty(
    const PositioningUncertaintyInputs& in,
    AxisKind kind,
    double span,
    std::vector<std::string>* warnings) {
  if (kind == AxisKind::kRotary) {
    if (in.any_length_input()) {
      warnings->push_back(
          "length uncertainty inputs (instrument µm/ppm, material temperature, misalignment, "
          "drift µm) do not apply to a rotary axis: use --instrument-u-arcsec, "
          "--instrument-accuracy-arcsec, --drift-range-arcsec");
    }
    return AngleUncertainty(in, span, warnings);
  }
  if (in.any_angle_input()) {
    warnings->push_back(
        "angle uncertainty inputs (instrument ″, drift ″) do not apply to a linear axis: use "
        "--instrument-u-um or --instrument-ppm and --drift-range-um");
  }
  return LengthUncertainty(in, span, warnings);
}

}  // namespace volcomp::metrology
