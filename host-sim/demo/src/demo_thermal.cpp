// The worn machine's thermal step of `volcomp-sim demo` (issue 23; docs/simulator.md 7.6): a drift
// test on the heat-balance machine, the model fitted with the entry points of `volcomp build
// thermal`, written into the last table's image, and the verification cycle run twice with the
// firmware in the loop: with the last table alone, and with the thermal image and sensor faults.
#include <cmath>
#include <cstdio>

#include "demo_session.hpp"
#include "volcomp/builders/thermal_fit.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/image/image_thermal.hpp"
#include "volcomp/metrology/drift_test.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::sim::demo {
namespace {

// `volcomp build thermal DRIFT --image LAST -o NEW`'s steps: the fit (the reach over the image's
// tables), the model on the image's axes, the new image.
Expected<std::vector<uint8_t>> ThermalImage(const std::string& drift_csv,
                                            const std::vector<uint8_t>& last_image,
                                            ThermalPhase& t) {
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table,
                     tools::CsvTable::ReadString(drift_csv, "drift_test.csv"));
  VOLCOMP_TRY_ASSIGN(const metrology::DriftRecord record, metrology::ReadDriftCsv(table));
  VOLCOMP_TRY_ASSIGN(const image::LoadedImage loaded,
                     image::LoadedImage::FromBytes(last_image, "table 3"));
  const table::TableView& v = loaded.view();
  builders::ThermalFitOptions o;
  o.travel_mm = image::LinearAxisSpans(v);
  VOLCOMP_TRY_ASSIGN(t.fit, builders::FitThermalModel(record, o));
  VOLCOMP_TRY_ASSIGN(t.model, builders::ToThermalModel(t.fit, v.axes, v.axis_count));
  image::ThermalImageOptions io;
  io.table_id = v.table_id + 1;
  io.info["source"] = "drift test, calibration duty cycle (volcomp-sim demo)";
  VOLCOMP_TRY_ASSIGN(const image::ThermalImage built,
                     image::WithThermalModel(loaded, "table 3", t.model, io));
  return built.bytes;
}

std::string Um3(const std::array<double, 3>& v) {
  char b[96];
  std::snprintf(b, sizeof b, "X %.1f / Y %.1f / Z %.1f um", v[0], v[1], v[2]);
  return b;
}

}  // namespace

Outcome RunThermal(Session& s, DemoResult& r) {
  ThermalPhase& t = r.thermal;
  t.ran = true;
  const auto t0 = Clock::now();
  // The worn machine with its heat balance instead of the closed-form warm-up.
  ThermalLoopOptions lo;
  lo.model_spec = s.o.model_spec;
  lo.wear = s.world.machine().wear();
  lo.wear.thermal = false;
  lo.run.check_interval_s = s.o.thermal_check_interval_s;
  lo.tick_hz = s.o.thermal_tick_hz;
  t.tick_hz = lo.tick_hz;
  lo.run.seed = s.o.seed ^ 0x7468657266ull;

  // The drift test: the calibration cycle on the machine, read with the laser at two points per
  // axis (no board needed: the drift is the machine's).
  MachineOptions mo;
  mo.model = s.world.machine().model();
  mo.wear = lo.wear;
  VOLCOMP_TRY_ASSIGN(Machine machine, Machine::Create(mo));
  const DutyCycle calibration = CalibrationDutyCycle();
  const ThermalRun drift = RunDutyCycle(machine, calibration, lo.run);
  t.drift_csv = DriftTestCsv(drift, r.machine_name);
  t.calibration_h = calibration.duration_s() / 3600;
  t.calibration_readings = drift.readings.size();
  t.calibration_drift_um = MaxDrift_um(drift);
  s.progress.Line(Fmt("drift test: %.1f h of the calibration duty cycle, ", t.calibration_h) +
                  std::to_string(drift.readings.size()) + " readings; largest drift " +
                  Um3(t.calibration_drift_um));

  VOLCOMP_TRY_ASSIGN(t.image, ThermalImage(t.drift_csv, r.table.image, t));
  for (const builders::ThermalAxisFit& a : t.fit.axes) {
    char b[160];
    std::snprintf(b, sizeof b,
                  "fit %c: residual rms %.2f um, max %.2f um, %.1f %% of the drift explained, "
                  "condition %.0f",
                  a.name, a.residual_rms_um, a.residual_max_um, 100 * a.explained, a.condition);
    s.progress.Line(b);
  }

  // The verification cycle, twice, with the firmware in the loop.
  lo.cycle = VerificationDutyCycle();
  t.verification_h = lo.cycle.duration_s() / 3600;
  lo.image = r.table.image;
  VOLCOMP_TRY_ASSIGN(t.uncompensated, RunThermalLoop(lo, s.progress.out()));
  lo.image = t.image;
  // Two faults inside the cycle, each shorter than the hold time (60 s): flagged, held.
  const double cycle_s = lo.cycle.duration_s();
  lo.faults = {{1, SensorFault::kOpenCircuit, std::round(0.4 * cycle_s), 30},
               {0, SensorFault::kStuck, std::round(0.8 * cycle_s), 30}};
  VOLCOMP_TRY_ASSIGN(t.compensated, RunThermalLoop(lo, s.progress.out()));
  t.slew_limit_um_s = t.model.slew_um_s;
  t.drift_before_um = MaxDrift_um(t.uncompensated.run);
  t.drift_after_um = MaxDrift_um(t.compensated.run);
  s.progress.Line("verification drift: table 3 alone " + Um3(t.drift_before_um) +
                  "; with the thermal model " + Um3(t.drift_after_um));
  for (const FaultOutcome& f : t.compensated.faults) {
    s.progress.Line(
        "injected fault on channel " + std::to_string(f.injected.sensor) +
        (f.injected.kind == SensorFault::kOpenCircuit ? " (open circuit)" : " (stuck)") +
        Fmt(": flagged after %.1f s, ", f.detected_after_s) +
        Fmt("correction moved %.2f um while held", f.change_while_held_um));
  }
  t.wall_s = Since(t0);
  return Outcome::Ok();
}

void EvaluateThermalGoals(DemoResult& r) {
  const ThermalPhase& t = r.thermal;
  if (!t.ran) return;
  for (size_t a = 0; a < 3; ++a) {
    const double before = t.drift_before_um[a], after = t.drift_after_um[a];
    AddGoal(r,
            std::string("thermal drift ") + "XYZ"[a] +
                " over the verification cycle >= 80 % below uncompensated",
            before > 0 ? 100.0 * (1.0 - after / before) : 0.0, 80, true);
  }
  double rate = 0;
  for (double v : t.compensated.max_rate_um_s) rate = std::max(rate, v);
  AddGoal(r, "fastest change of the thermal correction <= its slew limit", rate,
          t.slew_limit_um_s * 1.001, false, true, "um/s");
  for (const FaultOutcome& f : t.compensated.faults) {
    const std::string what =
        std::string(f.injected.kind == SensorFault::kOpenCircuit ? "open-circuit" : "stuck") +
        " sensor";
    AddGoal(r, what + " flagged within 2 s of the fault",
            f.detected_after_s < 0 ? 1e9 : f.detected_after_s, 2, false, true, "s");
    AddGoal(r, what + ": the correction held (moved while flagged)", f.change_while_held_um, 0,
            false, true, "um");
  }
}

}  // namespace volcomp::sim::demo
