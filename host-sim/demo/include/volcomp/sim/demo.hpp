// `volcomp-sim demo`'s run: the main job on the simulated installation, end to end (measure,
// evaluate, build the table, upload, reference, activate, re-measure; the steps of the ideal
// machine are docs/simulator.md §2, the worn machine's three tables §7.2), its summary and its
// report. Deterministic for a given seed (the wall-clock figures aside). Lengths mm, errors µm.
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "volcomp/builders/thermal_fit.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/circular.hpp"
#include "volcomp/model/tracker_lattice.hpp"
#include "volcomp/sim/board_session.hpp"
#include "volcomp/sim/instruments.hpp"
#include "volcomp/sim/latency_meter.hpp"
#include "volcomp/sim/measurements.hpp"
#include "volcomp/sim/table_from_measurements.hpp"
#include "volcomp/sim/thermal_loop.hpp"
#include "volcomp/sim/world.hpp"
#include "volcomp/sim/worn_profile.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::sim {

enum class MachineProfile { kIdeal, kWorn };

struct DemoOptions {
  uint64_t seed = 1;
  std::string model_spec = "s500";  // "s500" or a model config file
  std::string report_dir;           // empty: no report
  MachineProfile machine = MachineProfile::kIdeal;
  WornMachineProfile wear;  // used with kWorn (DefaultWornProfile: every source on)
  int gost_targets = 11;
  int gost_runs = 5;
  double gost_pitch_mm = 5;  // P of GOST 27843 §2.7 (lead-screw pitch)
  int diagonal_targets = 11;
  int diagonal_runs = 5;
  int random_points = 200;
  double parametric_step_mm = 10;
  double grid_spacing_mm = 10;
  double margin_mm = 10;         // test lines and diagonals stay this far inside the travel
  double dwell_s = 0.05;         // dwell at every measured stop (virtual)
  double test_feed_mm_s = 1000;  // G1 feed of the test cycles
  double accel_mm_s2 = 10000;
  int benchmark_moves = 6;  // rapid moves with every axis at 1 MHz for the speed figure
  // Worn machine only.
  double axis_run_pitch_mm = 20;   // nodes of the ISO 230-2 runs the AXIS1D tables come from
  double lattice_spacing_mm = 40;  // the tracker lattice
  int drift_readings = 10;         // tracker readings averaged per drift check
  // The ISO 230-4 circular test in XY, XZ and YZ about the centre of the travel in every phase
  // (`volcomp program circular`, a ballbar at the centre; docs/simulator.md 7.2).
  bool circular_tests = true;
  double circle_radius_mm = 50;
  double circle_feed_mm_min = 2000;
  // The thermal step (worn machine, unless `--without thermal`; docs/simulator.md 7.6): the heat
  // balance's drift test, the fitted model, the verification cycle with the firmware in the loop
  // at a lower control tick.
  double thermal_check_interval_s = 300;
  uint32_t thermal_tick_hz = 2000;
  InterferometerOptions laser;
  TrackerOptions tracker;
};

/// The worn-machine profile of the demo: every error source on with its default
/// (DefaultWornProfile) and the interferometer 1 mrad off the line of motion (a beam that walks
/// 0.4 mm over 400 mm: what a quick alignment by eye on the target leaves).
void UseWornMachine(DemoOptions* options);
/// Names of the sources `--without` may switch off: lost-motion, scatter, screw, thermal, sag,
/// misalignment. False for an unknown name.
bool SwitchOff(const std::string& source, DemoOptions* options);

struct AxisFigures {
  double A = 0, R = 0, B = 0;  // GOST 27843: accuracy, repeatability (R_max), reversal (B_max), µm
};

/// One ISO 230-4 circular test of a phase: the program, the ballbar's readings and their
/// evaluation (tools/metrology, as `volcomp evaluate circular`).
struct CircularTestResult {
  std::string plane;  // "XY", "XZ", "YZ"
  std::string gcode;  // `volcomp program circular`'s program
  metrology::CircularData data;
  metrology::CircularResult result;
  double cutting_max_error_um = 0;  // the tool point against the programmed path
};

struct PhaseResults {
  std::array<GostAxisResult, 3> gost;
  DiagonalSetResult diagonals;
  PointSetResult points;
  std::vector<CircularTestResult> circular;  // worn: XY, XZ, YZ
  std::array<AxisFigures, 3> Gost() const;
  double Ed() const;  // ISO 230-6 E_d, µm
  double Bd() const;
};

struct NamedPhase {
  std::string label;  // the compensation in force, e.g. "21-param"
  PhaseResults results;
};

struct BenchmarkFigures {
  uint64_t steps = 0;  // input steps (each also counted, planned and checked as an output step)
  double virtual_s = 0;
  double wall_s = 0;
  double steps_per_s = 0;
};

/// A table the demo built, uploaded and activated.
struct StagedTable {
  std::string label;
  TableBuildResult table;
  UploadReport upload;
  ActivationReport activation;
};

/// The tracker's reading of the drift check point (fixed tracker frame), µm from the first.
struct DriftCheck {
  std::string after;  // the test it follows ("" for the first)
  double time_s = 0;  // machine time
  int epoch = 0;      // the table in force; readings of different epochs are not compared
  model::Vec3 reading_um;
};

/// What remains after the last compensation, term by term (µm).
struct ErrorBudget {
  std::array<double, 3> sigma_um = {0, 0, 0};  // repeatability: GOST S pooled over targets, before
  double three_sigma_um = 0;                   // 3 × √(σx² + σy² + σz²)
  model::Vec3 drift_since_table_um;    // drift check, from the final table's measurement to the end
  double drift_since_table_s = 0;      // the time it spans (unmeasured gaps excluded)
  double unmeasured_s = 0;             // table changes inside that span, not covered by checks
  model::Vec3 drift_during_points_um;  // drift check around the final point-set test
  std::array<double, 3> short_period_um = {0, 0, 0};  // the machine's screw error amplitudes
  double tracker_three_sigma_um = 0;                  // the instrument, per coordinate
  double laser_cosine_um = 0;                         // cosine error over the longest line
  double step_um = 1;
  double limit_um = 0;              // 3σ + |drift since the table| + 1 step (the limit)
  double short_period_norm_um = 0;  // |(A_x, A_y, A_z)|: what no table at the pitch can remove
  double goal_limit_um = 0;         // limit_um + short_period_norm_um: the limit evaluated
};

struct Goal {
  std::string what;
  double value = 0;  // measured (% reduction or µm)
  double limit = 0;
  bool at_least = true;  // value must be >= limit (else <=)
  std::string unit;      // empty: "%" for an at-least goal, "um" otherwise
  bool holds = false;
  // false: printed with its verdict but not a check of the run (not in failures, the exit code):
  // the ISO 230-4 goals, whose residual is within the worn machine's scatter
  // (docs/simulator.md 8.1).
  bool asserted = true;
};

/// The worn machine's thermal step (docs/simulator.md 7.6).
struct ThermalPhase {
  bool ran = false;
  std::string drift_csv;  // the drift test (calibration cycle): the report's drift_test.csv
  double calibration_h = 0;
  size_t calibration_readings = 0;
  std::array<double, 3> calibration_drift_um = {0, 0, 0};
  builders::ThermalFit fit;
  thermal::ThermalModel model;
  std::vector<uint8_t> image;  // table 3 with the THERMAL section
  double verification_h = 0;
  ThermalLoopResult uncompensated;  // table 3 alone
  ThermalLoopResult compensated;    // table 3 with the model, sensor faults injected
  std::array<double, 3> drift_before_um = {0, 0, 0};
  std::array<double, 3> drift_after_um = {0, 0, 0};
  double slew_limit_um_s = 0;
  uint32_t tick_hz = 0;  // the board's control tick in the loop
  double wall_s = 0;
};

struct DemoResult {
  DemoOptions options;
  std::string machine_name;
  // The machine's error sources with their sizes, as the header prints them (geometry, lost
  // motion, scatter, screw, thermal, sag, instruments; docs/simulator.md §4, summary.json).
  tools::JsonValue error_sources;
  PhaseResults before, after;
  std::vector<NamedPhase> intermediate;  // worn: after 21-param, after 21-param + AXIS1D
  std::string after_label = "after";
  std::array<ParametricResult, 3> parametric;
  model::Model measured_model;
  TableBuildResult table;   // the last table (active during `after`)
  std::string table_label;  // its label ("": after_label)
  UploadReport upload;
  ActivationReport activation;
  std::vector<StagedTable> earlier_tables;             // worn: the tables before the last
  std::array<GostAxisResult, 3> axis_runs;             // worn: the ISO 230-2 runs for AXIS1D
  model::TrackerLatticeData lattice;                   // worn: the tracker lattice readings
  std::vector<DriftCheck> drift;                       // worn
  ErrorBudget budget;                                  // worn
  std::vector<Goal> goals;                             // worn
  ThermalPhase thermal;                                // worn
  std::array<double, 3> circle_centre_mm = {0, 0, 0};  // the circular tests' centre (mm)
  bool reference_agrees = false;  // board machine position == CNC position after homing
  StepAudit audit;
  LatencySummary latency;
  std::vector<uint64_t> latency_histogram;
  double tick_us = 0;
  double peak_input_rate_hz = 0;
  BenchmarkFigures benchmark;
  double virtual_s = 0;
  double wall_s = 0;
  std::vector<std::string> failures;  // "must show" checks that failed (empty: all passed)
};

/// Runs the demo; progress goes to `log`. Fails when a step cannot go on (a model file that cannot
/// be read, the board refused a table, a program did not finish, the model's tables miss the
/// reference point, a builder refused the measurements). A run that completes is a value even
/// when checks failed (DemoResult::failures).
Expected<DemoResult> RunDemo(const DemoOptions& options, std::ostream& log);

/// Every figure the summary prints, with the run's parameters: the document --report writes as
/// summary.json (keys: docs/simulator.md §4). Units are in the keys or in a row's "unit".
tools::JsonValue SummaryData(const DemoResult& result);
/// Prints the before/after summary and the checks (worn: the goals and the error budget) from
/// SummaryData's document alone, so the text shows no figure the JSON lacks.
void PrintSummaryData(const tools::JsonValue& summary, std::ostream& out);
/// PrintSummaryData(SummaryData(result), out).
void PrintSummary(const DemoResult& result, std::ostream& out);

/// Writes DIR/index.html, DIR/summary.json and the data files (CSV, G-code, model, image) of a
/// demo run; kIoError names a file or directory that cannot be written.
Outcome WriteDemoReport(const DemoResult& result, const std::string& dir);

}  // namespace volcomp::sim
