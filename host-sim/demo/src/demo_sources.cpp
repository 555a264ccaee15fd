// The machine's error sources with their sizes, read from the simulated machine (its geometry
// model, its worn profile) and the instruments' options: one document the worn demo's header
// prints and summary.json holds.
#include <cmath>
#include <cstdio>
#include <string>

#include "demo_session.hpp"
#include "summary_document.hpp"

namespace volcomp::sim::demo {
namespace {

using summary_document::At;
using summary_document::Num;
using tools::JsonValue;

JsonValue Triple(const std::array<double, 3>& v) {
  return JsonValue::Array().Push(v[0]).Push(v[1]).Push(v[2]);
}

// The largest |value| of the three linear (or angular) error functions of one axis, and its name
// (E_YX: the Y error of the X axis; E_BX: its rotation about Y).
JsonValue LargestTerm(const model::AxisErrorTable& t, size_t axis, bool angular) {
  double largest = 0;
  size_t term = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    const model::AxisErrorSample& row = t.row(i);
    const model::Vec3& v = angular ? row.angular_urad : row.linear_um;
    const double c[3] = {v.x, v.y, v.z};
    for (size_t k = 0; k < 3; ++k) {
      if (std::fabs(c[k]) > std::fabs(largest)) largest = c[k], term = k;
    }
  }
  JsonValue o = JsonValue::Object();
  o.Set("term", std::string("E_") + (angular ? "ABC" : "XYZ")[term] + "XYZ"[axis])
      .Set("value", largest)
      .Set("unit", angular ? "urad" : "um");
  return o;
}

JsonValue Channel(const ChannelErrors& c) {
  JsonValue o = JsonValue::Object();
  o.Set("noise", c.noise)
      .Set("samples", c.samples)
      .Set("repeatability", c.repeatability)
      .Set("resolution", c.resolution);
  return o;
}

bool On(const JsonValue& v) { return At(v, "on").boolean; }

std::string Fmt3(const char* format, const JsonValue& v, const std::string& key) {
  char b[120];
  std::snprintf(b, sizeof b, format, Num(v, key, 0), Num(v, key, 1), Num(v, key, 2));
  return b;
}

}  // namespace

tools::JsonValue ErrorSources(Session& s) {
  const Machine& m = s.world.machine();
  const model::Model& g = m.model();
  const WornMachineProfile& w = m.wear();
  JsonValue d = JsonValue::Object();

  JsonValue geometry = JsonValue::Object();
  geometry.Set("model", g.name);
  JsonValue axes = JsonValue::Array();
  for (size_t a = 0; a < 3; ++a) {
    JsonValue o = JsonValue::Object();
    o.Set("axis", std::string(1, "XYZ"[a]))
        .Set("largest_linear", LargestTerm(g.axes[a], a, false))
        .Set("largest_angular", LargestTerm(g.axes[a], a, true));
    axes.Push(std::move(o));
  }
  geometry.Set("axes", std::move(axes));
  geometry.Set("squareness_urad",
               Triple({g.squareness.c0y_urad, g.squareness.b0z_urad, g.squareness.a0z_urad}));
  d.Set("geometry", std::move(geometry));

  JsonValue lost = JsonValue::Object();
  lost.Set("on", w.lost_motion).Set("um", Triple(w.lost_motion_um));
  d.Set("lost_motion", std::move(lost));
  JsonValue scatter = JsonValue::Object();
  scatter.Set("on", w.scatter)
      .Set("sigma_um", Triple(w.scatter_sigma_um))
      .Set("standstill_ms", w.scatter_standstill_ms);
  d.Set("scatter", std::move(scatter));
  JsonValue screw = JsonValue::Object();
  screw.Set("on", w.screw_error)
      .Set("period_mm", w.screw_period_mm)
      .Set("amplitude_um", Triple(w.screw_amplitude_um))
      .Set("phase_rad", Triple(w.screw_phase_rad));
  d.Set("screw", std::move(screw));

  // Drift rates at the demo's time 0 (after the warm-up), over its first minute.
  const double x = s.check_point[0];
  const double z0 = ThermalGrowth::SpindleZ_um(w, 0), z1 = ThermalGrowth::SpindleZ_um(w, 60);
  const double x0 = ThermalGrowth::XScrew_um(w, x, 0), x1 = ThermalGrowth::XScrew_um(w, x, 60);
  JsonValue thermal = JsonValue::Object();
  thermal.Set("on", w.thermal)
      .Set("warmup_min", w.warmup_min)
      .Set("spindle_growth_um", w.spindle_growth_um)
      .Set("spindle_tau_min", w.spindle_tau_min)
      .Set("screw_heating_K", w.screw_heating_K)
      .Set("screw_tau_min", w.screw_tau_min)
      .Set("screw_expansion_ppm_per_K", w.screw_expansion_ppm_per_K)
      .Set("screw_fixed_end_mm", w.screw_fixed_end_mm)
      .Set("spindle_drift_um_per_h", -60 * (z1 - z0))
      .Set("x_screw_drift_um_per_h", 60 * (x1 - x0))
      .Set("x_screw_drift_at_mm", x);
  d.Set("thermal", std::move(thermal));
  JsonValue sag = JsonValue::Object();
  sag.Set("on", w.cross_axis_sag).Set("um", w.sag_um);
  d.Set("sag", std::move(sag));

  JsonValue laser = JsonValue::Object();
  laser.Set("linear_um", Channel(s.o.laser.linear_um))
      .Set("angular_urad", Channel(s.o.laser.angular_urad))
      .Set("misalignment_mrad", s.o.laser.misalignment_mrad);
  d.Set("laser", std::move(laser));
  JsonValue tracker = JsonValue::Object();
  tracker.Set("coordinate_um", Channel(s.o.tracker.coordinate_um));
  d.Set("tracker", std::move(tracker));
  return d;
}

void PrintErrorSources(const tools::JsonValue& d, Progress& progress) {
  std::ostream& out = progress.out();
  char b[400];
  out << "  error sources of the machine (each switchable with --without, docs/simulator.md "
         "7.1):\n";
  const JsonValue& g = At(d, "geometry");
  std::string line = "    geometry: 21 parameters of " + At(g, "model").string + "; largest";
  for (const JsonValue& a : At(g, "axes").array) {
    const JsonValue& lin = At(a, "largest_linear");
    const JsonValue& ang = At(a, "largest_angular");
    std::snprintf(b, sizeof b, " %s %.1f %s, %s %.1f %s;", At(lin, "term").string.c_str(),
                  Num(lin, "value"), At(lin, "unit").string.c_str(), At(ang, "term").string.c_str(),
                  Num(ang, "value"), At(ang, "unit").string.c_str());
    line += b;
  }
  out << line << " squareness as above\n";
  const JsonValue& lost = At(d, "lost_motion");
  out << "    lost motion: "
      << (On(lost) ? Fmt3("X %.1f, Y %.1f, Z %.1f um", lost, "um") : std::string("off")) << "\n";
  const JsonValue& scatter = At(d, "scatter");
  out << "    scatter at rest: ";
  if (On(scatter)) {
    std::snprintf(b, sizeof b, " (at rest: no step for %.0f ms)", Num(scatter, "standstill_ms"));
    out << Fmt3("sigma X %.2f, Y %.2f, Z %.2f um", scatter, "sigma_um") << b << "\n";
  } else {
    out << "off\n";
  }
  const JsonValue& screw = At(d, "screw");
  if (On(screw)) {
    std::snprintf(b, sizeof b, "    screw, short period %.1f mm: amplitude ",
                  Num(screw, "period_mm"));
    out << b << Fmt3("X %.2f, Y %.2f, Z %.2f um", screw, "amplitude_um") << "\n";
  } else {
    out << "    screw, short period: off\n";
  }
  const JsonValue& t = At(d, "thermal");
  if (On(t)) {
    std::snprintf(b, sizeof b,
                  "    thermal: spindle grows %.1f um toward the table (tau %.0f min), X screw "
                  "heats %.1f K (tau %.0f min, %.1f ppm/K, fixed end at X %.0f mm); after %.0f min "
                  "of warm-up drifting %.1f um/h (spindle), %.1f um/h (X screw at X %.0f mm)\n",
                  Num(t, "spindle_growth_um"), Num(t, "spindle_tau_min"), Num(t, "screw_heating_K"),
                  Num(t, "screw_tau_min"), Num(t, "screw_expansion_ppm_per_K"),
                  Num(t, "screw_fixed_end_mm"), Num(t, "warmup_min"),
                  Num(t, "spindle_drift_um_per_h"), Num(t, "x_screw_drift_um_per_h"),
                  Num(t, "x_screw_drift_at_mm"));
    out << b;
  } else {
    out << "    thermal: off\n";
  }
  const JsonValue& sag = At(d, "sag");
  if (On(sag)) {
    std::snprintf(b, sizeof b,
                  "    sag: %.1f um (the tool rises at both ends of X, the more toward the end of "
                  "Y)\n",
                  Num(sag, "um"));
    out << b;
  } else {
    out << "    sag: off\n";
  }
  const JsonValue& laser = At(At(d, "laser"), "linear_um");
  const JsonValue& tracker = At(At(d, "tracker"), "coordinate_um");
  std::snprintf(b, sizeof b,
                "    instruments: laser sigma %.3f um (mean of %.0f), repeatability %.3f um, beam "
                "%.2f mrad off the line of motion; tracker sigma %.2f um (mean of %.0f), "
                "repeatability %.2f um per coordinate\n",
                Num(laser, "noise"), Num(laser, "samples"), Num(laser, "repeatability"),
                Num(At(d, "laser"), "misalignment_mrad"), Num(tracker, "noise"),
                Num(tracker, "samples"), Num(tracker, "repeatability"));
  out << b;
}

}  // namespace volcomp::sim::demo
