// Text, JSON and HTML output of ISO 230-7 evaluations.
#include "volcomp/metrology/rotary_report.hpp"

#include <algorithm>

#include "volcomp/metrology/polar_fit.hpp"
#include "volcomp/report/format.hpp"
#include "volcomp/report/polar_chart.hpp"

namespace volcomp::metrology {
namespace {

using report::FormatFixed;

int Decimals(const std::string& unit) { return unit == "µrad" ? 2 : 3; }

void JsonCentre(tools::JsonWriter& j, const CentreValues& v) {
  j.begin_object();
  j.key("centre_offset_x").value(v.a);
  j.key("centre_offset_y").value(v.b);
  j.key("synchronous").value(v.synchronous);
  j.key("total").value(v.total);
  j.key("inner").value(v.inner);
  j.key("outer").value(v.outer);
  j.end_object();
}

std::vector<const CentreValues*> Centres(const ErrorMotion& m) {
  std::vector<const CentreValues*> c = {&m.pc, &m.lsc};
  if (m.mz) c.push_back(&*m.mz);
  return c;
}

}  // namespace

void WriteRotaryText(std::ostream& out,
                     const RotaryEvaluation& ev,
                     const std::optional<ReversalResult>& reversal) {
  out << "ISO 230-7 error motion: " << ev.source << "\n";
  if (!ev.conditions.empty()) out << "conditions: " << ConditionsText(ev.conditions) << "\n";
  out << ev.revolutions << " revolution(s) × " << ev.samples_per_revolution
      << " angles; values about PC, LSC" << (ev.options.min_zone ? ", MZ" : "")
      << "; * marks the preferred centre of Table 1\n";
  for (const auto& m : ev.measurements) {
    const int d = Decimals(m.unit);
    const ErrorMotion& em = m.motion;
    out << "\n" << m.name << " [" << m.unit << "]: " << m.profile << "\n";
    auto row = [&](const char* label, double CentreValues::*field) {
      out << "  " << label;
      for (const CentreValues* c : Centres(em)) {
        out << "  " << CentreName(c->kind) << (c->kind == m.preferred ? "*" : " ") << " "
            << FormatFixed((*c).*field, d);
      }
      out << "\n";
    };
    row("synchronous ", &CentreValues::synchronous);
    out << "  asynchronous  " << FormatFixed(em.asynchronous_value, d) << " (max at "
        << FormatFixed(em.asynchronous_angle_deg, 1) << "°, along rays through PC)\n";
    row("total       ", &CentreValues::total);
    row("inner       ", &CentreValues::inner);
    row("outer       ", &CentreValues::outer);
    out << "  LSC centre offset (" << FormatFixed(em.lsc.a, d) << ", " << FormatFixed(em.lsc.b, d)
        << ") " << m.unit;
    if (em.mz) {
      out << "; MZ centre offset (" << FormatFixed(em.mz->a, d) << ", " << FormatFixed(em.mz->b, d)
          << ")";
    }
    out << "\n";
    out << "  fundamental " << (m.report_fundamental ? "axial value (§3.8.5) " : "(once per rev) ")
        << FormatFixed(em.fundamental_value, d) << " " << m.unit << " peak-to-peak at "
        << FormatFixed(em.fundamental_angle_deg, 1) << "°\n";
  }
  if (ev.radial_fundamentals) {
    const auto& f = *ev.radial_fundamentals;
    out << "\nradial 2D fundamentals of ΔX + iΔY: c₊ = " << FormatFixed(f.positive_um, 3)
        << " µm at " << FormatFixed(f.positive_phase_deg, 1) << "° (symmetric, incl. eccentricity)"
        << ", c₋ = " << FormatFixed(f.negative_um, 3) << " µm at "
        << FormatFixed(f.negative_phase_deg, 1) << "° (asymmetry δ)\n";
  }
  if (reversal) {
    out << "\nDonaldson reversal (annex B): artefact roundness (LSC) "
        << FormatFixed(reversal->artefact_value, 3) << " µm, spindle synchronous radial error "
        << "motion (LSC) " << FormatFixed(reversal->spindle_value, 3) << " µm\n";
  }
}

void WriteRotaryJson(tools::JsonWriter& j,
                     const RotaryEvaluation& ev,
                     const std::optional<ReversalResult>& reversal) {
  j.begin_object();
  j.key("command").value("evaluate rotary");
  j.key("standard").value("ISO 230-7:2015");
  j.key("source").value(ev.source);
  WriteConditionsJson(j, ev.conditions);
  j.key("revolutions").value(ev.revolutions);
  j.key("samples_per_revolution").value(ev.samples_per_revolution);
  j.key("sensitive_direction")
      .value(ev.options.sensitive == SensitiveDirection::kRotating ? "rotating" : "fixed");
  if (ev.options.sensitive == SensitiveDirection::kFixed) {
    j.key("fsd_angle_deg").value(ev.options.fsd_angle_deg);
  }
  j.key("measurements").begin_object();
  for (const auto& m : ev.measurements) {
    const ErrorMotion& em = m.motion;
    j.key(m.key).begin_object();
    j.key("name").value(m.name);
    j.key("unit").value(m.unit == "µm" ? "um" : "urad");
    j.key("profile").value(m.profile);
    j.key("preferred_centre").value(CentreName(m.preferred));
    const CentreValues& pref = ValuesAbout(em, m.preferred);
    j.key("synchronous_value").value(pref.synchronous);
    j.key("asynchronous_value").value(em.asynchronous_value);
    j.key("asynchronous_angle_deg").value(em.asynchronous_angle_deg);
    j.key("total_value").value(pref.total);
    j.key("fundamental_value").value(em.fundamental_value);
    j.key("fundamental_angle_deg").value(em.fundamental_angle_deg);
    j.key("about").begin_object();
    for (const CentreValues* c : Centres(em)) {
      j.key(CentreName(c->kind));
      JsonCentre(j, *c);
    }
    j.end_object();
    j.key("angle_deg").begin_array();
    for (double a : em.angle_deg) j.value(a);
    j.end_array();
    j.key("synchronous").begin_array();
    for (double v : em.synchronous) j.value(v);
    j.end_array();
    j.end_object();
  }
  j.end_object();
  j.key("radial_fundamentals");
  if (ev.radial_fundamentals) {
    const auto& f = *ev.radial_fundamentals;
    j.begin_object();
    j.key("positive_um").value(f.positive_um);
    j.key("positive_phase_deg").value(f.positive_phase_deg);
    j.key("negative_um").value(f.negative_um);
    j.key("negative_phase_deg").value(f.negative_phase_deg);
    j.end_object();
  } else {
    j.null();
  }
  j.key("reversal");
  if (reversal) {
    j.begin_object();
    j.key("artefact_roundness_lsc_um").value(reversal->artefact_value);
    j.key("spindle_synchronous_lsc_um").value(reversal->spindle_value);
    j.key("artefact").begin_array();
    for (double v : reversal->artefact) j.value(v);
    j.end_array();
    j.key("spindle").begin_array();
    for (double v : reversal->spindle) j.value(v);
    j.end_array();
    j.end_object();
  } else {
    j.null();
  }
  j.key("warnings").begin_array();
  for (const auto& w : ev.warnings) j.value(w);
  j.end_array();
  j.end_object();
}

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
    for (const CentreValues* c : Centres(em)) {
      rows.push_back(
          {std::string(CentreName(c->kind)) + (c->kind == m.preferred ? " (preferred)" : ""),
           FormatFixed(c->synchronous, d), FormatFixed(em.asynchronous_value, d),
           FormatFixed(c->total, d), FormatFixed(c->inner, d), FormatFixed(c->outer, d),
           "(" + FormatFixed(c->a, d) + ", " + FormatFixed(c->b, d) + ")"});
    }
    page->Table({"centre", "synchronous", "asynchronous", "total", "inner", "outer",
                 "centre offset " + m.unit},
                rows);
    page->Paragraph(std::string(m.report_fundamental ? "Fundamental axial value (§3.8.5): "
                                                     : "Once-per-revolution fundamental: ") +
                    FormatFixed(em.fundamental_value, d) + " " + m.unit + " peak-to-peak.");
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
    if (em.mz) pc.centres.push_back({"MZ", em.mz->a, em.mz->b, "#ff7f0e"});
    page->Figure(pc.Render(),
                 "Polar plot about a base circle (r0 arbitrary): total motion "
                 "(dots), synchronous plot, centres and the two circles of the "
                 "synchronous value about the preferred centre.");
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

}  // namespace volcomp::metrology
