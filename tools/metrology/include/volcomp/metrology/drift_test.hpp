// The thermal drift test in the manner of ISO 230-3:2020 (thermal effects, "environmental
// temperature variation error" / drift test): the positions of two or more points per linear axis
// are read repeatedly while the machine warms up, the temperature channels logged with each
// reading. docs/pc-tool.md "evaluate thermal" and docs/thermal.md "The PC tool".
//
// The file (CSV, csv.hpp syntax: ',' or ';' or TAB, decimal comma with ';' or TAB):
//   # machine: MILL-7                  the test conditions (test_conditions.hpp), optional
//   time_s,axis,position_mm,deviation_um,T_screw_x_C,T_spindle_C,T_ambient_C
//   0,X,50,0.0,20.00,20.10,20.00       one reading of one point and the temperatures at that time
// time_s: seconds since the start of the test (any origin; per point strictly increasing);
// axis: X, Y, Z, U, V or W (any case; A, B, C are rotary axes: refused, they have no thermal
// term); position_mm: the point on that axis (a point is an (axis, position) pair, the same number
// in every reading of it); deviation_um: the reading (measured − nominal, µm); one column
// T_<name>_C per temperature channel (°C), named by <name> (letters, digits, '_'); the channel's
// number (the board's channel 0..7) is its column order among the T_ columns. Up to 8 channels
// (none is allowed for the evaluation: the drift alone).
//
// Failures (kInputInvalid) name the file and line and, where one is at fault, the column: a
// missing or unknown column, a channel name that is empty or given twice, more than 8 channels, a
// cell that is not a number, an unknown or rotary axis, an axis with fewer than 2 points, a point
// read only once, a point whose time does not increase from one reading to the next.
//
// The evaluation, per axis and point: the drift (the reading minus the point's first reading),
// its largest magnitude and when, its range (max − min, the first reading's 0 included), its rate
// (µm/h: the least-squares slope of the drift over the readings of the last hour of the point's
// readings, or of all of them when the point was read over less than an hour; the last two
// readings when fewer than two fall in the hour). Per axis, the offset-like and slope-like
// components: at each reading time of the axis's first point that lies within every point's
// readings, every point's drift is interpolated linearly in time and a least-squares line is
// fitted over the positions: its value at the points' mean position (µm) and its slope (µm per
// metre of travel); reported at the last such time and at their largest magnitude. Per channel:
// the first, last, lowest and highest temperature and the rise (last − first, K).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/test_conditions.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::metrology {

inline constexpr std::size_t kMaxDriftChannels = 8;  // the board's temperature channels
inline constexpr double kDriftRateWindow_s = 3600.0;

struct DriftChannel {
  std::string name;    // "screw_x"
  std::string column;  // "T_screw_x_C"
};

/// One reading of one point.
struct DriftReading {
  double time_s = 0;
  double deviation_um = 0;
  std::vector<double> temperature_C;  // one per channel, channel order
  std::size_t line = 0;               // of the file
};

struct DriftPoint {
  double position_mm = 0;
  std::vector<DriftReading> readings;  // file order (time strictly increasing)
};

struct DriftAxis {
  char name = 'X';
  std::vector<DriftPoint> points;  // ascending position
};

struct DriftRecord {
  std::string source;
  TestConditions conditions;
  std::vector<DriftChannel> channels;  // channel number = index
  std::vector<DriftAxis> axes;         // order of first appearance in the file
  /// Every row's time and temperatures, file order (the channels' log).
  std::vector<double> time_s;
  std::vector<std::vector<double>> temperature_C;
};

/// Reads a drift test (the layout above); failures name file, line and column.
Expected<DriftRecord> ReadDriftCsv(const tools::CsvTable& table);

struct DriftPointResult {
  double position_mm = 0;
  std::vector<double> time_s;
  std::vector<double> drift_um;  // reading − first reading
  double max_drift_um = 0;       // the drift of largest magnitude (signed)
  double max_drift_time_s = 0;
  double range_um = 0;
  double final_drift_um = 0;
  double rate_um_per_h = 0;
  double rate_from_s = 0;  // the rate window: readings from this time to the last
  std::size_t rate_readings = 0;
};

/// The least-squares line of the points' drift over their positions at one time.
struct DriftComponents {
  double time_s = 0;
  double offset_um = 0;       // at the points' mean position
  double slope_um_per_m = 0;  // change of drift per metre of travel
};

struct DriftAxisResult {
  char name = 'X';
  double mean_position_mm = 0;
  std::vector<DriftPointResult> points;
  std::vector<DriftComponents> components;  // empty when the points' readings never overlap
  std::optional<DriftComponents> final_components;
  std::optional<DriftComponents> max_offset;  // the entry of largest |offset|
  std::optional<DriftComponents> max_slope;   // the entry of largest |slope|
};

struct ChannelRise {
  std::string name;
  std::size_t number = 0;
  double first_C = 0, last_C = 0, min_C = 0, max_C = 0;
  double rise_K = 0;  // last − first
};

struct DriftEvaluation {
  std::string source;
  TestConditions conditions;
  double start_s = 0, end_s = 0;  // first and last time of the file
  std::size_t readings = 0;
  std::vector<DriftAxisResult> axes;
  std::vector<ChannelRise> channels;
  std::vector<double> log_time_s;  // the channels' log (DriftRecord::time_s, temperature_C)
  std::vector<std::vector<double>> log_temperature_C;
  std::vector<std::string> warnings;
};

/// Evaluates a record ReadDriftCsv() returned (never fails on one).
DriftEvaluation EvaluateDrift(const DriftRecord& record);

/// The environmental variation error E_VE a measurement-uncertainty budget takes from a drift
/// test (positioning_uncertainty.hpp, error_motion_uncertainty.hpp): the largest range of one
/// point's readings (ISO/TR 230-9's E_VE: the range of a fixed position's readings over the
/// test's duration with the machine at rest; a warm-up test of ISO 230-3 gives a larger,
/// conservative figure), and which point it is.
struct EnvironmentalVariation {
  double range_um = 0;
  char axis = 'X';
  double position_mm = 0;
  double duration_s = 0;  // of that point's readings
};
/// nullopt when no point has two readings (ReadDriftCsv() refuses such a file).
std::optional<EnvironmentalVariation> LargestDriftRange(const DriftEvaluation& ev);

/// Least-squares slope of y over x (0 when x does not vary); the helper of the rate and the
/// components, public for the tests.
double LeastSquaresSlope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace volcomp::metrology
