// ISG kernel / Beckhoff TwinCAT CNC leadscrew error compensation list (LSEC, German SSFK; one
// `achskw*.lis` file per axis) from a positioning test (data-formats.md B6, [manual]):
//
//   # comment                                 (`#` comments as in the ISG .lis files)
//   kopf.achs_nr                1             P-COMP-00001, the axis's logical number
//   kopf.log_achs_name          X             P-COMP-00002
//   kw.ssfk.unit                1             P-COMP-00017, lengths in 0.1 µm (the manual's
//   example) kw.ssfk.interval            0             P-COMP-00018, 0: every setpoint listed
//   kw.ssfk.kw_startpos         0             P-COMP-00019, the first setpoint
//   kw.ssfk.kw_nr_max           11            P-COMP-00020, the number of entries
//   kw.ssfk.bilateral           1             P-COMP-00021, separate .pos / .neg tables
//   kw.ssfk.table[i].setpoint   500000        P-COMP-00025
//   kw.ssfk.table[i].pos        -102          P-COMP-00023, moving in the positive direction
//   kw.ssfk.table[i].neg        80            P-COMP-00024, moving in the negative direction
//
// Sign: the table holds the error, actual − setpoint ("absolute position errors"; the manual's
// example: setpoint 19866.7 µm, measured 19856.5 µm, value −102 × 0.1 µm), the volcomp convention:
// no sign change unless `negate`. Source:
// https://infosys.beckhoff.com/content/1033/tf5200_axis_compensation_parameters/113439115.html
// Units: linear setpoints and values in 0.1 µm, rotary in 0.0001° (P-COMP-00019/23/24).
// Limits: kw_nr_max must be smaller than kw.ssfk.max_points (P-COMP-00059, default 1500).
// A one-direction test gives bilateral 0 with the same values in .pos and .neg.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/positioning.hpp"

namespace volcomp::exporters {

/// P-COMP-00059's default.
inline constexpr std::size_t kIsgLsecDefaultMaxPoints = 1500;

struct IsgLsecOptions {
  int axis_number = 1;    // kopf.achs_nr
  std::string axis_name;  // kopf.log_achs_name
  bool negate = false;    // write −error (for a controller that proves the other way)
  std::size_t max_points = kIsgLsecDefaultMaxPoints;
};

struct IsgLsecRow {
  int64_t setpoint = 0;  // 0.1 µm (0.0001°)
  int64_t pos = 0;       // error moving in the positive direction, 0.1 µm (0.0001°)
  int64_t neg = 0;
};

struct IsgLsec {
  bool rotary = false;
  bool bilateral = false;
  std::vector<IsgLsecRow> rows;
};

/// The list of a test: one row per tested position, values rounded to the file's unit.
/// kInvalidArgument naming the count and the limit: fewer than 2 positions, or kw_nr_max not
/// below max_points.
Expected<IsgLsec> BuildIsgLsec(const model::PositioningData& data, const IsgLsecOptions& options);

/// The file text: `header` as `#` comment lines, then the list.
std::string FormatIsgLsec(const IsgLsec& list,
                          const IsgLsecOptions& options,
                          const std::vector<std::string>& header);

}  // namespace volcomp::exporters
