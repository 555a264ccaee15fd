// Laser-tracker measurements as CSV files.
//
// Axis lines (samples/model/tracker_s500_315.csv; `volcomp build tracker --points FILE`): axis
//   (X|Y|Z), x_cmd_mm, y_cmd_mm, z_cmd_mm, x_mm, y_mm, z_mm and optionally cos_x, cos_y, cos_z
//   (printed direction cosines). Each line moves only its own axis from 0 in equal steps.
// Lattice (`volcomp build tracker --lattice FILE`): x_cmd_mm, y_cmd_mm, z_cmd_mm, x_mm, y_mm,
//   z_mm, every node of an equally spaced lattice exactly once (≥ 2 nodes per axis), any order;
//   other columns ignored.
// Lengths in mm. Failures name the file and line (kInputInvalid; kIoError when the file cannot
// be read); data returned pass model::ValidateTrackerData / TrackerLattice::Create's checks of
// shape.
#pragma once

#include <string>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/tracker.hpp"
#include "volcomp/model/tracker_lattice.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::datasets {

Expected<model::TrackerData> TrackerDataFromCsv(const tools::CsvTable& csv);
Expected<model::TrackerData> LoadTrackerCsv(const std::string& path);

Expected<model::TrackerLatticeData> TrackerLatticeFromCsv(const tools::CsvTable& csv);
Expected<model::TrackerLatticeData> LoadTrackerLatticeCsv(const std::string& path);

}  // namespace volcomp::datasets
