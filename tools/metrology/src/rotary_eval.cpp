// ISO 230-7 profile construction and evaluation.
#include "volcomp/metrology/rotary_eval.hpp"

#include <cmath>
#include <complex>
#include <sstream>

#include "volcomp/metrology/polar_fit.hpp"
#include "volcomp/tools/math_constants.hpp"

namespace volcomp::metrology {
namespace {

using tools::kPi;

double Rad(double deg) { return deg * kPi / 180.0; }

std::string Num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

const Revolutions* Channel(const RotaryRecord& r, const std::string& name) {
  const auto it = r.channels.find(name);
  return it == r.channels.end() ? nullptr : &it->second;
}

// u[k][j] = fx(θ_j)·X[k][j] + fy(θ_j)·Y[k][j] (either channel may be absent when its factor is 0).
template <typename Fx, typename Fy>
Revolutions Combine(
    const RotaryRecord& rec, const Revolutions* x, const Revolutions* y, Fx fx, Fy fy) {
  const std::size_t k_n = rec.revs.size(), n = rec.angle_deg.size();
  Revolutions u(k_n, std::vector<double>(n, 0.0));
  for (std::size_t k = 0; k < k_n; ++k) {
    for (std::size_t j = 0; j < n; ++j) {
      const double th = rec.angle_deg[j];
      if (x) u[k][j] += fx(th) * (*x)[k][j];
      if (y) u[k][j] += fy(th) * (*y)[k][j];
    }
  }
  return u;
}

Revolutions Difference(const Revolutions& a, const Revolutions& b, double scale) {
  Revolutions d = a;
  for (std::size_t k = 0; k < d.size(); ++k) {
    for (std::size_t j = 0; j < d[k].size(); ++j) d[k][j] = (a[k][j] - b[k][j]) * scale;
  }
  return d;
}

Unexpected<Failure> Refuse(const RotaryRecord& r, const std::string& msg) {
  return Fail(Error::kInputInvalid, r.source + ": " + msg);
}

// The synchronous (revolution-averaged) profile of one channel.
Expected<std::vector<double>> SynchronousChannel(const RotaryRecord& rec,
                                                 const std::string& channel) {
  const auto it = rec.channels.find(channel);
  if (it == rec.channels.end()) {
    return Refuse(rec, "no column \"" + channel + "\" for the reversal");
  }
  std::vector<double> s(rec.angle_deg.size(), 0.0);
  for (const auto& rev : it->second) {
    for (std::size_t j = 0; j < s.size(); ++j) s[j] += rev[j];
  }
  for (double& v : s) v /= static_cast<double>(it->second.size());
  return s;
}

// The measurements of `rec` (every revolution in it) into ev->measurements, with warnings.
Outcome EvaluateMeasurements(const RotaryRecord& rec,
                             const RotaryOptions& o,
                             RotaryEvaluation* out) {
  RotaryEvaluation& ev = *out;
  const bool rsd = o.sensitive == SensitiveDirection::kRotating;
  const double cf = std::cos(Rad(o.fsd_angle_deg)), sf = std::sin(Rad(o.fsd_angle_deg));
  const bool need_x = rsd || std::fabs(cf) > 1e-12;
  const bool need_y = rsd || std::fabs(sf) > 1e-12;
  // µm terms of the uncertainty into the measurement's unit: 1, or for a tilt from two sensors
  // `distance_mm` apart √2·1000/distance (µm → µrad).
  auto add = [&](std::string name, std::string key, std::string unit, std::string profile,
                 CentreKind preferred, bool fundamental, const Revolutions& u,
                 double u_scale = 1.0) -> Outcome {
    RotaryMeasurement m;
    if (o.uncertainty.stated()) {
      VOLCOMP_TRY_ASSIGN(m.u, ErrorMotionU(o.uncertainty, static_cast<int>(u.size()), u_scale));
    }
    m.name = std::move(name);
    m.key = std::move(key);
    m.unit = std::move(unit);
    m.profile = std::move(profile);
    m.preferred = preferred;
    m.report_fundamental = fundamental;
    VOLCOMP_TRY_ASSIGN(m.motion, AnalyseErrorMotion(rec.angle_deg, u, o.centres));
    ev.measurements.push_back(std::move(m));
    return Outcome::Ok();
  };
  auto radial_profile = [&](const Revolutions* x, const Revolutions* y) {
    if (rsd) {
      return Combine(
          rec, x, y, [](double th) { return std::cos(Rad(th)); },
          [](double th) { return std::sin(Rad(th)); });
    }
    return Combine(
        rec, need_x ? x : nullptr, need_y ? y : nullptr, [cf](double) { return cf; },
        [sf](double) { return sf; });
  };
  const std::string mode =
      rsd ? "rotating sensitive direction, u = ΔX·cos θ + ΔY·sin θ (ISO 230-7 formula (1))"
          : "fixed sensitive direction at θ_f = " + Num(o.fsd_angle_deg) +
                "°, u = ΔX·cos θ_f + ΔY·sin θ_f (formulas (3), (4))";

  const Revolutions* x = Channel(rec, "x_um");
  const Revolutions* y = Channel(rec, "y_um");
  const Revolutions* x2 = Channel(rec, "x2_um");
  const Revolutions* y2 = Channel(rec, "y2_um");
  const Revolutions* z = Channel(rec, "z_um");
  const Revolutions* face = Channel(rec, "face_um");
  const bool radial1 = x || y;
  const bool radial2 = x2 || y2;
  auto check_plane = [&](const Revolutions* px, const Revolutions* py, const char* xn,
                         const char* yn) -> Outcome {
    if (need_x && !px) {
      return Refuse(rec, std::string(rsd ? "a rotating sensitive direction" : "this θ_f") +
                             " needs column " + xn);
    }
    if (need_y && !py) {
      return Refuse(rec, std::string(rsd ? "a rotating sensitive direction" : "this θ_f") +
                             " needs column " + yn);
    }
    return Outcome::Ok();
  };
  if (radial1) {
    VOLCOMP_TRY(check_plane(x, y, "x_um", "y_um"));
    VOLCOMP_TRY(add("radial", "radial", "µm", mode, CentreKind::kLsc, false, radial_profile(x, y)));
  }
  if (radial2) {
    if (!radial1) return Refuse(rec, "x2_um/y2_um (second plane) need x_um/y_um (first plane)");
    VOLCOMP_TRY(check_plane(x2, y2, "x2_um", "y2_um"));
    VOLCOMP_TRY(add("radial, plane 2", "radial_plane2", "µm", mode, CentreKind::kLsc, false,
                    radial_profile(x2, y2)));
    if (!o.tilt_distance_mm) {
      ev.warnings.push_back(
          "x2_um/y2_um are present but no tilt distance was given "
          "(--tilt-distance-mm L): tilt is not evaluated");
    }
  }
  if (radial2 && o.tilt_distance_mm) {
    if (!(*o.tilt_distance_mm > 0.0)) return Refuse(rec, "the tilt distance must be positive");
    // µm / mm = mrad; ×1000 gives µrad.
    const double k = 1000.0 / *o.tilt_distance_mm;
    const Revolutions dx = need_x ? Difference(*x2, *x, k) : Revolutions();
    const Revolutions dy = need_y ? Difference(*y2, *y, k) : Revolutions();
    VOLCOMP_TRY(add("tilt", "tilt", "µrad",
                    "(plane 2 − plane 1)/L with L = " + Num(*o.tilt_distance_mm) +
                        " mm, combined as the radial profile (A.6; §5.3.3 method 2; formula (5) "
                        "for a fixed direction)",
                    CentreKind::kLsc, false,
                    radial_profile(need_x ? &dx : nullptr, need_y ? &dy : nullptr),
                    std::sqrt(2.0) * k));
  }
  if (z) {
    VOLCOMP_TRY(
        add("axial", "axial", "µm", "u = Δz (§5.3.4, §5.4.4, §6.2)", CentreKind::kPc, true, *z));
  }
  if (face) {
    VOLCOMP_TRY(
        add("face", "face", "µm",
            "face channel" +
                (o.face_radius_mm ? " at R = " + Num(*o.face_radius_mm) + " mm" : std::string()) +
                " (§3.4.5)",
            CentreKind::kPc, true, *face));
  }
  if (z && face && o.face_radius_mm) {
    if (!(*o.face_radius_mm > 0.0)) return Refuse(rec, "the face radius must be positive");
    VOLCOMP_TRY(add("tilt from axial and face", "tilt_axial_face", "µrad",
                    "(Δz − face)/R with R = " + Num(*o.face_radius_mm) + " mm (A.5)",
                    CentreKind::kLsc, false, Difference(*z, *face, 1000.0 / *o.face_radius_mm),
                    std::sqrt(2.0) * 1000.0 / *o.face_radius_mm));
  }
  if (ev.measurements.empty()) return Refuse(rec, "no channel to evaluate");

  if (x && y) {
    // Synchronous ΔX, ΔY, then the positive and negative fundamentals of ΔX + iΔY.
    const std::size_t n = rec.angle_deg.size();
    const double kk = static_cast<double>(rec.revs.size());
    std::complex<double> cp(0, 0), cm(0, 0);
    for (std::size_t j = 0; j < n; ++j) {
      double sx = 0.0, sy = 0.0;
      for (std::size_t k = 0; k < rec.revs.size(); ++k) {
        sx += (*x)[k][j];
        sy += (*y)[k][j];
      }
      const std::complex<double> zj(sx / kk, sy / kk);
      const double th = Rad(rec.angle_deg[j]);
      cp += zj * std::polar(1.0, -th);
      cm += zj * std::polar(1.0, th);
    }
    cp /= static_cast<double>(n);
    cm /= static_cast<double>(n);
    ev.radial_fundamentals = RadialFundamentals{std::abs(cp), std::arg(cp) * 180.0 / kPi,
                                                std::abs(cm), std::arg(cm) * 180.0 / kPi};
  }

  return Outcome::Ok();
}

std::string Count(int n, const char* what) { return std::to_string(n) + " " + what; }

// The number-of-revolutions rules (digest §5.3): spindles ≥ 20 per speed (5.3.2.2 footnote);
// tables axial 5 CW + 5 CCW (6.2.2), radial and tilt 4 + 4 (6.3.2, 6.4.2); heads and tilting
// tables axial 5 + 5 full-travel cycles, radial and tilt 2 + 2; static tests ≥ 2 revolutions and
// ≥ 8 stops per revolution (E.2).
void CheckRevolutions(const RotaryRecord& rec, const RotaryOptions& o, RotaryEvaluation* ev) {
  const int n = ev->revolutions;
  if (o.static_test) {
    if (n < 2) {
      ev->warnings.push_back(Count(n, "revolution(s)") +
                             ": a static test asks at least 2 (ISO 230-7 E.2)");
    }
    if (ev->samples_per_revolution < 8) {
      ev->warnings.push_back(Count(ev->samples_per_revolution, "stops per revolution") +
                             ": a static test asks at least 8 (ISO 230-7 E.2)");
    }
    return;
  }
  if (ev->samples_per_revolution < 8) {
    ev->warnings.push_back(
        "fewer than 8 angles per revolution: few angles filter out the "
        "higher undulations per revolution (ISO 230-7 A.7.5)");
  }
  if (o.axis == RotaryAxisKind::kSpindle) {
    if (n < 20) {
      ev->warnings.push_back(Count(n, "revolution(s)") +
                             ": ISO 230-7 asks at least 20 revolutions per speed for a spindle "
                             "(5.3.2.2, 5.3.4.2 footnotes)");
    }
    return;
  }
  const bool table = o.axis == RotaryAxisKind::kTable;
  const bool radial = rec.channels.count("x_um") || rec.channels.count("y_um");
  const bool axial = rec.channels.count("z_um") || rec.channels.count("face_um");
  const char* cycles = table ? "revolutions" : "full-travel cycles";
  auto rule = [&](int each, const char* what, const char* clause) {
    if (ev->revolutions_cw >= each && ev->revolutions_ccw >= each) return;
    ev->warnings.push_back(std::to_string(ev->revolutions_cw) + " CW and " +
                           std::to_string(ev->revolutions_ccw) + " CCW " + cycles +
                           (ev->revolutions_cw + ev->revolutions_ccw < n
                                ? " (" +
                                      Count(n - ev->revolutions_cw - ev->revolutions_ccw,
                                            "without a direction; add a direction column") +
                                      ")"
                                : std::string()) +
                           ": ISO 230-7 asks at least " + std::to_string(each) + " CW + " +
                           std::to_string(each) + " CCW for the " + what + " of a " +
                           (table ? "rotary table" : "swivelling head or tilting table") + " (" +
                           clause + ")");
  };
  if (axial) rule(5, "axial error motion", "6.2.2");
  if (radial) rule(table ? 4 : 2, "radial and tilt error motion", "6.3.2, 6.4.2");
}

}  // namespace

const char* RotaryAxisKindName(RotaryAxisKind kind) {
  switch (kind) {
    case RotaryAxisKind::kTable:
      return "table";
    case RotaryAxisKind::kHead:
      return "head";
    case RotaryAxisKind::kSpindle:
      break;
  }
  return "spindle";
}

Expected<RotaryEvaluation> EvaluateRotary(const RotaryRecord& rec, const RotaryOptions& o) {
  RotaryEvaluation ev;
  ev.source = rec.source;
  ev.revolutions = static_cast<int>(rec.revs.size());
  ev.samples_per_revolution = static_cast<int>(rec.angle_deg.size());
  ev.options = o;
  for (RotationSense s : rec.rev_sense) {
    ev.revolutions_cw += s == RotationSense::kCw;
    ev.revolutions_ccw += s == RotationSense::kCcw;
  }
  VOLCOMP_TRY(EvaluateMeasurements(rec, o, &ev));
  if (ev.revolutions_cw > 0 && ev.revolutions_ccw > 0) {
    for (RotationSense s : {RotationSense::kCw, RotationSense::kCcw}) {
      RotaryEvaluation one;
      VOLCOMP_TRY(EvaluateMeasurements(RevolutionsTurning(rec, s), o, &one));
      ev.by_direction.push_back({s,
                                 s == RotationSense::kCw ? ev.revolutions_cw : ev.revolutions_ccw,
                                 std::move(one.measurements)});
    }
    ev.warnings.push_back(
        "revolutions in both senses: values are given per direction and pooled; ISO 230-7 does "
        "not say whether CW and CCW runs may be pooled");
  }
  if (!rec.equally_spaced) {
    ev.warnings.push_back(
        "angles are not equally spaced: LSC centres are fitted by least squares; "
        "the c₊/c₋ fundamentals assume equal spacing");
  }
  if (ev.revolutions < 2) {
    ev.warnings.push_back("one revolution only: asynchronous error motion cannot be evaluated");
  }
  CheckRevolutions(rec, o, &ev);
  if (!o.uncertainty.stated()) {
    ev.warnings.push_back(
        "no measurement uncertainty: state the instrument (--instrument-u-um from its "
        "calibration certificate, or --instrument-range-um) and a drift test range "
        "(--drift-range-um) for U at k = 2 (ISO 230-7 annex F)");
  }
  return ev;
}

Expected<ReversalResult> DonaldsonReversal(const std::vector<double>& angle_deg,
                                           const std::vector<double>& t1,
                                           const std::vector<double>& t2,
                                           ReversalProcedure procedure) {
  if (t1.size() != angle_deg.size() || t2.size() != angle_deg.size()) {
    return Fail(Error::kInvalidArgument, "reversal records must have the same angles");
  }
  ReversalResult r;
  r.angle_deg = angle_deg;
  r.artefact.resize(t1.size());
  r.spindle.resize(t1.size());
  for (std::size_t j = 0; j < t1.size(); ++j) {
    if (procedure == ReversalProcedure::kP) {
      r.artefact[j] = 0.5 * (t1[j] + t2[j]);  // (B.3)
      r.spindle[j] = 0.5 * (t1[j] - t2[j]);
    } else {
      r.spindle[j] = 0.5 * (t1[j] + t2[j]);  // (B.5)
      r.artefact[j] = 0.5 * (t1[j] - t2[j]);
    }
  }
  VOLCOMP_TRY_ASSIGN(r.artefact_lsc, FitLeastSquaresCentre(angle_deg, r.artefact));
  VOLCOMP_TRY_ASSIGN(r.spindle_lsc, FitLeastSquaresCentre(angle_deg, r.spindle));
  r.artefact_value = ValueAbout(angle_deg, r.artefact, r.artefact_lsc.a, r.artefact_lsc.b);
  r.spindle_value = ValueAbout(angle_deg, r.spindle, r.spindle_lsc.a, r.spindle_lsc.b);
  return r;
}

Expected<ReversalResult> DonaldsonReversal(const RotaryRecord& setup1,
                                           const RotaryRecord& setup2,
                                           const std::string& channel,
                                           ReversalProcedure procedure) {
  if (setup2.angle_deg.size() != setup1.angle_deg.size()) {
    return Refuse(setup2, "the reversal record has " + std::to_string(setup2.angle_deg.size()) +
                              " angles per revolution, " + setup1.source + " has " +
                              std::to_string(setup1.angle_deg.size()));
  }
  for (std::size_t j = 0; j < setup1.angle_deg.size(); ++j) {
    if (std::abs(setup1.angle_deg[j] - setup2.angle_deg[j]) > 1e-6) {
      return Refuse(setup2, "the reversal record must use the angles of " + setup1.source);
    }
  }
  VOLCOMP_TRY_ASSIGN(const std::vector<double> t1, SynchronousChannel(setup1, channel));
  VOLCOMP_TRY_ASSIGN(const std::vector<double> t2, SynchronousChannel(setup2, channel));
  return DonaldsonReversal(setup1.angle_deg, t1, t2, procedure);
}

}  // namespace volcomp::metrology
