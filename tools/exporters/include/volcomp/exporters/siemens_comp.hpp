// SINUMERIK 840D sl / 828D / 808D compensation programs from error tables (error_table.hpp):
//   LEC (leadscrew / measuring-system error compensation): %_N_AX_EEC_INI, one table per axis,
//     $AA_ENC_COMP[encoder, point, axis] and its _STEP/_MIN/_MAX/_IS_MODULO, for one direction;
//   CEC (sag / angularity compensation): $AN_CEC tables with $AN_CEC_DIRECTION 1 (positive
//     traverse) and −1 (negative), input axis = output axis for direction-dependent pitch, or a
//     cross-axis table (input X, output Y: the straightness E_YX of straightness.hpp), the
//     output axis compensated as a function of the input axis's position.
// Sign (K3 function manual, 6FC5397-1BP40-3BA1, pp. 238/242 and 249): the value is the measured
// error, actual − nominal: "a positive compensation value causes the machine axis to move in the
// negative direction". Unit mm (deg on a rotary axis), 4 decimals (0.1 µm); on an inch machine
// (basic system inch, MD10240 = 0) inches, 6 decimals — the basic system's unit [inferred: K3's
// tables show mm only]. Limits: equally
// spaced points, at most MD38000 $MA_MM_ENC_COMP_MAX_POINTS (LEC) / MD18342 $MN_MM_CEC_MAX_POINTS
// (CEC) points per table — the machine's value, `max_points` (200: the 808D's LEC and the 828D's
// CEC tables). The machine data to set are written as comments at the top of the program.
// Data formats and sources: docs/pc-tool.md "Controller tables", shared reference §B1–B2.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/exporters/error_table.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::exporters {

enum class SiemensMode { kLec, kCec };

/// The 808D's LEC and the 828D's CEC limit: 200 points per table.
inline constexpr std::size_t kSiemensDefaultMaxPoints = 200;

struct SiemensAxis {
  std::string machine_axis;  // the machine axis name in the program, e.g. "X1" or "AX1"
  std::string source;        // the test file, named in the program's header
  ErrorTable table;
  std::string output_axis;  // CEC: the axis compensated; empty: machine_axis (pitch)
  std::string what;         // one line on what the table is, e.g. "straightness E_YX ..."
};

struct SiemensOptions {
  SiemensMode mode = SiemensMode::kLec;
  int encoder = 0;  // LEC: 0 the first measuring system, 1 the second
  std::size_t max_points = kSiemensDefaultMaxPoints;
  LengthUnit unit = LengthUnit::kMm;  // the basic system; every linear table's ErrorTable::unit
};

struct SiemensTableInfo {  // one table written, for the command's report
  std::string machine_axis;
  std::string output_axis;  // = machine_axis except for a cross-axis table
  bool rotary = false;      // values in deg, positions in deg
  int cec_table = -1;       // CEC: the table index; −1 for LEC
  int direction = 0;        // CEC: 1, −1, or 0 for both directions; LEC: 0
  std::size_t points = 0;
  double min = 0, max = 0, step = 0;  // machine units (deg)
  double largest_value = 0;           // the largest |value| in the table, machine units (deg)
};

struct SiemensProgram {
  std::string text;  // the program, CRLF-free, "\n" line ends
  std::vector<SiemensTableInfo> tables;
  std::vector<std::string> notes;  // complete sentences the command prints as warnings
};

/// kInvalidArgument naming the axis, the value, the limit and the fix: unequal spacing, more
/// points than `max_points`, an encoder other than 0/1, a cross-axis table in LEC mode.
/// LEC with a two-direction test writes the mean of both directions (a note says so and gives
/// the mean reversal); CEC with a one-direction test writes one table for both directions.
Expected<SiemensProgram> BuildSiemensProgram(const std::vector<SiemensAxis>& axes,
                                             const SiemensOptions& options);

}  // namespace volcomp::exporters
