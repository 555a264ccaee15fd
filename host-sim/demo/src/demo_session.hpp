// The steps of `volcomp-sim demo` (private to host-sim/demo): the session every step works on and
// one function per step. RunDemo (demo.cpp) strings them together for each machine profile.
#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "volcomp/sim/demo.hpp"
#include "volcomp/sim/random.hpp"

namespace volcomp::sim::demo {

using Clock = std::chrono::steady_clock;
constexpr uint64_t kSecond_ns = 1000000000ull;

double Since(Clock::time_point t0);
std::string Fmt(const char* format, double a);

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

Expected<Layout> MakeLayout(const Machine& m, double margin);

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
  // Worn machine: the drift checks (a tracker that stays registered at the first check).
  bool drift_checks = false;
  LaserTracker drift_tracker;
  Point3 check_point = {0, 0, 0};
  int epoch = 0;  // the table in force, for the drift checks

  std::array<double, 3> step_mm() {
    return {world.machine().step_mm(0), world.machine().step_mm(1), world.machine().step_mm(2)};
  }
};

// The GOST 27843 plans of the three axes and the random points (from `rng`, in this order).
Outcome PlanTests(Session& s, Random& rng);
// The installation; the worn machine's also lists r.error_sources.
void PrintSetup(Session& s, const DemoResult& r, const WorldOptions& wo);
// The machine's error sources with their sizes, read from the machine and the instruments'
// options (demo_sources.cpp; DemoResult::error_sources).
tools::JsonValue ErrorSources(Session& s);
void PrintErrorSources(const tools::JsonValue& sources, Progress& progress);

Outcome Home(World& world);
// Power-up homing; checks that the board and the CNC agree on the positions.
Outcome HomeAtPowerUp(Session& s, DemoResult& r);
// GOST 27843 per axis, ISO 230-6 body diagonals, random points (a drift check after each test
// when the session has them).
Expected<PhaseResults> MeasurePhase(Session& s, DemoResult& r);
// The ISO 230-4 circular test in XY, XZ and YZ about the centre of the travel (demo_circular.cpp):
// `volcomp program circular`'s program through the board, a ballbar at the centre.
Expected<std::vector<CircularTestResult>> MeasureCircularTests(Session& s);
// The six error motions of each axis along a line through the reference point.
Outcome MeasureErrorMotions(Session& s, DemoResult& r);
// The measured model and its GRID3 section (ModelGridSource, BuildGridSection).
Expected<builders::GridSection> BuildModelGrid(Session& s, DemoResult& r);
// Prints the image's size, encoding and CRC-32.
void PrintImageLine(Session& s, const TableBuildResult& t, Clock::time_point t0);
// Upload over the simulated bus with the PC tool's SDO code; the board verifies it.
Expected<UploadReport> Upload(Session& s, const TableBuildResult& table);
// (`home`: home again, the board references,) rest, activate, let the correction ramp in.
Expected<ActivationReport> Activate(Session& s, uint32_t crc32, bool home);
// Upload, then activation.
Expected<StagedTable> StageTable(Session& s,
                                 const std::string& label,
                                 TableBuildResult table,
                                 bool home);
// Rapid moves with X, Y and Z each at 1 MHz through the compensating board.
void RunSpeedBenchmark(Session& s, DemoResult& r);
// The step audit, latency and rates of the whole run.
void CollectFigures(World& world, DemoResult& r);

// Worn machine (demo_worn.cpp).
// Reads the drift check point with the tracker (registers the tracker at the first call).
Outcome CheckDrift(Session& s, DemoResult& r, const std::string& after);
// Drift between checks `from` and `to` (indices into r.drift): the sum of the differences of
// consecutive checks under the same table; `span_s` gets the time covered, `gap_s` the time of
// table changes in between (not covered).
model::Vec3 DriftBetween(
    const std::vector<DriftCheck>& checks, size_t from, size_t to, double* span_s, double* gap_s);
// Prints the thermal state the warm-up left (the drift rates at time 0).
void PrintWarmUp(Session& s);
// Bidirectional ISO 230-2 runs along the centre lines at the compensation pitch, and the AXIS1D
// tables from their mean deviations (BuildAxisSection).
Expected<std::vector<builders::AxisSection>> MeasureAxisTables(Session& s, DemoResult& r);
// Tracker readings at every node of a lattice over the travel, measured through the table in
// force (`in_force`, its image), and the GRID3 section that replaces that table's
// (GridOfImage, TrackerLatticeThroughGridSource, BuildGridSection).
Expected<builders::GridSection> MeasureTrackerLattice(Session& s,
                                                      DemoResult& r,
                                                      const std::vector<uint8_t>& in_force);
// The error budget of the last phase and the goals of the worn profile.
void EvaluateWornGoals(Session& s, DemoResult& r, size_t first_check_of_last_table);
// A goal with its verdict; a failed asserted one is also a failure of the run.
void AddGoal(DemoResult& r,
             const std::string& what,
             double value,
             double limit,
             bool at_least,
             bool asserted = true,
             const std::string& unit = "");

// The thermal step (demo_thermal.cpp): the drift test, the fitted model in table 3's image, the
// verification cycle with the firmware in the loop without and with it; and its goals.
Outcome RunThermal(Session& s, DemoResult& r);
void EvaluateThermalGoals(DemoResult& r);

}  // namespace volcomp::sim::demo
