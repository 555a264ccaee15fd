// The error table of one linear axis as a CSV file (like the dissertation's Tables 3.2-3.4;
// samples/model/s500_x.csv):
//   position_mm, ex_um, ey_um, ez_um, and the angular columns ea_*, eb_*, ec_* in one unit:
//   _urad, _mrad, _um_per_mm (= mrad, the dissertation's unit) or _arcsec. An `n` column and
//   unknown extra columns are ignored. Rows in increasing position, at least two.
//   e = error of the tool point along x/y/z (µm) while this axis moves; ea/eb/ec = rotation about
//   x/y/z (right-handed). For the X axis file these are E_XX, E_YX, E_ZX, E_AX, E_BX, E_CX.
// Failures name the file and line ("x.csv:4: positions must increase from row to row";
// kInputInvalid, kIoError when the file cannot be read).
#pragma once

#include <string>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/axis_table.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::datasets {

Expected<model::AxisErrorTable> AxisTableFromCsv(const tools::CsvTable& csv);
Expected<model::AxisErrorTable> LoadAxisTableCsv(const std::string& path);

}  // namespace volcomp::datasets
