// `volcomp-sim demo`: the main job on the simulated installation, end to end.
//
//   1. power up, home the axes (the board references on the home switch edges)
//   2. measure the uncompensated machine: GOST 27843-88 per axis (laser), ISO 230-6 body diagonals
//      (laser), volumetric error at random points (laser tracker); evaluate with tools/metrology
//   3. measure the six error motions of X, Y and Z through the reference point (6-DOF laser)
//   4. build the table: measured 21-parameter model -> inverse GRID3 (tools/model) -> image
//   5. upload it over the simulated CAN bus with the PC tool's SDO code, verify on the board
//   6. home again (reference), activate, let the correction ramp in
//   7. re-measure exactly as in 2
//   8. speed benchmark (all three axes at 1 MHz through the compensating board) and the summary
// Deterministic for a given seed (the wall-clock figures aside).
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "volcomp/sim/board_session.hpp"
#include "volcomp/sim/instruments.hpp"
#include "volcomp/sim/latency_meter.hpp"
#include "volcomp/sim/measurements.hpp"
#include "volcomp/sim/sim_status.hpp"
#include "volcomp/sim/table_from_measurements.hpp"
#include "volcomp/sim/world.hpp"

namespace volcomp::sim {

struct DemoOptions {
  uint64_t seed = 1;
  std::string model_spec = "s500";  // "s500" or a model config file
  std::string report_dir;           // empty: no report
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
  InterferometerOptions laser;
  TrackerOptions tracker;
};

struct AxisFigures {
  double A = 0, R = 0, B = 0;  // GOST 27843: accuracy, repeatability (R_max), reversal (B_max), µm
};

struct PhaseResults {
  std::array<GostAxisResult, 3> gost;
  DiagonalSetResult diagonals;
  PointSetResult points;
  std::array<AxisFigures, 3> Gost() const;
  double Ed() const;  // ISO 230-6 E_d, µm
  double Bd() const;
};

struct BenchmarkFigures {
  uint64_t steps = 0;  // input steps (each also counted, planned and checked as an output step)
  double virtual_s = 0;
  double wall_s = 0;
  double steps_per_s = 0;
};

struct DemoResult {
  DemoOptions options;
  std::string machine_name;
  PhaseResults before, after;
  std::array<ParametricResult, 3> parametric;
  model::Model measured_model;
  TableBuildResult table;
  UploadReport upload;
  ActivationReport activation;
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

/// Runs the demo; progress goes to `log`. Fails when a step cannot go on (the board refused a
/// table, a program did not finish, the model's tables miss the reference point); a model file
/// that cannot be read throws tools::InputError (the builders' error, printed by the command).
SimResult<DemoResult> RunDemo(const DemoOptions& options, std::ostream& log);

/// Prints the before/after summary and the checks.
void PrintSummary(const DemoResult& result, std::ostream& out);

/// Writes DIR/index.html and the data files (CSV, G-code, model, image) of a demo run; kIoError
/// names a file that cannot be written.
SimStatus WriteDemoReport(const DemoResult& result, const std::string& dir);

}  // namespace volcomp::sim
