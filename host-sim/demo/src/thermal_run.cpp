#include "volcomp/sim/thermal_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace volcomp::sim {
namespace {

const char kAxisNames[] = "XYZ";

std::array<int64_t, 3> DriveStepsAt(const Machine& machine, const model::Vec3& q_mm) {
  std::array<int64_t, 3> steps = {};
  for (int a = 0; a < 3; ++a) {
    steps[static_cast<size_t>(a)] =
        std::llround((q_mm[a] - machine.power_up_mm(a)) / machine.step_mm(a));
  }
  return steps;
}

double DeviationAt_um(const Machine& machine, int axis, const model::Vec3& q_mm) {
  const model::Vec3 tool =
      machine.ToolPoint_mm(machine.AxisPositions_mm(DriveStepsAt(machine, q_mm)));
  return 1e3 * (tool[axis] - q_mm[axis]);
}

}  // namespace

std::vector<DriftCheckPoint> DefaultDriftCheckPoints(const Machine& machine) {
  std::vector<DriftCheckPoint> points;
  model::Vec3 mid;
  for (int a = 0; a < 3; ++a) {
    mid[a] = 0.5 * (machine.travel_min_mm(a) + machine.travel_max_mm(a));
  }
  for (int a = 0; a < 3; ++a) {
    const double lo = machine.travel_min_mm(a), hi = machine.travel_max_mm(a);
    for (double f : {0.1, 0.9}) {
      DriftCheckPoint p{a, mid};
      p.q_mm[a] = lo + f * (hi - lo);
      points.push_back(p);
    }
  }
  return points;
}

ThermalRun RunDutyCycle(Machine& machine,
                        const DutyCycle& cycle,
                        const ThermalRunOptions& options,
                        const ThermalCorrectionAt& correction) {
  const std::vector<DriftCheckPoint> points =
      options.points.empty() ? DefaultDriftCheckPoints(machine) : options.points;
  std::vector<ThermalSensorParams> sensor_params = options.sensors;
  if (sensor_params.empty()) {
    for (const ThermalSensorParams& s : WornMachineSensors()) sensor_params.push_back(s);
  }
  HeatBalance heat(options.machine, cycle.start_ambient_C);
  std::vector<ThermalSensor> sensors;
  ThermalRun run;
  run.cycle = cycle.name;
  for (size_t i = 0; i < sensor_params.size(); ++i) {
    sensors.emplace_back(sensor_params[i], heat, cycle.start_ambient_C, options.seed + 101 * i);
    run.channel_names.push_back(sensor_params[i].name);
  }
  const double end_s = cycle.duration_s();
  double next_check_s = 0;
  for (double t = 0;; t += options.step_s) {
    if (t + 1e-9 >= next_check_s) {
      machine.SetThermalDeformation(heat.Deformation());
      std::vector<int16_t> cC;
      for (ThermalSensor& s : sensors) cC.push_back(s.Read_cC());
      for (const DriftCheckPoint& p : points) {
        DriftReading r{t, p.axis, p.q_mm[p.axis], DeviationAt_um(machine, p.axis, p.q_mm), cC};
        if (correction) r.deviation_um += correction(p.axis, p.q_mm, cC);
        run.readings.push_back(std::move(r));
      }
      std::array<double, kThermalBodies + 1> b;
      b[0] = t;
      for (int i = 0; i < kThermalBodies; ++i)
        b[static_cast<size_t>(i) + 1] = heat.temperatures_C()[i];
      run.bodies_C.push_back(b);
      next_check_s += options.check_interval_s;
    }
    if (t >= end_s) break;
    const ThermalLoad load = cycle.LoadAt(t);
    heat.Step(options.step_s, load);
    for (ThermalSensor& s : sensors)
      s.Step(options.step_s, heat, cycle.LoadAt(t + options.step_s).ambient_C);
  }
  return run;
}

std::array<double, 3> MaxDrift_um(const ThermalRun& run) {
  std::array<double, 3> out = {0, 0, 0};
  std::map<std::pair<int, double>, double> first;  // (axis, position) -> first deviation
  for (const DriftReading& r : run.readings) {
    const auto [it, inserted] =
        first.emplace(std::make_pair(r.axis, r.position_mm), r.deviation_um);
    double& m = out[static_cast<size_t>(r.axis)];
    m = std::max(m, std::fabs(r.deviation_um - it->second));
  }
  return out;
}

std::string DriftTestCsv(const ThermalRun& run, const std::string& machine_name) {
  std::string csv;
  char line[256];
  std::snprintf(line, sizeof line,
                "# test: thermal drift (ISO 230-3 manner), duty cycle %s\n# machine: %s\n"
                "# instrument: simulated laser interferometer\n",
                run.cycle.c_str(), machine_name.c_str());
  csv += line;
  csv += "time_s,axis,position_mm,deviation_um";
  for (const std::string& n : run.channel_names) csv += ",T_" + n + "_C";
  csv += '\n';
  for (const DriftReading& r : run.readings) {
    std::snprintf(line, sizeof line, "%.0f,%c,%.3f,%.3f", r.time_s, kAxisNames[r.axis],
                  r.position_mm, r.deviation_um);
    csv += line;
    for (int16_t c : r.channels_cC) {
      std::snprintf(line, sizeof line, ",%.2f", c / 100.0);
      csv += line;
    }
    csv += '\n';
  }
  return csv;
}

}  // namespace volcomp::sim
