// `volcomp-sim run`: a part program on the simulated installation, the real firmware between the
// CNC and the drives, and the tool point's error against the programmed path sampled along the
// whole program (docs/simulator.md "Running a part program").
//
// The run: the machine (ideal or worn) powers up, homes (the board references on the switches),
// the table image (if any) goes over the simulated bus with the PC tool's protocol code and is
// activated, the tool is touched off (the CNC moves to the touch-off point, by default the end of
// the program's first move, and the tool point's offset from the command there becomes the work
// offset, as a shop touches off the workpiece), then the program runs. Every `sample_period_s` of
// virtual time the tool point (the machine's own kinematics at the carriages' positions, less the
// work offset) is compared with the programmed path: while the CNC runs a move, the distance to the
// move's path (the line or arc of that program line: the contour error, so the board's latency
// along the path does not count); at rest (dwell, end) the distance to the commanded point. Errors
// in µm.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/circular.hpp"
#include "volcomp/sim/gcode.hpp"
#include "volcomp/sim/path.hpp"

namespace volcomp::sim {

struct ProgramRunOptions {
  std::string program_name;  // shown in results and failure messages
  std::string program_text;  // G-code (gcode.hpp subset)
  bool worn = false;         // the worn machine (DefaultWornProfile) instead of the ideal one
  uint64_t seed = 1;         // the worn machine's random stream
  std::string model_spec = "s500";
  std::vector<uint8_t> table_image;  // empty: run without compensation
  /// Board settings over the simulator's (the PC tool's board INI: [board] and one [axis X|Y|Z]
  /// section per axis; keys left out keep the simulated board's values); empty: none.
  std::string settings_ini;
  std::string settings_source;
  std::optional<Point3> touch_off_mm;  // default: the end of the program's first move
  /// A ballbar's centre pivot (the test circle's centre): the bar reads on every full circle
  /// about it (ISO 230-4), one reading per degree and direction.
  std::optional<Point3> ballbar_pivot_mm;
  double accel_mm_s2 = 10000;
  double sample_period_s = 100e-6;
  uint64_t limit_s = 3600;  // virtual time the program may take
};

enum class SampleKind { kCutting, kRapid, kRest };
const char* SampleKindName(SampleKind k);

struct PathSample {
  double t_s = 0;  // since the program started
  int line = 0;    // program line (0: after the end)
  SampleKind kind = SampleKind::kRest;
  Point3 commanded_mm = {0, 0, 0};
  Point3 tool_mm = {0, 0, 0};
  double error_um = 0;
};

struct LineFigures {
  int line = 0;
  SampleKind kind = SampleKind::kRest;
  uint64_t samples = 0;
  double max_error_um = 0;
};

struct BallbarReading {
  bool cw = false;
  double angle_deg = 0;  // in the circle's plane from its first axis towards its second
  double deviation_um = 0;
  int plane = 17;
  double radius_mm = 0;
};

struct ProgramRunResult {
  std::string program;
  std::string machine;     // "ideal" or "worn"
  uint32_t table_crc = 0;  // 0: no table
  Point3 touch_off_mm = {0, 0, 0};
  Point3 work_offset_um = {0, 0, 0};  // tool point - command at the touch-off point
  double duration_s = 0;              // virtual time of the program
  double cutting_max_error_um = 0, cutting_rms_error_um = 0;
  double rapid_max_error_um = 0, rest_max_error_um = 0;
  uint64_t cutting_samples = 0;
  uint64_t lost_steps = 0, timing_violations = 0, rest_checks = 0;
  std::vector<LineFigures> lines;  // per program line that ran, in order of first appearance
  std::vector<PathSample> samples;
  std::vector<BallbarReading> ballbar;                // with ballbar_pivot_mm
  std::optional<metrology::CircularResult> circular;  // the ballbar's readings evaluated
};

/// Runs the program. Failures: the program (kInputInvalid, "name:line: ..."), the model, the
/// board's refusal of the table (upload or activation), the program not finishing in limit_s, a
/// ballbar that read no full circle about its pivot or too little of one.
Expected<ProgramRunResult> RunProgramOnMachine(const ProgramRunOptions& options, std::ostream& log);

class World;

/// The program part of a run, on an installation that is ready (homed and referenced, its table
/// active or none): the paths checked, the touch-off, the program sampled along its path, the
/// ballbar (if any) evaluated. The demo runs its circular tests with it (docs/simulator.md 7.2).
struct ProgramInWorldOptions {
  std::string program_name;
  std::optional<Point3> touch_off_mm;      // default: the end of the program's first move
  std::optional<Point3> ballbar_pivot_mm;  // as ProgramRunOptions::ballbar_pivot_mm
  uint64_t ballbar_seed = 1;               // the ballbar's own noise
  double sample_period_s = 100e-6;
  uint64_t limit_s = 3600;
  bool keep_samples = true;  // false: only the figures (the per-line maxima, the ballbar)
};

/// Fills `r`'s touch-off, work offset, duration, error figures, lines, samples and ballbar (not
/// program, machine, table_crc or the step audit, which are the installation's). Failures as
/// RunProgramOnMachine()'s for the program, the time limit and the ballbar.
Outcome RunProgramInWorld(World& world,
                          const Program& program,
                          const ProgramInWorldOptions& options,
                          ProgramRunResult& r);

/// The samples as CSV (t_s,line,kind,x_cmd_mm,..,x_mm,..,error_um), the error along the program
/// as an HTML page with an SVG chart and, with a ballbar, its readings as ballbar.csv in the
/// format `volcomp evaluate circular` reads, into `dir` (created).
Outcome WriteProgramRunReport(const ProgramRunResult& result, const std::string& dir);

}  // namespace volcomp::sim
