// Measurement sessions on the simulated installation.
#include "volcomp/sim/measurements.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "volcomp/sim/gcode.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::sim {
namespace {

model::Vec3 ToVec(const Point3& p) { return {p[0], p[1], p[2]}; }

std::string Fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// GOST 27843 and ISO 230-2 evaluations of one set of readings.
Outcome EvaluateAxis(const metrology::GroupingOptions& grouping, GostAxisResult& r) {
  metrology::EvaluationOptions gost;
  gost.standard = metrology::Standard::kGost27843;
  metrology::EvaluationOptions iso;
  iso.standard = metrology::Standard::kIso230_2;
  VOLCOMP_TRY_ASSIGN(const metrology::PositioningSet set,
                     metrology::GroupReadings(r.data, grouping));
  VOLCOMP_TRY_ASSIGN(r.gost, metrology::EvaluatePositioning(set, gost));
  VOLCOMP_TRY_ASSIGN(r.iso, metrology::EvaluatePositioning(set, iso));
  return Outcome::Ok();
}

}  // namespace

Expected<std::vector<StopState>> RunTestProgram(World& world, const TestProgram& program) {
  VOLCOMP_TRY_ASSIGN(const Program blocks, ParseGcode(program.gcode, program.name));
  std::vector<StopState> states;
  world.cnc().set_dwell_handler([&](uint64_t) {
    StopState s;
    if (states.size() < program.stops.size()) s.stop = program.stops[states.size()];
    s.at_rest_ok = world.CheckAtRest();
    s.q_mm = world.AxisPositions_mm();
    s.cmd_mm = world.CommandedPoint_mm();
    states.push_back(s);
  });
  world.cnc().QueueProgram(blocks);
  const bool done = world.RunUntilCncIdle(3600ull * 1000000000ull);
  world.cnc().set_dwell_handler({});
  if (!done) {
    return Fail(Error::kNotReady, program.name + ": the CNC did not finish the program");
  }
  if (states.size() != program.stops.size()) {
    return Fail(Error::kNotReady, program.name + ": " + std::to_string(states.size()) +
                                      " dwells for " + std::to_string(program.stops.size()) +
                                      " stops");
  }
  return states;
}

Expected<GostAxisResult> MeasureGostAxis(World& world,
                                         LaserInterferometer& laser,
                                         int axis,
                                         const GostPlan& plan) {
  GostAxisResult r;
  r.axis = axis;
  VOLCOMP_TRY_ASSIGN(r.program,
                     GostAxisProgram(axis, plan.line_point_mm, plan.targets_mm, plan.cycle));
  VOLCOMP_TRY_ASSIGN(const std::vector<StopState> states, RunTestProgram(world, r.program));
  model::Vec3 beam;
  beam[axis] = 1;
  r.data.source = r.program.name;
  size_t line = 0;
  for (const StopState& s : states) {
    ++line;
    if (s.stop.datum) {
      laser.Zero(s.q_mm, s.cmd_mm);
      continue;
    }
    metrology::PositioningReading reading;
    reading.target = s.stop.along_mm;
    reading.direction = s.stop.approach;
    reading.run = s.stop.run;
    reading.deviation = laser.Deviation_um(s.q_mm, s.cmd_mm, beam);
    reading.line = line;
    r.data.readings.push_back(reading);
  }
  metrology::GroupingOptions grouping;  // GOST 27843 §2.10: 5 approaches (fewer only if asked)
  grouping.min_approaches = std::max(2, std::min(5, plan.cycle.runs));
  VOLCOMP_TRY(EvaluateAxis(grouping, r));
  return r;
}

Expected<DiagonalSetResult> MeasureDiagonals(World& world,
                                             LaserInterferometer& laser,
                                             const std::vector<BodyDiagonal>& diagonals,
                                             int targets_per_diagonal,
                                             const CycleOptions& cycle) {
  DiagonalSetResult r;
  r.csv = "diagonal,target_mm,direction,run,deviation_um\n";
  for (const BodyDiagonal& d : diagonals) {
    double len2 = 0;
    for (size_t a = 0; a < 3; ++a) len2 += (d.p2[a] - d.p1[a]) * (d.p2[a] - d.p1[a]);
    const double increment = std::sqrt(len2) / std::max(1, targets_per_diagonal - 1);
    VOLCOMP_TRY_ASSIGN(const TestProgram p, DiagonalProgram(d.name, d.p1, d.p2, increment, cycle));
    VOLCOMP_TRY_ASSIGN(const std::vector<StopState> states, RunTestProgram(world, p));
    const model::Vec3 beam = ToVec(p.direction);
    for (const StopState& s : states) {
      if (s.stop.datum) {
        laser.Zero(s.q_mm, s.cmd_mm);
        continue;
      }
      const double dev = laser.Deviation_um(s.q_mm, s.cmd_mm, beam);
      r.csv += d.name + "," + Fixed(s.stop.along_mm, 4) + "," +
               metrology::DirectionName(s.stop.approach) + "," + std::to_string(s.stop.run) + "," +
               Fixed(dev, 4) + "\n";
    }
    r.programs.push_back(p);
  }
  VOLCOMP_TRY_ASSIGN(const tools::CsvTable table,
                     tools::CsvTable::ReadString(r.csv, "ISO 230-6 diagonals"));
  metrology::GroupingOptions grouping;  // ISO 230-6 §5.3: 5 approaches (fewer only if asked)
  grouping.min_approaches = std::max(2, std::min(5, cycle.runs));
  VOLCOMP_TRY_ASSIGN(r.evaluation, metrology::EvaluateDiagonals(table, grouping));
  return r;
}

Expected<PointSetResult> MeasurePointSet(World& world,
                                         LaserTracker& tracker,
                                         const std::vector<Point3>& points_mm,
                                         double dwell_s,
                                         double approach_mm) {
  PointSetResult r;
  r.program = PointSetProgram("volumetric point set", points_mm, dwell_s, approach_mm);
  VOLCOMP_TRY_ASSIGN(const std::vector<StopState> states, RunTestProgram(world, r.program));
  double sum2 = 0, true_sum2 = 0;
  for (const StopState& s : states) {
    if (s.stop.datum) {
      tracker.Zero(s.q_mm, s.cmd_mm);
      continue;
    }
    const model::Vec3 m = 1e3 * (tracker.Measure_mm(s.q_mm) - s.cmd_mm);
    const model::Vec3 t = 1e3 * (tracker.True_mm(s.q_mm) - s.cmd_mm);
    r.targets_mm.push_back(s.stop.point_mm);
    r.measured_error_um.push_back(m);
    r.true_error_um.push_back(t);
    r.max_um = std::max(r.max_um, model::Norm(m));
    r.true_max_um = std::max(r.true_max_um, model::Norm(t));
    sum2 += model::Dot(m, m);
    true_sum2 += model::Dot(t, t);
  }
  if (!r.targets_mm.empty()) {
    r.rms_um = std::sqrt(sum2 / static_cast<double>(r.targets_mm.size()));
    r.true_rms_um = std::sqrt(true_sum2 / static_cast<double>(r.targets_mm.size()));
  }
  return r;
}

Expected<ParametricResult> MeasureParametric(World& world,
                                             LaserInterferometer& laser,
                                             int axis,
                                             const Point3& reference_mm,
                                             const std::vector<double>& positions_mm,
                                             const CycleOptions& cycle) {
  ParametricResult r;
  r.axis = axis;
  r.position_mm = positions_mm;
  const double ref = reference_mm[static_cast<size_t>(axis)];
  int ref_target = -1;
  for (size_t j = 0; j < positions_mm.size(); ++j) {
    if (std::fabs(positions_mm[j] - ref) < 1e-9) ref_target = static_cast<int>(j) + 1;
  }
  if (ref_target < 0) {
    return Fail(Error::kInvalidArgument,
                "parametric run: the positions must include the reference point");
  }
  VOLCOMP_TRY_ASSIGN(const TestProgram p,
                     ParametricProgram(axis, reference_mm, positions_mm, cycle));
  VOLCOMP_TRY_ASSIGN(const std::vector<StopState> states, RunTestProgram(world, p));
  std::map<int, std::pair<SixDofReading, int>> sum, truth;
  for (const StopState& s : states) {
    if (s.stop.datum) {
      laser.Zero(s.q_mm, s.cmd_mm);
      continue;
    }
    const SixDofReading m = laser.SixDof(s.q_mm, s.cmd_mm, axis);
    const SixDofReading t = laser.SixDofTrue(s.q_mm, s.cmd_mm);
    for (auto [acc, v] : {std::pair{&sum, &m}, std::pair{&truth, &t}}) {
      auto& e = (*acc)[s.stop.target];
      e.first.linear_um += v->linear_um;
      e.first.angular_urad += v->angular_urad;
      e.second++;
    }
  }
  auto mean = [](const std::pair<SixDofReading, int>& e) {
    SixDofReading m;
    m.linear_um = (1.0 / e.second) * e.first.linear_um;
    m.angular_urad = (1.0 / e.second) * e.first.angular_urad;
    return m;
  };
  for (int target = 1; target <= static_cast<int>(positions_mm.size()); ++target) {
    if (sum.count(target) == 0) {
      return Fail(Error::kNotReady, p.name + ": no reading at target " + std::to_string(target));
    }
  }
  const SixDofReading m0 = mean(sum[ref_target]), t0 = mean(truth[ref_target]);
  for (size_t j = 0; j < positions_mm.size(); ++j) {
    const int target = static_cast<int>(j) + 1;
    SixDofReading m = mean(sum[target]), t = mean(truth[target]);
    m.linear_um -= m0.linear_um;
    m.angular_urad -= m0.angular_urad;
    t.linear_um -= t0.linear_um;
    t.angular_urad -= t0.angular_urad;
    r.measured.push_back(m);
    r.truth.push_back(t);
  }
  return r;
}

std::string PositioningCsv(const metrology::PositioningData& data) {
  std::string csv = "target_mm,direction,run,deviation_um\n";
  for (const metrology::PositioningReading& r : data.readings) {
    csv += Fixed(r.target, 4) + "," + metrology::DirectionName(r.direction) + "," +
           std::to_string(r.run) + "," + Fixed(r.deviation, 4) + "\n";
  }
  return csv;
}

}  // namespace volcomp::sim
