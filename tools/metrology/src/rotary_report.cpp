// Text, JSON and HTML output of ISO 230-7 evaluations.
#include "volcomp/metrology/rotary_report.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "json_fields.hpp"
#include "volcomp/metrology/polar_fit.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/polar_chart.hpp"

namespace volcomp::metrology {
namespace {

// "; FILE ..." naming the drift test E_VE came from, or "" (the JSON's drift_source).
std::string DriftSourceText(const tools::JsonValue* source) {
  return source != nullptr ? "; " + source->string : "";
}

using report::FormatFixed;
using tools::JsonValue;

int Decimals(const std::string& unit) { return unit == "µrad" ? 2 : 3; }

JsonValue CentreJson(const CentreValues& v) {
  JsonValue j = JsonValue::Object();
  j.Set("centre_offset_x", v.a);
  j.Set("centre_offset_y", v.b);
  j.Set("synchronous", v.synchronous);
  j.Set("total", v.total);
  j.Set("inner", v.inner);
  j.Set("outer", v.outer);
  return j;
}

JsonValue UncertaintyJson(const std::optional<ErrorMotionUncertainty>& u) {
  if (!u) return JsonValue();
  JsonValue j = JsonValue::Object();
  j.Set("k", 2);
  j.Set("synchronous_value", u->synchronous_value);
  j.Set("single_plot_value", u->single_value);
  j.Set("single_plot_formula", u->literal_f6 ? "F.6 as printed" : "1.4 U_single");
  j.Set("device", u->device);
  j.Set("device_basis", u->device_basis);
  j.Set("device_from", u->from_calibration ? "calibration (F.1)" : "0.6 x error range (F.2)");
  j.Set("setup", u->setup);
  j.Set("drift", u->eve);
  j.Set("drift_stated", u->drift_stated);
  if (!u->drift_source.empty()) j.Set("drift_source", u->drift_source);
  j.Set("revolutions", u->revolutions);
  return j;
}

// The measurements by key; `detail` adds the centres' coordinates, the plots and the profile.
JsonValue MeasurementsJson(const std::vector<RotaryMeasurement>& list, bool detail) {
  JsonValue measurements = JsonValue::Object();
  for (const auto& m : list) {
    const ErrorMotion& em = m.motion;
    JsonValue o = JsonValue::Object();
    o.Set("name", m.name);
    o.Set("unit", m.unit == "µm" ? "um" : "urad");
    o.Set("preferred_centre", CentreName(m.preferred));
    const CentreValues& pref = ValuesAbout(em, m.preferred);
    o.Set("synchronous_value", pref.synchronous);
    o.Set("asynchronous_value", em.asynchronous_value);
    o.Set("total_value", pref.total);
    o.Set("uncertainty", UncertaintyJson(m.u));
    if (detail) {
      o.Set("profile", m.profile);
      o.Set("asynchronous_angle_deg", em.asynchronous_angle_deg);
      o.Set("fundamental_value", em.fundamental_value);
      o.Set("fundamental_angle_deg", em.fundamental_angle_deg);
      o.Set("fundamental_is_axial_value", m.report_fundamental);
      JsonValue about = JsonValue::Object();
      for (const CentreValues* c : ComputedCentres(em))
        about.Set(CentreName(c->kind), CentreJson(*c));
      o.Set("about", std::move(about));
      o.Set("angle_deg", JsonValue::Numbers(em.angle_deg));
      o.Set("synchronous", JsonValue::Numbers(em.synchronous));
    }
    measurements.Set(m.key, std::move(o));
  }
  return measurements;
}

}  // namespace

JsonValue RotaryJson(const RotaryEvaluation& ev, const std::optional<ReversalResult>& reversal) {
  JsonValue j = JsonValue::Object();
  j.Set("command", "evaluate rotary");
  j.Set("standard", "ISO 230-7:2015");
  j.Set("source", ev.source);
  j.Set("conditions", ConditionsJson(ev.conditions));
  j.Set("revolutions", ev.revolutions);
  j.Set("samples_per_revolution", ev.samples_per_revolution);
  j.Set("sensitive_direction",
        ev.options.sensitive == SensitiveDirection::kRotating ? "rotating" : "fixed");
  if (ev.options.sensitive == SensitiveDirection::kFixed) {
    j.Set("fsd_angle_deg", ev.options.fsd_angle_deg);
  }
  JsonValue centres = JsonValue::Array();
  centres.Push("PC");
  centres.Push("LSC");
  if (ev.options.centres.mrs) centres.Push("MRS");
  if (ev.options.centres.mic) centres.Push("MIC");
  if (ev.options.centres.mcc) centres.Push("MCC");
  j.Set("centres", std::move(centres));
  j.Set("axis_kind", RotaryAxisKindName(ev.options.axis));
  j.Set("static_test", ev.options.static_test);
  j.Set("revolutions_cw", ev.revolutions_cw);
  j.Set("revolutions_ccw", ev.revolutions_ccw);
  j.Set("measurements", MeasurementsJson(ev.measurements, true));
  JsonValue by_direction = JsonValue::Array();
  for (const auto& d : ev.by_direction) {
    JsonValue o = JsonValue::Object();
    o.Set("sense", RotationSenseName(d.sense));
    o.Set("revolutions", d.revolutions);
    o.Set("measurements", MeasurementsJson(d.measurements, false));
    by_direction.Push(std::move(o));
  }
  j.Set("by_direction", std::move(by_direction));
  if (ev.radial_fundamentals) {
    const auto& f = *ev.radial_fundamentals;
    JsonValue o = JsonValue::Object();
    o.Set("positive_um", f.positive_um);
    o.Set("positive_phase_deg", f.positive_phase_deg);
    o.Set("negative_um", f.negative_um);
    o.Set("negative_phase_deg", f.negative_phase_deg);
    j.Set("radial_fundamentals", std::move(o));
  } else {
    j.Set("radial_fundamentals", JsonValue());
  }
  if (reversal) {
    JsonValue o = JsonValue::Object();
    o.Set("artefact_roundness_lsc_um", reversal->artefact_value);
    o.Set("spindle_synchronous_lsc_um", reversal->spindle_value);
    o.Set("artefact", JsonValue::Numbers(reversal->artefact));
    o.Set("spindle", JsonValue::Numbers(reversal->spindle));
    j.Set("reversal", std::move(o));
  } else {
    j.Set("reversal", JsonValue());
  }
  JsonValue warnings = JsonValue::Array();
  for (const auto& w : ev.warnings) warnings.Push(w);
  j.Set("warnings", std::move(warnings));
  return j;
}

void WriteRotaryText(std::ostream& out, const JsonValue& ev) {
  out << "ISO 230-7 error motion: " << json::Text(ev, "source") << "\n";
  const JsonValue& conditions = json::At(ev, "conditions");
  if (!conditions.object.empty()) out << "conditions: " << ConditionsText(conditions) << "\n";
  out << json::Integer(ev, "revolutions") << " revolution(s) × "
      << json::Integer(ev, "samples_per_revolution") << " angles; values about";
  const char* sep = " ";
  for (const JsonValue& c : json::At(ev, "centres").array) {
    out << sep << c.string;
    sep = ", ";
  }
  out << "; * marks the preferred centre of Table 1\n";
  out << (json::At(ev, "static_test").boolean ? "static test (annex E) of a " : "axis: ")
      << json::Text(ev, "axis_kind");
  if (json::Integer(ev, "revolutions_cw") + json::Integer(ev, "revolutions_ccw") > 0) {
    out << "; " << json::Integer(ev, "revolutions_cw") << " CW, "
        << json::Integer(ev, "revolutions_ccw") << " CCW revolution(s)";
  }
  out << "\n";
  for (const auto& [key, m] : json::At(ev, "measurements").object) {
    const std::string unit = json::Text(m, "unit") == "um" ? "µm" : "µrad";
    const int d = Decimals(unit);
    const std::string& preferred = json::Text(m, "preferred_centre");
    const JsonValue& about = json::At(m, "about");
    out << "\n"
        << json::Text(m, "name") << " [" << unit << "]: " << json::Text(m, "profile") << "\n";
    auto row = [&](const char* label, const char* field) {
      out << "  " << label;
      for (const auto& [centre, values] : about.object) {
        out << "  " << centre << (centre == preferred ? "*" : " ") << " "
            << FormatFixed(json::Number(values, field), d);
      }
      out << "\n";
    };
    row("synchronous ", "synchronous");
    out << "  asynchronous  " << FormatFixed(json::Number(m, "asynchronous_value"), d)
        << " (max at " << FormatFixed(json::Number(m, "asynchronous_angle_deg"), 1)
        << "°, along rays through PC)\n";
    row("total       ", "total");
    row("inner       ", "inner");
    row("outer       ", "outer");
    out << "  centre offsets from PC [" << unit << "]:";
    sep = " ";
    for (const auto& [centre, values] : about.object) {
      if (centre == "PC") continue;
      out << sep << centre << " (" << FormatFixed(json::Number(values, "centre_offset_x"), d)
          << ", " << FormatFixed(json::Number(values, "centre_offset_y"), d) << ")";
      sep = "; ";
    }
    out << "\n";
    out << "  fundamental "
        << (json::At(m, "fundamental_is_axial_value").boolean ? "axial value (§3.8.5) "
                                                              : "(once per rev) ")
        << FormatFixed(json::Number(m, "fundamental_value"), d) << " " << unit
        << " peak-to-peak at " << FormatFixed(json::Number(m, "fundamental_angle_deg"), 1) << "°"
        << (json::At(m, "fundamental_is_axial_value").boolean
                ? ""
                : " (centring, not an error motion value: ISO 230-7 ignores the fundamental for "
                  "radial and tilt, §3.8.5)")
        << "\n";
    const JsonValue& u = json::At(m, "uncertainty");
    if (!u.is_null()) {
      out << "  U (k = 2, annex F): synchronous values ±"
          << FormatFixed(json::Number(u, "synchronous_value"), d + 1)
          << ", total/inner/outer/asynchronous values ±"
          << FormatFixed(json::Number(u, "single_plot_value"), d + 1) << " " << unit << " ("
          << json::Text(u, "single_plot_formula") << "); device "
          << FormatFixed(json::Number(u, "device_basis"), d + 1) << " from "
          << json::Text(u, "device_from") << ", setup "
          << FormatFixed(json::Number(u, "setup"), d + 1) << ", drift "
          << (json::At(u, "drift_stated").boolean
                  ? FormatFixed(json::Number(u, "drift"), d + 1) + " (0.6 × E_VE, F.3" +
                        DriftSourceText(u.get("drift_source")) + ")"
                  : std::string("not stated"))
          << ", n = " << json::Integer(u, "revolutions") << "\n";
    }
  }
  for (const JsonValue& dir : json::At(ev, "by_direction").array) {
    out << "\n"
        << json::Text(dir, "sense") << " only (" << json::Integer(dir, "revolutions")
        << " revolutions), about the preferred centre:\n";
    for (const auto& entry : json::At(dir, "measurements").object) {
      const JsonValue& m = entry.second;  // (a lambda below uses it: no structured binding)
      const std::string unit = json::Text(m, "unit") == "um" ? "µm" : "µrad";
      const int d = Decimals(unit);
      const JsonValue& u = json::At(m, "uncertainty");
      auto value = [&](const char* field, const char* u_field) {
        return FormatFixed(json::Number(m, field), d) +
               (u.is_null() ? std::string() : " ± " + FormatFixed(json::Number(u, u_field), d));
      };
      out << "  " << json::Text(m, "name") << ": synchronous "
          << value("synchronous_value", "synchronous_value") << ", asynchronous "
          << value("asynchronous_value", "single_plot_value") << ", total "
          << value("total_value", "single_plot_value") << " " << unit << " ("
          << json::Text(m, "preferred_centre") << ")\n";
    }
  }
  const JsonValue& f = json::At(ev, "radial_fundamentals");
  if (!f.is_null()) {
    out << "\nradial 2D fundamentals of ΔX + iΔY: c₊ = "
        << FormatFixed(json::Number(f, "positive_um"), 3) << " µm at "
        << FormatFixed(json::Number(f, "positive_phase_deg"), 1)
        << "° (symmetric, incl. eccentricity), c₋ = "
        << FormatFixed(json::Number(f, "negative_um"), 3) << " µm at "
        << FormatFixed(json::Number(f, "negative_phase_deg"), 1) << "° (asymmetry δ)\n";
  }
  const JsonValue& reversal = json::At(ev, "reversal");
  if (!reversal.is_null()) {
    out << "\nDonaldson reversal (annex B): artefact roundness (LSC) "
        << FormatFixed(json::Number(reversal, "artefact_roundness_lsc_um"), 3)
        << " µm, spindle synchronous radial error motion (LSC) "
        << FormatFixed(json::Number(reversal, "spindle_synchronous_lsc_um"), 3) << " µm\n";
  }
}

namespace {

// The annex F paragraph of one measurement, or what is missing for it.
std::string UncertaintyText(const RotaryMeasurement& m) {
  if (!m.u) return "Uncertainty: not stated (no instrument given; docs/metrology.md).";
  const int d = Decimals(m.unit) + 1;
  const ErrorMotionUncertainty& u = *m.u;
  return "Uncertainty (annex F, k = 2): synchronous values ± " +
         FormatFixed(u.synchronous_value, d) + ", total, inner, outer and asynchronous values ± " +
         FormatFixed(u.single_value, d) + " " + m.unit + " (" +
         (u.literal_f6 ? "F.6 as printed" : "1.4 U_single") + "). Contributors: device " +
         FormatFixed(u.device_basis, d) +
         (u.from_calibration ? " (calibration, F.1)" : " (0.6 × error range, F.2)") + ", setup " +
         FormatFixed(u.setup, d) + ", drift " +
         (u.drift_stated ? FormatFixed(u.eve, d) + " (0.6 × E_VE, F.3" +
                               (u.drift_source.empty() ? "" : "; " + u.drift_source) + ")"
                         : std::string("not stated")) +
         ", n = " + std::to_string(u.revolutions) + " revolutions.";
}

}  // namespace

void AddRotarySections(report::HtmlPage* page,
                       const RotaryEvaluation& ev,
                       const std::optional<ReversalResult>& reversal) {
  page->Paragraph("Source: " + ev.source + "; " + std::to_string(ev.revolutions) +
                  " revolution(s) × " + std::to_string(ev.samples_per_revolution) +
                  " angles. Preferred centres per ISO 230-7 Table 1: radial and tilt LSC, axial "
                  "and face PC. The asynchronous value is measured along rays through PC.");
  AddConditionsSection(page, ev.conditions);
  for (const auto& m : ev.measurements) {
    const ErrorMotion& em = m.motion;
    const int d = Decimals(m.unit);
    page->Heading(2, m.name + " error motion");
    page->Paragraph(m.profile + ".");
    std::vector<std::vector<std::string>> rows;
    for (const CentreValues* c : ComputedCentres(em)) {
      rows.push_back(
          {std::string(CentreName(c->kind)) + (c->kind == m.preferred ? " (preferred)" : ""),
           FormatFixed(c->synchronous, d), FormatFixed(em.asynchronous_value, d),
           FormatFixed(c->total, d), FormatFixed(c->inner, d), FormatFixed(c->outer, d),
           "(" + FormatFixed(c->a, d) + ", " + FormatFixed(c->b, d) + ")"});
    }
    page->Table({"centre", "synchronous", "asynchronous", "total", "inner", "outer",
                 "centre offset " + m.unit},
                rows);
    page->Paragraph(
        m.report_fundamental
            ? "Fundamental axial value (§3.8.5): " + FormatFixed(em.fundamental_value, d) + " " +
                  m.unit + " peak-to-peak."
            : "Once-per-revolution fundamental: " + FormatFixed(em.fundamental_value, d) + " " +
                  m.unit +
                  " peak-to-peak: centring, not an error motion value (ISO 230-7 "
                  "ignores the fundamental for radial and tilt, §3.8.5; the LSC "
                  "centre removes it).");
    page->Paragraph(UncertaintyText(m));
    report::PolarChart pc;
    pc.title = m.name + " (" + m.unit + ")";
    pc.units = m.unit;
    report::PolarTrace cloud;
    cloud.label = "total (all revolutions)";
    cloud.color = "#999999";
    cloud.dots = true;
    for (const auto& rev : em.total) {
      for (std::size_t j = 0; j < rev.size(); ++j) {
        cloud.angle_deg.push_back(em.angle_deg[j]);
        cloud.value.push_back(rev[j] - em.lsc_mean);
      }
    }
    report::PolarTrace sync;
    sync.label = "synchronous";
    sync.color = "#1f5fbf";
    sync.width_px = 1.8;
    sync.angle_deg = em.angle_deg;
    for (double v : em.synchronous) sync.value.push_back(v - em.lsc_mean);
    pc.traces = {cloud, sync};
    const CentreValues& pref = ValuesAbout(em, m.preferred);
    const auto res = ResidualsAbout(em.angle_deg, em.synchronous, pref.a, pref.b);
    double lo = res[0], hi = res[0];
    for (double r : res) lo = std::min(lo, r), hi = std::max(hi, r);
    pc.zones.push_back({std::string("synchronous zone about ") + CentreName(m.preferred), pref.a,
                        pref.b, lo - em.lsc_mean, hi - em.lsc_mean, "#2ca02c"});
    pc.centres.push_back({"PC", 0.0, 0.0, "#000000"});
    pc.centres.push_back({"LSC", em.lsc.a, em.lsc.b, "#d62728"});
    if (em.mrs) pc.centres.push_back({"MRS", em.mrs->a, em.mrs->b, "#ff7f0e"});
    if (em.mic) pc.centres.push_back({"MIC", em.mic->a, em.mic->b, "#9467bd"});
    if (em.mcc) pc.centres.push_back({"MCC", em.mcc->a, em.mcc->b, "#8c564b"});
    page->Figure(pc.Render(),
                 "Polar plot about a base circle (r0 arbitrary): total motion "
                 "(dots), synchronous plot, centres and the two circles of the "
                 "synchronous value about the preferred centre.");
  }
  for (const auto& dir : ev.by_direction) {
    page->Heading(2, std::string(RotationSenseName(dir.sense)) + " only (" +
                         std::to_string(dir.revolutions) + " revolutions)");
    std::vector<std::vector<std::string>> rows;
    for (const auto& m : dir.measurements) {
      const int d = Decimals(m.unit);
      const CentreValues& pref = ValuesAbout(m.motion, m.preferred);
      auto with_u = [&](double v, bool synchronous) {
        if (!m.u) return FormatFixed(v, d);
        return FormatFixed(v, d) + " ± " +
               FormatFixed(synchronous ? m.u->synchronous_value : m.u->single_value, d);
      };
      rows.push_back({m.name + " (" + CentreName(m.preferred) + ")", with_u(pref.synchronous, true),
                      with_u(m.motion.asynchronous_value, false), with_u(pref.total, false),
                      m.unit});
    }
    page->Table({"measurement", "synchronous", "asynchronous", "total", "unit"}, rows);
  }
  if (ev.radial_fundamentals) {
    const auto& f = *ev.radial_fundamentals;
    page->Heading(2, "Radial 2D fundamentals");
    page->Paragraph(
        "c₊ = " + FormatFixed(f.positive_um, 3) + " µm at " + FormatFixed(f.positive_phase_deg, 1) +
        "° (symmetric part, includes artefact eccentricity); c₋ = " +
        FormatFixed(f.negative_um, 3) + " µm at " + FormatFixed(f.negative_phase_deg, 1) +
        "° (structural asymmetry, ISO 230-7 A.9-A.10).");
  }
  if (reversal) {
    page->Heading(2, "Donaldson reversal (annex B)");
    page->Paragraph("Artefact roundness about LSC: " + FormatFixed(reversal->artefact_value, 3) +
                    " µm; spindle synchronous radial error motion about LSC: " +
                    FormatFixed(reversal->spindle_value, 3) + " µm.");
    report::PolarChart pc;
    pc.title = "Reversal: artefact P and spindle S (µm)";
    report::PolarTrace p, s;
    p.label = "artefact P (roundness)";
    p.color = "#8e44ad";
    s.label = "spindle S";
    s.color = "#1f5fbf";
    p.angle_deg = s.angle_deg = reversal->angle_deg;
    for (std::size_t j = 0; j < reversal->angle_deg.size(); ++j) {
      p.value.push_back(reversal->artefact[j] - reversal->artefact_lsc.mean);
      s.value.push_back(reversal->spindle[j] - reversal->spindle_lsc.mean);
    }
    pc.traces = {p, s};
    pc.centres.push_back({"PC", 0.0, 0.0, "#000000"});
    page->Figure(pc.Render(), "Separated artefact form and spindle error motion.");
  }
  if (!ev.warnings.empty()) {
    page->Heading(3, "Warnings");
    page->List(ev.warnings);
  }
}

report::HtmlPage RotaryPage(const RotaryEvaluation& ev,
                            const std::optional<ReversalResult>& reversal) {
  report::HtmlPage page("ISO 230-7 error motion");
  AddRotarySections(&page, ev, reversal);
  return page;
}

}  // namespace volcomp::metrology
