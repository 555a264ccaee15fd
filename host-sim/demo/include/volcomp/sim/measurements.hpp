// Measurement sessions on the simulated installation: run a test program on the CNC through the
// board, read the instrument at every stop, evaluate with tools/metrology (GOST 27843 and ISO
// 230-2 per axis, ISO 230-6 diagonals, tracker point sets, the six error motions of an axis).
// Lengths mm, deviations µm, angles µrad. A session fails with kNotReady when the CNC does not
// finish the program or the dwells do not match its stops, and with the reason when a program
// cannot be planned or the evaluation refuses the readings. The evaluations require 5 approaches
// per target and direction (GOST 27843 §2.10, ISO 230-6 §5.3), or the cycle's runs if fewer (>= 2).
#pragma once

#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/diagonal.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/metrology/positioning_eval.hpp"
#include "volcomp/model/vec3.hpp"
#include "volcomp/sim/instruments.hpp"
#include "volcomp/sim/test_programs.hpp"
#include "volcomp/sim/world.hpp"

namespace volcomp::sim {

/// The state at one stop: where the drives put the axes and what the CNC commanded.
struct StopState {
  MeasuredStop stop;
  model::Vec3 q_mm;    // axis positions at the drives (machine model frame)
  model::Vec3 cmd_mm;  // the CNC's commanded point
  bool at_rest_ok = true;
};

/// Parses and runs `program` on `world`; the state at the end of every dwell.
Expected<std::vector<StopState>> RunTestProgram(World& world, const TestProgram& program);

struct GostAxisResult {
  int axis = 0;
  TestProgram program;
  metrology::PositioningData data;
  metrology::PositioningResult gost;  // GOST 27843-88
  metrology::PositioningResult iso;   // ISO 230-2:2014, the same readings
};

struct GostPlan {
  std::vector<double> targets_mm;  // metrology::PlanGostTargets
  Point3 line_point_mm;            // the other coordinates of the test line
  CycleOptions cycle;
};

Expected<GostAxisResult> MeasureGostAxis(World& world,
                                         LaserInterferometer& laser,
                                         int axis,
                                         const GostPlan& plan);

struct DiagonalSetResult {
  std::vector<TestProgram> programs;
  std::string csv;  // the readings in the layout `volcomp evaluate diagonal` reads
  metrology::DiagonalEvaluation evaluation;
};

Expected<DiagonalSetResult> MeasureDiagonals(World& world,
                                             LaserInterferometer& laser,
                                             const std::vector<BodyDiagonal>& diagonals,
                                             int targets_per_diagonal,
                                             const CycleOptions& cycle);

struct PointSetResult {
  TestProgram program;
  std::vector<Point3> targets_mm;              // without the datum
  std::vector<model::Vec3> measured_error_um;  // tracker reading minus command
  std::vector<model::Vec3> true_error_um;      // machine model, no instrument error
  double max_um = 0, rms_um = 0;               // of |measured error|
  double true_max_um = 0, true_rms_um = 0;
};

/// `approach_mm` > 0: every point approached from that far below on every axis
/// (PointSetProgram).
Expected<PointSetResult> MeasurePointSet(World& world,
                                         LaserTracker& tracker,
                                         const std::vector<Point3>& points_mm,
                                         double dwell_s,
                                         double approach_mm = 0);

struct ParametricResult {
  int axis = 0;
  std::vector<double> position_mm;
  std::vector<SixDofReading> measured;  // mean over the approaches, zero at the reference point
  std::vector<SixDofReading> truth;     // the same without instrument errors
};

/// `positions_mm` must contain the reference point's coordinate of `axis` (else kInvalidArgument).
Expected<ParametricResult> MeasureParametric(World& world,
                                             LaserInterferometer& laser,
                                             int axis,
                                             const Point3& reference_mm,
                                             const std::vector<double>& positions_mm,
                                             const CycleOptions& cycle);

/// Long-layout positioning CSV (target_mm,direction,run,deviation_um) of `volcomp evaluate
/// positioning`.
std::string PositioningCsv(const metrology::PositioningData& data);

}  // namespace volcomp::sim
