// Input files of the table builders: per-axis error tables, the model config, tracker lines.
// Every problem is a tools::InputError "file:line: problem" (never a crash).
//
// Axis error table CSV (one file per axis, like Tables 3.2-3.4; samples/model/s500_x.csv):
//   position_mm, ex_um, ey_um, ez_um, and the angular columns ea_*, eb_*, ec_* in one unit:
//   _urad, _mrad, _um_per_mm (= mrad, the dissertation's unit) or _arcsec. An `n` column and
//   unknown extra columns are ignored. Rows in increasing position, at least two.
//   e = error of the tool point along x/y/z (µm) while this axis moves; ea/eb/ec = rotation about
//   x/y/z (right-handed). For the X axis file these are E_XX, E_YX, E_ZX, E_AX, E_BX, E_CX.
//
// Model config (samples/model/s500.conf): `key = value` lines, `#` comments. Keys:
//   builtin = s500               start from the compiled-in S500 model (others override it)
//   name = TEXT
//   axis_x | axis_y | axis_z = FILE   axis tables, relative to the config's directory
//   squareness_c0y_urad | squareness_b0z_urad | squareness_a0z_urad = NUMBER
//   tool_offset_mm = X, Y, Z
//   workpiece_axes = LETTERS     from the workpiece down to the base (may be empty)
//   tool_axes = LETTERS          from the base up to the tool
//   workpiece_errors = relative | carriage
//   formulation = physical | dissertation
//   order = first | exact        (dissertation: first | second)
//   dissertation_case = plus | minus
//   angle_scale = NUMBER
//
// Tracker lines CSV (samples/model/tracker_s500_315.csv): axis (X|Y|Z), x_cmd_mm, y_cmd_mm,
//   z_cmd_mm, x_mm, y_mm, z_mm and optionally cos_x, cos_y, cos_z (printed direction cosines).
//   Each line moves only its own axis from 0 in equal steps.
#pragma once

#include <string>

#include "volcomp/model/axis_table.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/model/tracker.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::model {

AxisErrorTable AxisTableFromCsv(const tools::CsvTable& csv);
AxisErrorTable LoadAxisTableCsv(const std::string& path);

/// `source` names the text in errors; relative axis files are resolved against `base_dir`.
Model ModelFromConfigText(const std::string& text,
                          const std::string& source,
                          const std::string& base_dir);
Model LoadModelConfig(const std::string& path);

TrackerData TrackerDataFromCsv(const tools::CsvTable& csv);
TrackerData LoadTrackerCsv(const std::string& path);

}  // namespace volcomp::model
