// The steps of `volcomp-sim demo` both machine profiles share (see demo_session.hpp).
#include "demo_session.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "volcomp/firmware/board_objects.hpp"
#include "volcomp/metrology/test_program.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::sim {

std::array<AxisFigures, 3> PhaseResults::Gost() const {
  std::array<AxisFigures, 3> f;
  for (size_t a = 0; a < 3; ++a) {
    const metrology::PositioningResult& g = gost[a].gost;
    if (g.accuracy) f[a].A = g.accuracy->value;
    if (g.repeatability) f[a].R = g.repeatability->value;
    if (g.reversal_max) f[a].B = g.reversal_max->value;
  }
  return f;
}

double PhaseResults::Ed() const {
  return diagonals.evaluation.body ? diagonals.evaluation.body->E_d : 0.0;
}

double PhaseResults::Bd() const {
  return diagonals.evaluation.body ? diagonals.evaluation.body->B_d : 0.0;
}

namespace demo {
namespace {

std::vector<double> ParametricPositions(double lo, double hi, double ref, double step) {
  std::vector<double> p;
  for (int k = 0;; ++k) {
    const double x = lo + k * step;
    if (x > hi - 1e-9) break;
    p.push_back(std::round(x * 1e4) / 1e4);
  }
  p.push_back(hi);
  if (std::find_if(p.begin(), p.end(), [&](double x) { return std::fabs(x - ref) < 1e-9; }) ==
      p.end()) {
    p.push_back(ref);
    std::sort(p.begin(), p.end());
  }
  return p;
}

std::string GostLine(const char* axis, const AxisFigures& f) {
  char b[160];
  std::snprintf(b, sizeof b, "GOST 27843 %s: A = %8.3f um   R = %6.3f um   B = %6.3f um", axis, f.A,
                f.R, f.B);
  return b;
}

Outcome AfterTest(Session& s, DemoResult& r, const std::string& test) {
  return s.drift_checks ? CheckDrift(s, r, test) : Outcome::Ok();
}

}  // namespace

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string Fmt(const char* format, double a) {
  char b[64];
  std::snprintf(b, sizeof b, format, a);
  return b;
}

Expected<Layout> MakeLayout(const Machine& m, double margin) {
  Layout l;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    l.lo[i] = m.travel_min_mm(a);
    l.hi[i] = m.travel_max_mm(a);
    const double span = l.hi[i] - l.lo[i];
    const double g = std::min(margin, 0.1 * span);
    l.inner_lo[i] = l.lo[i] + g;
    l.inner_hi[i] = l.hi[i] - g;
    l.centre[i] = 0.5 * (l.lo[i] + l.hi[i]);
    // The model's lever arms start where all commands are 0, so the parametric lines must meet
    // there (see docs/simulator.md): the tables must cover position 0.
    if (!(l.lo[i] <= 0.0 && 0.0 <= l.hi[i])) {
      return Fail(Error::kInvalidArgument,
                  std::string("the model's ") + "XYZ"[a] +
                      " table must include position 0 (the reference point)");
    }
    l.reference[i] = 0.0;
  }
  return l;
}

Outcome PlanTests(Session& s, Random& rng) {
  const Layout& l = s.layout;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    metrology::TargetPlan tp;
    tp.start = l.inner_lo[i];
    tp.end = l.inner_hi[i];
    tp.count = s.o.gost_targets;
    tp.pitch = s.o.gost_pitch_mm;
    tp.seed = static_cast<uint32_t>(rng.Next() & 0x7FFFFFFF);
    VOLCOMP_TRY_ASSIGN(s.gost[i].targets_mm, metrology::PlanGostTargets(tp));
    s.gost[i].line_point_mm = l.centre;
    s.gost[i].cycle.runs = s.o.gost_runs;
    s.gost[i].cycle.dwell_s = s.o.dwell_s;
    s.gost[i].cycle.feed_mm_s = s.o.test_feed_mm_s;
  }
  s.points = {l.reference};
  for (int k = 0; k < s.o.random_points; ++k) {
    Point3 p;
    for (size_t i = 0; i < 3; ++i) p[i] = std::round(rng.Uniform(l.lo[i], l.hi[i]) * 1e3) / 1e3;
    s.points.push_back(p);
  }
  return Outcome::Ok();
}

void PrintSetup(Session& s, const DemoResult& r, const WorldOptions& wo) {
  const Layout& l = s.layout;
  const model::Model& m = s.world.machine().model();
  s.progress.out() << "volcomp-sim demo: seed " << s.o.seed << "\n"
                   << "  machine: " << r.machine_name << "\n"
                   << "    squareness C0Y " << m.squareness.c0y_urad << ", B0Z "
                   << m.squareness.b0z_urad << ", A0Z " << m.squareness.a0z_urad << " urad; chain "
                   << m.chain.ToString() << " (workpiece|tool)\n"
                   << "  travel: X " << l.lo[0] << ".." << l.hi[0] << ", Y " << l.lo[1] << ".."
                   << l.hi[1] << ", Z " << l.lo[2] << ".." << l.hi[2] << " mm; "
                   << s.world.machine().step_mm(0) * 1000 << " um/step; CNC up to "
                   << s.world.cnc().config().max_step_rate_hz / 1e6 << " MHz per axis, "
                   << s.o.accel_mm_s2 / 1000 << " m/s^2\n"
                   << "  board: the real firmware (BoardApp) on the mock HAL, tick "
                   << wo.board.board.tick_hz / 1000 << " kHz; CAN " << wo.can_bitrate / 1000
                   << " kbit/s; node " << static_cast<int>(wo.board.node_id) << "\n";
  if (s.o.machine == MachineProfile::kWorn) PrintErrorSources(r.error_sources, s.progress);
}

Outcome Home(World& world) {
  world.cnc().QueueHome(7);
  if (!world.RunUntilCncIdle(120 * kSecond_ns)) {
    return Fail(Error::kNotReady, "homing did not finish within 120 s");
  }
  return Outcome::Ok();
}

Outcome HomeAtPowerUp(Session& s, DemoResult& r) {
  const auto t0 = Clock::now();
  VOLCOMP_TRY(Home(s.world));
  s.world.RunFor(20000000);
  const ControlTick& e = s.world.board().app().control_tick();
  bool agree = e.all_referenced();
  for (uint8_t a = 0; a < 3; ++a) {
    agree = agree && e.machine_position(a) == s.world.cnc().position(a);
  }
  r.reference_agrees = agree;
  const AxisConfig* axis = s.world.options().board.board.axis;
  s.progress.Line(std::string("X, Y, Z referenced at their home positions (0x2018: ") +
                  std::to_string(axis[0].home_position_steps) + ", " +
                  std::to_string(axis[1].home_position_steps) + ", " +
                  std::to_string(axis[2].home_position_steps) +
                  " steps); board and CNC positions " + (agree ? "agree" : "DISAGREE") +
                  Fmt("   (%.1f s)", Since(t0)));
  return Outcome::Ok();
}

Expected<PhaseResults> MeasurePhase(Session& s, DemoResult& r) {
  PhaseResults p;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    const auto t0 = Clock::now();
    VOLCOMP_TRY_ASSIGN(p.gost[i], MeasureGostAxis(s.world, s.laser, a, s.gost[i]));
    s.progress.Line(GostLine(a == 0   ? "X"
                             : a == 1 ? "Y"
                                      : "Z",
                             p.Gost()[i]) +
                    Fmt("   (%.1f s)", Since(t0)));
    VOLCOMP_TRY(AfterTest(s, r, std::string("GOST 27843 ") + "XYZ"[a]));
  }
  {
    const auto t0 = Clock::now();
    CycleOptions c;
    c.runs = s.o.diagonal_runs;
    c.dwell_s = s.o.dwell_s;
    c.feed_mm_s = s.o.test_feed_mm_s;
    VOLCOMP_TRY_ASSIGN(
        p.diagonals,
        MeasureDiagonals(s.world, s.laser, BodyDiagonals(s.layout.inner_lo, s.layout.inner_hi),
                         s.o.diagonal_targets, c));
    std::string e;
    for (const auto& d : p.diagonals.evaluation.diagonals) {
      e += d.name.text + " " + Fmt("%.2f", d.E.value) + "  ";
    }
    s.progress.Line("ISO 230-6 body diagonals, E_i (um): " + e);
    s.progress.Line(Fmt("ISO 230-6 E_d = %.3f um", p.Ed()) + Fmt(", B_d = %.3f um", p.Bd()) +
                    Fmt("   (%.1f s)", Since(t0)));
    VOLCOMP_TRY(AfterTest(s, r, "ISO 230-6 diagonals"));
  }
  {
    const auto t0 = Clock::now();
    VOLCOMP_TRY_ASSIGN(p.points, MeasurePointSet(s.world, s.tracker, s.points, s.o.dwell_s));
    char b[200];
    std::snprintf(b, sizeof b,
                  "volumetric error at %zu random points (tracker): max %.2f um, rms %.2f um "
                  "(machine model: max %.2f, rms %.2f)   (%.1f s)",
                  p.points.targets_mm.size(), p.points.max_um, p.points.rms_um,
                  p.points.true_max_um, p.points.true_rms_um, Since(t0));
    s.progress.Line(b);
    VOLCOMP_TRY(AfterTest(s, r, "random points"));
  }
  if (s.o.machine == MachineProfile::kWorn && s.o.circular_tests) {
    VOLCOMP_TRY_ASSIGN(p.circular, MeasureCircularTests(s));
    VOLCOMP_TRY(AfterTest(s, r, "ISO 230-4 circular tests"));
  }
  return p;
}

Outcome MeasureErrorMotions(Session& s, DemoResult& r) {
  const auto t0 = Clock::now();
  const Layout& l = s.layout;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    CycleOptions c;
    c.runs = 1;
    c.overrun_mm = 2;
    c.dwell_s = s.o.dwell_s;
    c.feed_mm_s = s.o.test_feed_mm_s;
    const std::vector<double> pos =
        ParametricPositions(l.lo[i], l.hi[i], l.reference[i], s.o.parametric_step_mm);
    VOLCOMP_TRY_ASSIGN(r.parametric[i],
                       MeasureParametric(s.world, s.laser, a, l.reference, pos, c));
    double lin = 0, ang = 0, dev_lin = 0;
    for (size_t k = 0; k < pos.size(); ++k) {
      const SixDofReading& m = r.parametric[i].measured[k];
      const SixDofReading& t = r.parametric[i].truth[k];
      lin = std::max(lin, model::MaxAbs(m.linear_um));
      ang = std::max(ang, model::MaxAbs(m.angular_urad));
      dev_lin = std::max(dev_lin, model::MaxAbs(m.linear_um - t.linear_um));
    }
    char b[200];
    std::snprintf(b, sizeof b,
                  "%c: %zu positions every %.0f mm, up and down: linear errors up to %.1f um, "
                  "angular up to %.1f urad (readings minus model: linear <= %.3f um)",
                  "XYZ"[a], pos.size(), s.o.parametric_step_mm, lin, ang, dev_lin);
    s.progress.Line(b);
    VOLCOMP_TRY(AfterTest(s, r, std::string("error motions of ") + "XYZ"[a]));
  }
  s.progress.Line(Fmt("(%.1f s)", Since(t0)));
  return Outcome::Ok();
}

Expected<builders::GridSection> BuildModelGrid(Session& s, DemoResult& r) {
  VOLCOMP_TRY_ASSIGN(r.measured_model,
                     ModelFromParametric(r.parametric, s.world.machine().model().chain));
  const double h = s.o.grid_spacing_mm;
  VOLCOMP_TRY_ASSIGN(
      builders::GridSection grid,
      BuildModelGridSection(r.measured_model,
                            LatticeOptions(s.layout.lo, s.layout.hi, {h, h, h}, s.step_mm())));
  const model::GridAxes& g = grid.build.grid.axes;
  s.progress.Line(
      "source: the measured six error motions of each axis (18 functions; the three "
      "squareness angles are in the straightness slopes) = a 21-parameter model, "
      "chain " +
      r.measured_model.chain.ToString());
  char b[300];
  std::snprintf(b, sizeof b,
                "inverse GRID3 (tools/model, as `volcomp build model`): %ux%ux%u nodes every "
                "%.0f mm, largest correction %.1f um, inverse residual <= %.1e um, predicted "
                "interpolation error %.3f um max",
                g[0].nodes, g[1].nodes, g[2].nodes, g[0].spacing_mm,
                grid.build.stats.max_correction_um, grid.build.stats.max_residual_um,
                grid.build.interpolation.max_um);
  s.progress.Line(b);
  return grid;
}

void PrintImageLine(Session& s, const TableBuildResult& t, Clock::time_point t0) {
  char b[300];
  std::snprintf(b, sizeof b,
                "image: %zu bytes, int16 with %u fraction bits (LSB %.4f um), "
                "CRC-32 0x%08X   (%.1f s)",
                t.image.size(), t.frac_bits, t.lsb_um, t.crc32, Since(t0));
  s.progress.Line(b);
}

Expected<UploadReport> Upload(Session& s, const TableBuildResult& table) {
  const auto t0 = Clock::now();
  VOLCOMP_TRY_ASSIGN(const UploadReport up, UploadTable(s.world, table.image, s.progress.out()));
  char b[240];
  std::snprintf(b, sizeof b,
                "%u bytes in %.2f s of bus time (%.1f kB/s, %llu frames, %u segments resent); "
                "board verified it, staged CRC-32 0x%08X   (%.1f s)",
                up.bytes, up.transfer_s, up.rate_bytes_s / 1000,
                static_cast<unsigned long long>(up.frames), up.resent_segments, up.staged_crc,
                Since(t0));
  s.progress.Line(b);
  return up;
}

Expected<ActivationReport> Activate(Session& s, uint32_t crc32, bool home) {
  const auto t0 = Clock::now();
  if (home) VOLCOMP_TRY(Home(s.world));
  s.world.RunFor(150000000);  // activation needs 100 ms without input steps
  VOLCOMP_TRY_ASSIGN(ActivationReport act, ActivateTable(s.world, crc32));
  ++s.epoch;
  s.world.RunFor(500000000);  // the correction ramps in within the rate limits
  const uint16_t state = ReadDeviceState(s.world);
  act.device_state = state;
  s.progress.Line(std::string("active table CRC-32 ") + tools::Hex32(act.active_crc) +
                  "; device state: referenced " +
                  ((state & canopen::kStateReferenced) ? "yes" : "no") + ", engaged " +
                  ((state & canopen::kStateEngaged) ? "yes" : "no") +
                  Fmt("   (%.1f s)", Since(t0)));
  return act;
}

Expected<StagedTable> StageTable(Session& s,
                                 const std::string& label,
                                 TableBuildResult table,
                                 bool home) {
  StagedTable t;
  t.label = label;
  t.table = std::move(table);
  VOLCOMP_TRY_ASSIGN(t.upload, Upload(s, t.table));
  VOLCOMP_TRY_ASSIGN(t.activation, Activate(s, t.table.crc32, home));
  return t;
}

void RunSpeedBenchmark(Session& s, DemoResult& r) {
  World& world = s.world;
  const Layout& l = s.layout;
  const Machine& m = world.machine();
  const double d = std::min({l.hi[0] - l.lo[0], l.hi[1] - l.lo[1], l.hi[2] - l.lo[2]});
  const std::array<int64_t, 3> a = {std::llround(l.lo[0] / m.step_mm(0)),
                                    std::llround(l.lo[1] / m.step_mm(1)),
                                    std::llround(l.lo[2] / m.step_mm(2))};
  std::array<int64_t, 3> b = a;
  for (size_t i = 0; i < 3; ++i) b[i] += std::llround(d / m.step_mm(static_cast<int>(i)));
  world.cnc().QueueRapid(a);
  world.RunUntilCncIdle(60 * kSecond_ns);
  const uint64_t steps0 = world.cnc().steps_emitted();
  const uint64_t v0 = world.now_ns();
  const auto t0 = Clock::now();
  for (int k = 0; k < s.o.benchmark_moves; ++k) world.cnc().QueueRapid(k % 2 == 0 ? b : a);
  world.RunUntilCncIdle(600 * kSecond_ns);
  BenchmarkFigures& f = r.benchmark;
  f.wall_s = Since(t0);
  f.steps = world.cnc().steps_emitted() - steps0;
  f.virtual_s = static_cast<double>(world.now_ns() - v0) * 1e-9;
  f.steps_per_s = f.wall_s > 0 ? static_cast<double>(f.steps) / f.wall_s : 0;
  world.RunFor(20000000);
  world.CheckAtRest();
  char line[200];
  std::snprintf(line, sizeof line,
                "%llu steps (%.2f s of machine time) in %.2f s wall: %.1f M steps/s "
                "(%.1f M input + output pulses/s)",
                static_cast<unsigned long long>(f.steps), f.virtual_s, f.wall_s,
                f.steps_per_s / 1e6, 2 * f.steps_per_s / 1e6);
  s.progress.Line(line);
}

void CollectFigures(World& world, DemoResult& r) {
  r.audit = world.Audit();
  r.latency = world.latency().Summarize();
  r.latency_histogram = world.latency().histogram();
  r.peak_input_rate_hz = world.cnc().peak_step_rate_hz();
  r.virtual_s = static_cast<double>(world.now_ns()) * 1e-9;
}

}  // namespace demo
}  // namespace volcomp::sim
