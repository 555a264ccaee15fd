// `volcomp-sim demo`: the steps strung together for the ideal and the worn machine, and the
// checks of each.
#include "volcomp/sim/demo.hpp"

#include <memory>
#include <utility>

#include "demo_session.hpp"
#include "volcomp/firmware/board_objects.hpp"

namespace volcomp::sim {
namespace {

using demo::Clock;
using demo::Session;

// The "must show" checks of every run; each failed one is named in r.failures.
void CheckRun(DemoResult& r) {
  auto check = [&](bool ok, const std::string& what) {
    if (!ok) r.failures.push_back(what);
  };
  check(r.audit.lost_steps == 0 && r.audit.tick_mismatches == 0, "lost steps");
  check(r.audit.timing_violations == 0, "pulse timing violations");
  check(r.latency.max_ticks <= 2.0 && r.latency.unmatched == 0, "latency above 2 ticks");
  check(r.reference_agrees, "board and CNC disagree after homing");
  check((r.activation.device_state & canopen::kStateEngaged) != 0, "table not engaged");
}

// The ideal machine's figures: 95 % below uncompensated (or within one step).
void CheckIdeal(double step_um, DemoResult& r) {
  if (!(r.after.Ed() <= 0.05 * r.before.Ed() || r.after.Ed() <= step_um)) {
    r.failures.push_back("ISO 230-6 E_d not reduced by 95 %");
  }
  if (!(r.after.points.max_um <= 0.05 * r.before.points.max_um ||
        r.after.points.max_um <= step_um)) {
    r.failures.push_back("max volumetric error at the random points not reduced by 95 %");
  }
}

void Keep(DemoResult& r, StagedTable t) {
  r.table_label = t.label;
  r.table = std::move(t.table);
  r.upload = t.upload;
  r.activation = t.activation;
}

// Steps 3-8 on the ideal machine: error motions, table, upload, activation, re-measuring.
Outcome RunIdeal(Session& s, DemoResult& r) {
  demo::Progress& progress = s.progress;
  progress.Step(
      "measuring the six error motions of X, Y, Z through the reference point "
      "(virtual 6-DOF laser, like XL-80 linear/straightness/angular setups)");
  VOLCOMP_TRY(demo::MeasureErrorMotions(s, r));
  progress.Step("building the table from the measurements");
  const auto t0 = Clock::now();
  VOLCOMP_TRY_ASSIGN(builders::GridSection grid, demo::BuildModelGrid(s, r));
  r.table_label = "21-param";
  VOLCOMP_TRY_ASSIGN(
      r.table, AssembleTable(
                   std::move(grid), {}, s.step_mm(), 1,
                   {{"builder", "volcomp-sim demo (the sources and grid of `volcomp build model`)"},
                    {"source", "measured 21-parameter model: 6-DOF laser runs of X, Y, Z"}}));
  demo::PrintImageLine(s, r.table, t0);
  progress.Step("uploading over the simulated CAN bus (PC tool's SDO client, block transfer)");
  VOLCOMP_TRY_ASSIGN(r.upload, demo::Upload(s, r.table));
  progress.Step("homing again (references the axes), activating the table");
  VOLCOMP_TRY_ASSIGN(r.activation, demo::Activate(s, r.table.crc32, true));
  progress.Step("re-measuring the compensated machine (same programs, fresh instrument noise)");
  VOLCOMP_TRY_ASSIGN(r.after, demo::MeasurePhase(s, r));
  return Outcome::Ok();
}

// Steps 3-9 on the worn machine: the three compensations, each re-measured.
Outcome RunWorn(Session& s, DemoResult& r) {
  demo::Progress& progress = s.progress;
  const std::array<double, 3> step = s.step_mm();
  progress.Step(
      "measuring the six error motions of X, Y, Z through the reference point "
      "(virtual 6-DOF laser), mean of the runs up and down");
  VOLCOMP_TRY(demo::MeasureErrorMotions(s, r));

  progress.Step("table 1: GRID3 from the 21-parameter measurements; upload, reference, activate");
  auto t0 = Clock::now();
  VOLCOMP_TRY_ASSIGN(const builders::GridSection model_grid, demo::BuildModelGrid(s, r));
  VOLCOMP_TRY_ASSIGN(
      TableBuildResult t1,
      AssembleTable(
          model_grid, {}, step, 1,
          {{"builder", "volcomp-sim demo (the sources and grid of `volcomp build model`)"},
           {"source", "measured 21-parameter model: 6-DOF laser runs of X, Y, Z"}}));
  demo::PrintImageLine(s, t1, t0);
  VOLCOMP_TRY_ASSIGN(StagedTable staged, demo::StageTable(s, "21-param", std::move(t1), true));
  r.earlier_tables.push_back(std::move(staged));
  progress.Step("re-measuring with table 1 (21-parameter GRID3)");
  r.intermediate.push_back({"21-param", {}});
  VOLCOMP_TRY_ASSIGN(r.intermediate.back().results, demo::MeasurePhase(s, r));

  progress.Step(
      "table 2: AXIS1D forward/reverse tables from bidirectional ISO 230-2 runs (table 1 "
      "active), with the GRID3 of table 1");
  VOLCOMP_TRY_ASSIGN(const std::vector<builders::AxisSection> axis_tables,
                     demo::MeasureAxisTables(s, r));
  t0 = Clock::now();
  VOLCOMP_TRY_ASSIGN(
      TableBuildResult t2,
      AssembleTable(
          model_grid, axis_tables, step, 2,
          {{"builder",
            "volcomp-sim demo (the entry points of `volcomp build model` and `build axis`)"},
           {"source", "measured 21-parameter model + ISO 230-2 runs"}}));
  demo::PrintImageLine(s, t2, t0);
  VOLCOMP_TRY_ASSIGN(staged, demo::StageTable(s, "21-param + AXIS1D", std::move(t2), false));
  r.earlier_tables.push_back(std::move(staged));
  progress.Step("re-measuring with table 2 (21-parameter GRID3 + AXIS1D)");
  r.intermediate.push_back({"+AXIS1D", {}});
  VOLCOMP_TRY_ASSIGN(r.intermediate.back().results, demo::MeasurePhase(s, r));

  progress.Step(
      "table 3: laser tracker at every node of a lattice, measured through table 2; its GRID3 "
      "(composed with table 2's) with the AXIS1D tables");
  const size_t first_check = r.drift.size() - 1;  // the check after the last test of table 2
  VOLCOMP_TRY_ASSIGN(builders::GridSection lattice_grid,
                     demo::MeasureTrackerLattice(s, r, r.earlier_tables.back().table.image));
  t0 = Clock::now();
  VOLCOMP_TRY_ASSIGN(
      TableBuildResult t3,
      AssembleTable(
          std::move(lattice_grid), axis_tables, step, 3,
          {{"builder",
            "volcomp-sim demo (the entry points of `volcomp build tracker --lattice --through` "
            "and `build axis`)"},
           {"source", "laser-tracker lattice through table 2 + ISO 230-2 runs"}}));
  demo::PrintImageLine(s, t3, t0);
  VOLCOMP_TRY_ASSIGN(staged, demo::StageTable(s, "tracker + AXIS1D", std::move(t3), false));
  Keep(r, std::move(staged));
  VOLCOMP_TRY(demo::CheckDrift(s, r, "table 3 activated"));
  progress.Step("re-measuring with table 3 (tracker-lattice GRID3 + AXIS1D)");
  r.after_label = "tracker";
  VOLCOMP_TRY_ASSIGN(r.after, demo::MeasurePhase(s, r));
  demo::EvaluateWornGoals(s, r, first_check);
  if (s.world.machine().wear().thermal) {
    progress.Step(
        "thermal: a drift test on the heat-balance machine (calibration duty cycle), the model "
        "fitted (`volcomp build thermal`) into table 3's image; the verification duty cycle with "
        "the firmware in the loop, without and with it, two sensor faults injected");
    VOLCOMP_TRY(demo::RunThermal(s, r));
    demo::EvaluateThermalGoals(r);
  }
  return Outcome::Ok();
}

}  // namespace

void UseWornMachine(DemoOptions* o) {
  o->machine = MachineProfile::kWorn;
  o->wear = DefaultWornProfile(o->seed);
  o->laser.misalignment_mrad = 1.0;
}

bool SwitchOff(const std::string& source, DemoOptions* o) {
  WornMachineProfile& w = o->wear;
  if (source == "lost-motion") {
    w.lost_motion = false;
  } else if (source == "scatter") {
    w.scatter = false;
  } else if (source == "screw") {
    w.screw_error = false;
  } else if (source == "thermal") {
    w.thermal = false;
  } else if (source == "sag") {
    w.cross_axis_sag = false;
  } else if (source == "misalignment") {
    o->laser.misalignment_mrad = 0;
  } else {
    return false;
  }
  return true;
}

Expected<DemoResult> RunDemo(const DemoOptions& o, std::ostream& log) {
  const auto wall0 = Clock::now();
  const bool worn = o.machine == MachineProfile::kWorn;
  DemoResult r;
  r.options = o;
  demo::Progress progress(log, worn ? (o.wear.thermal ? 11 : 10) : 8);

  WorldOptions wo;
  VOLCOMP_TRY_ASSIGN(wo.machine.model, LoadMachineModel(o.model_spec));
  if (worn) {
    wo.machine.wear = o.wear;
    wo.machine.wear.seed = o.seed ^ 0x6d616368696e65ull;  // the machine's own random stream
  }
  r.machine_name = wo.machine.model.name + (worn ? ", worn" : "");
  {
    VOLCOMP_TRY_ASSIGN(const Machine machine, Machine::Create(wo.machine));
    wo.board = BoardSettingsFor(machine);
  }
  wo.cnc.accel_mm_s2 = o.accel_mm_s2;
  VOLCOMP_TRY_ASSIGN(const std::unique_ptr<World> installation, World::Create(wo));
  World& world = *installation;
  VOLCOMP_TRY(world.Start());
  r.tick_us = static_cast<double>(world.tick_ns()) / 1000.0;
  VOLCOMP_TRY_ASSIGN(const demo::Layout layout, demo::MakeLayout(world.machine(), o.margin_mm));
  Random rng(o.seed);
  Session s{o,
            progress,
            world,
            layout,
            LaserInterferometer(&world.machine(), o.laser, rng.Next()),
            LaserTracker(&world.machine(), o.tracker, rng.Next()),
            {},
            {},
            worn,
            LaserTracker(&world.machine(), o.tracker, Random(o.seed ^ 0x6472696674ull).Next()),
            {layout.inner_hi[0], layout.centre[1], layout.centre[2]},
            0};
  r.error_sources = demo::ErrorSources(s);
  r.circle_centre_mm = layout.centre;
  demo::PrintSetup(s, r, wo);
  VOLCOMP_TRY(demo::PlanTests(s, rng));

  progress.Step(
      "power-up and homing: home switches 5 mm below the travel, board references on "
      "their edges");
  VOLCOMP_TRY(demo::HomeAtPowerUp(s, r));
  if (worn) {
    demo::PrintWarmUp(s);
    VOLCOMP_TRY(demo::CheckDrift(s, r, ""));
  }
  progress.Step(
      "measuring the uncompensated machine (GOST 27843 per axis, ISO 230-6 diagonals, "
      "random points)");
  VOLCOMP_TRY_ASSIGN(r.before, demo::MeasurePhase(s, r));
  VOLCOMP_TRY(worn ? RunWorn(s, r) : RunIdeal(s, r));
  progress.Step("simulator speed: rapid moves with X, Y and Z each at 1 MHz through the board");
  demo::RunSpeedBenchmark(s, r);

  demo::CollectFigures(world, r);
  r.wall_s = demo::Since(wall0);
  if (!worn) CheckIdeal(1000 * world.machine().step_mm(0), r);
  CheckRun(r);
  return r;
}

}  // namespace volcomp::sim
