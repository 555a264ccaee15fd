// `volcomp-sim demo`: measure -> evaluate -> build -> upload -> reference -> activate ->
// re-measure.
#include "volcomp/sim/demo.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "volcomp/firmware/board_objects.hpp"
#include "volcomp/metrology/test_program.hpp"
#include "volcomp/sim/random.hpp"
#include "volcomp/tools/hex.hpp"

namespace volcomp::sim {
namespace {

using Clock = std::chrono::steady_clock;
using tools::Hex32;

constexpr uint64_t kSecond_ns = 1000000000ull;

double Since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string Fmt(const char* format, double a) {
  char b[64];
  std::snprintf(b, sizeof b, format, a);
  return b;
}

// Prints "[n/N] step" headings and indented lines as the demo goes.
class Progress {
 public:
  Progress(std::ostream& out, int steps) : out_(out), steps_(steps) {}
  void Step(const std::string& text) {
    out_ << "\n[" << ++n_ << "/" << steps_ << "] " << text << "\n" << std::flush;
  }
  void Line(const std::string& text) { out_ << "    " << text << "\n" << std::flush; }
  std::ostream& out() { return out_; }

 private:
  std::ostream& out_;
  int steps_;
  int n_ = 0;
};

struct Layout {
  Point3 lo, hi;              // travel of the error tables
  Point3 inner_lo, inner_hi;  // test box (margin inside)
  Point3 centre;
  Point3 reference;  // where the parametric lines meet: the command origin
};

SimResult<Layout> MakeLayout(const Machine& m, double margin) {
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
      return SimStatus(Error::kInvalidArgument,
                       std::string("the model's ") + "XYZ"[a] +
                           " table must include position 0 (the reference point)");
    }
    l.reference[i] = 0.0;
  }
  return l;
}

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

// Everything one demo run shares: the installation, the instruments, the test plans.
struct Session {
  const DemoOptions& o;
  Progress& progress;
  World& world;
  Layout layout;
  LaserInterferometer laser;
  LaserTracker tracker;
  std::array<GostPlan, 3> gost;  // the plans every measuring phase runs
  std::vector<Point3> points;    // the reference point, then the random points
};

// The GOST 27843 plans of the three axes and the random points (from `rng`, in this order).
void PlanTests(Session& s, Random& rng) {
  const Layout& l = s.layout;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    metrology::TargetPlan tp;
    tp.start = l.inner_lo[i];
    tp.end = l.inner_hi[i];
    tp.count = s.o.gost_targets;
    tp.pitch = s.o.gost_pitch_mm;
    tp.seed = static_cast<uint32_t>(rng.Next() & 0x7FFFFFFF);
    s.gost[i].targets_mm = metrology::PlanGostTargets(tp);
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
}

// Homing: the CNC finds the switches, the board references on their edges.
SimStatus Home(World& world) {
  world.cnc().QueueHome(7);
  if (!world.RunUntilCncIdle(120 * kSecond_ns)) {
    return SimStatus(Error::kNotReady, "homing did not finish within 120 s");
  }
  return SimStatus::Ok();
}

// Step 1: power-up homing; checks that the board and the CNC agree on the positions.
SimStatus HomeAtPowerUp(Session& s, DemoResult& r) {
  const auto t0 = Clock::now();
  VOLCOMP_SIM_TRY(Home(s.world));
  s.world.RunFor(20000000);
  const ControlTick& e = s.world.board().app().engine();
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
  return SimStatus::Ok();
}

// Steps 2 and 7: GOST 27843 per axis, ISO 230-6 body diagonals, random points.
SimResult<PhaseResults> MeasurePhase(Session& s) {
  PhaseResults r;
  for (int a = 0; a < 3; ++a) {
    const size_t i = static_cast<size_t>(a);
    const auto t0 = Clock::now();
    VOLCOMP_SIM_ASSIGN(r.gost[i], MeasureGostAxis(s.world, s.laser, a, s.gost[i]));
    s.progress.Line(GostLine(a == 0   ? "X"
                             : a == 1 ? "Y"
                                      : "Z",
                             r.Gost()[i]) +
                    Fmt("   (%.1f s)", Since(t0)));
  }
  {
    const auto t0 = Clock::now();
    CycleOptions c;
    c.runs = s.o.diagonal_runs;
    c.dwell_s = s.o.dwell_s;
    c.feed_mm_s = s.o.test_feed_mm_s;
    VOLCOMP_SIM_ASSIGN(
        r.diagonals,
        MeasureDiagonals(s.world, s.laser, BodyDiagonals(s.layout.inner_lo, s.layout.inner_hi),
                         s.o.diagonal_targets, c));
    std::string e;
    for (const auto& d : r.diagonals.evaluation.diagonals) {
      e += d.name.text + " " + Fmt("%.2f", d.E.value) + "  ";
    }
    s.progress.Line("ISO 230-6 body diagonals, E_i (um): " + e);
    s.progress.Line(Fmt("ISO 230-6 E_d = %.3f um", r.Ed()) + Fmt(", B_d = %.3f um", r.Bd()) +
                    Fmt("   (%.1f s)", Since(t0)));
  }
  {
    const auto t0 = Clock::now();
    VOLCOMP_SIM_ASSIGN(r.points, MeasurePointSet(s.world, s.tracker, s.points, s.o.dwell_s));
    char b[200];
    std::snprintf(b, sizeof b,
                  "volumetric error at %zu random points (tracker): max %.2f um, rms %.2f um "
                  "(machine model: max %.2f, rms %.2f)   (%.1f s)",
                  r.points.targets_mm.size(), r.points.max_um, r.points.rms_um,
                  r.points.true_max_um, r.points.true_rms_um, Since(t0));
    s.progress.Line(b);
  }
  return r;
}

// Step 3: the six error motions of each axis along a line through the reference point.
SimStatus MeasureErrorMotions(Session& s, DemoResult& r) {
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
    VOLCOMP_SIM_ASSIGN(r.parametric[i],
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
  }
  s.progress.Line(Fmt("(%.1f s)", Since(t0)));
  return SimStatus::Ok();
}

// Step 4: the measured model, inverted into a GRID3 image.
SimStatus BuildTable(Session& s, DemoResult& r) {
  const auto t0 = Clock::now();
  VOLCOMP_SIM_ASSIGN(r.measured_model,
                     ModelFromParametric(r.parametric, s.world.machine().model().chain));
  const Machine& m = s.world.machine();
  const double h = s.o.grid_spacing_mm;
  r.table = BuildTableImage(r.measured_model, s.layout.lo, s.layout.hi, {h, h, h},
                            {m.step_mm(0), m.step_mm(1), m.step_mm(2)}, 1);
  const model::GridSpec& g = r.table.grid.grid.axes;
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
                r.table.grid.stats.max_correction_um, r.table.grid.stats.max_residual_um,
                r.table.grid.interpolation.max_um);
  s.progress.Line(b);
  std::snprintf(b, sizeof b,
                "image: %zu bytes, int16 with %u fraction bits (LSB %.4f um), "
                "CRC-32 0x%08X   (%.1f s)",
                r.table.image.size(), r.table.frac_bits, r.table.lsb_um, r.table.crc32, Since(t0));
  s.progress.Line(b);
  return SimStatus::Ok();
}

// Step 5: the image over the simulated bus with the PC tool's SDO code.
SimStatus Upload(Session& s, DemoResult& r) {
  const auto t0 = Clock::now();
  VOLCOMP_SIM_ASSIGN(r.upload, UploadTable(s.world, r.table.image, s.progress.out()));
  char b[240];
  std::snprintf(b, sizeof b,
                "%u bytes in %.2f s of bus time (%.1f kB/s, %llu frames, %u segments resent); "
                "board verified it, staged CRC-32 0x%08X   (%.1f s)",
                r.upload.bytes, r.upload.transfer_s, r.upload.rate_bytes_s / 1000,
                static_cast<unsigned long long>(r.upload.frames), r.upload.resent_segments,
                r.upload.staged_crc, Since(t0));
  s.progress.Line(b);
  return SimStatus::Ok();
}

// Step 6: home again (the board references), activate, let the correction ramp in.
SimStatus ReferenceAndActivate(Session& s, DemoResult& r) {
  const auto t0 = Clock::now();
  VOLCOMP_SIM_TRY(Home(s.world));
  s.world.RunFor(150000000);  // activation needs 100 ms without input steps
  VOLCOMP_SIM_ASSIGN(r.activation, ActivateTable(s.world, r.table.crc32));
  s.world.RunFor(500000000);  // the correction ramps in within the rate limits
  const uint16_t state = ReadDeviceState(s.world);
  r.activation.device_state = state;
  s.progress.Line(std::string("active table CRC-32 ") + Hex32(r.activation.active_crc) +
                  "; device state: referenced " +
                  ((state & firmware::kStateReferenced) ? "yes" : "no") + ", engaged " +
                  ((state & firmware::kStateEngaged) ? "yes" : "no") +
                  Fmt("   (%.1f s)", Since(t0)));
  return SimStatus::Ok();
}

// Step 8: rapid moves with X, Y and Z each at 1 MHz through the compensating board.
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

// The step audit, latency and rates of the whole run.
void CollectFigures(World& world, DemoResult& r) {
  r.audit = world.Audit();
  r.latency = world.latency().Summarize();
  r.latency_histogram = world.latency().histogram();
  r.peak_input_rate_hz = world.cnc().peak_step_rate_hz();
  r.virtual_s = static_cast<double>(world.now_ns()) * 1e-9;
}

// The "must show" checks; each failed one is named in r.failures.
void Check(double step_um, DemoResult& r) {
  auto check = [&](bool ok, const std::string& what) {
    if (!ok) r.failures.push_back(what);
  };
  check(r.after.Ed() <= 0.05 * r.before.Ed() || r.after.Ed() <= step_um,
        "ISO 230-6 E_d not reduced by 95 %");
  check(r.after.points.max_um <= 0.05 * r.before.points.max_um || r.after.points.max_um <= step_um,
        "max volumetric error at the random points not reduced by 95 %");
  check(r.audit.lost_steps == 0 && r.audit.tick_mismatches == 0, "lost steps");
  check(r.audit.timing_violations == 0, "pulse timing violations");
  check(r.latency.max_ticks <= 2.0 && r.latency.unmatched == 0, "latency above 2 ticks");
  check(r.reference_agrees, "board and CNC disagree after homing");
  check((r.activation.device_state & firmware::kStateEngaged) != 0, "table not engaged");
}

double Reduction(double before, double after) {
  return before > 0 ? 100.0 * (1.0 - after / before) : 0.0;
}

}  // namespace

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

SimResult<DemoResult> RunDemo(const DemoOptions& o, std::ostream& log) {
  const auto wall0 = Clock::now();
  DemoResult r;
  r.options = o;
  Progress progress(log, 8);

  WorldOptions wo;
  wo.machine.model = LoadMachineModel(o.model_spec);
  r.machine_name = wo.machine.model.name;
  wo.board = BoardSettingsFor(Machine(wo.machine));
  wo.cnc.accel_mm_s2 = o.accel_mm_s2;
  World world(wo);
  if (const Status started = world.Start(); !started.ok()) {
    return SimStatus(started.error(), std::string("the simulated board did not start: ") +
                                          ErrorText(started.error()));
  }
  r.tick_us = static_cast<double>(world.tick_ns()) / 1000.0;
  Layout layout;
  VOLCOMP_SIM_ASSIGN(layout, MakeLayout(world.machine(), o.margin_mm));
  Random rng(o.seed);
  Session s{o,
            progress,
            world,
            layout,
            LaserInterferometer(&world.machine(), o.laser, rng.Next()),
            LaserTracker(&world.machine(), o.tracker, rng.Next()),
            {},
            {}};
  PrintSetup(s, r, wo);
  PlanTests(s, rng);

  progress.Step(
      "power-up and homing: home switches 5 mm below the travel, board references on "
      "their edges");
  VOLCOMP_SIM_TRY(HomeAtPowerUp(s, r));
  progress.Step(
      "measuring the uncompensated machine (GOST 27843 per axis, ISO 230-6 diagonals, "
      "random points)");
  VOLCOMP_SIM_ASSIGN(r.before, MeasurePhase(s));
  progress.Step(
      "measuring the six error motions of X, Y, Z through the reference point "
      "(virtual 6-DOF laser, like XL-80 linear/straightness/angular setups)");
  VOLCOMP_SIM_TRY(MeasureErrorMotions(s, r));
  progress.Step("building the table from the measurements");
  VOLCOMP_SIM_TRY(BuildTable(s, r));
  progress.Step("uploading over the simulated CAN bus (PC tool's SDO client, block transfer)");
  VOLCOMP_SIM_TRY(Upload(s, r));
  progress.Step("homing again (references the axes), activating the table");
  VOLCOMP_SIM_TRY(ReferenceAndActivate(s, r));
  progress.Step("re-measuring the compensated machine (same programs, fresh instrument noise)");
  VOLCOMP_SIM_ASSIGN(r.after, MeasurePhase(s));
  progress.Step("simulator speed: rapid moves with X, Y and Z each at 1 MHz through the board");
  RunSpeedBenchmark(s, r);

  CollectFigures(world, r);
  r.wall_s = Since(wall0);
  Check(1000 * world.machine().step_mm(0), r);
  return r;
}

void PrintSummary(const DemoResult& r, std::ostream& out) {
  char b[256];
  out << "\n== before / after compensation ==========================================\n";
  out << "                                                  before        after   reduction\n";
  // `reduce`: print the reduction (not for noise-level figures such as R and B here: the model
  // has no backlash and no random positioning error, so they are instrument noise).
  auto row = [&](const std::string& label, double before, double after, bool reduce = true) {
    char line[256];
    if (reduce) {
      std::snprintf(line, sizeof line, "%-44s %9.3f um %9.3f um   %6.2f %%\n", label.c_str(),
                    before, after, Reduction(before, after));
    } else {
      std::snprintf(line, sizeof line, "%-44s %9.3f um %9.3f um   (noise)\n", label.c_str(), before,
                    after);
    }
    out << line;
  };
  row("ISO 230-6 E_d (4 body diagonals)", r.before.Ed(), r.after.Ed());
  row("ISO 230-6 B_d", r.before.Bd(), r.after.Bd(), false);
  row("volumetric error, max of " + std::to_string(r.after.points.targets_mm.size()) +
          " points (tracker)",
      r.before.points.max_um, r.after.points.max_um);
  row("  rms (tracker)", r.before.points.rms_um, r.after.points.rms_um);
  row("  max, machine model (no instrument error)", r.before.points.true_max_um,
      r.after.points.true_max_um);
  const auto gb = r.before.Gost(), ga = r.after.Gost();
  for (size_t a = 0; a < 3; ++a) {
    const char axis = "XYZ"[a];
    std::string label = std::string("GOST 27843 ") + axis + "  A (accuracy)";
    row(label, gb[a].A, ga[a].A);
    label = std::string("GOST 27843 ") + axis + "  R (repeatability)";
    row(label, gb[a].R, ga[a].R, false);
    label = std::string("GOST 27843 ") + axis + "  B (reversal)";
    row(label, gb[a].B, ga[a].B, false);
  }
  out << "\n== steps, timing, latency, speed =========================================\n";
  std::snprintf(b, sizeof b,
                "input steps %llu, output steps %llu, peak input rate %.3f MHz per axis\n",
                static_cast<unsigned long long>(r.audit.input_steps),
                static_cast<unsigned long long>(r.audit.output_steps), r.peak_input_rate_hz / 1e6);
  out << b;
  std::snprintf(b, sizeof b,
                "lost steps: %llu (drive == CNC steps + correction at %llu rest points; drive == "
                "board output at every one of %llu ticks: %llu mismatches)\n",
                static_cast<unsigned long long>(r.audit.lost_steps),
                static_cast<unsigned long long>(r.audit.rest_checks),
                static_cast<unsigned long long>(r.audit.ticks),
                static_cast<unsigned long long>(r.audit.tick_mismatches));
  out << b;
  std::snprintf(b, sizeof b,
                "pulse timing violations at the drives: %llu; backlog overruns: %u, largest "
                "backlog %u steps\n",
                static_cast<unsigned long long>(r.audit.timing_violations), r.audit.overruns,
                r.audit.max_backlog);
  out << b;
  std::snprintf(b, sizeof b,
                "latency input step -> output step (tick %.0f us, %llu steps): p50 %.2f, p90 "
                "%.2f, p99 %.2f, p99.9 %.2f, max %.3f ticks; > 2 ticks: %llu; unmatched: %llu\n",
                r.tick_us, static_cast<unsigned long long>(r.latency.samples), r.latency.p50_ticks,
                r.latency.p90_ticks, r.latency.p99_ticks, r.latency.p999_ticks, r.latency.max_ticks,
                static_cast<unsigned long long>(r.latency.over_2_ticks),
                static_cast<unsigned long long>(r.latency.unmatched));
  out << b;
  std::snprintf(b, sizeof b,
                "simulator speed: %.1f M steps/s (3 axes at 1 MHz; goal >= 10 M/s); whole demo: "
                "%.1f s of machine time, %.1f M steps in %.1f s wall (%.1f M steps/s)\n",
                r.benchmark.steps_per_s / 1e6, r.virtual_s,
                static_cast<double>(r.audit.input_steps) / 1e6, r.wall_s,
                static_cast<double>(r.audit.input_steps) / r.wall_s / 1e6);
  out << b;
  if (r.failures.empty()) {
    out << "\nall checks passed: residual >= 95 % below uncompensated (E_d and random points), "
           "zero lost steps, zero timing violations, latency <= 2 ticks\n";
  } else {
    out << "\nFAILED:";
    for (const std::string& f : r.failures) out << " " << f << ";";
    out << "\n";
  }
}

}  // namespace volcomp::sim
