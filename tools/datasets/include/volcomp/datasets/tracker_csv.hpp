// Laser-tracker measurements as CSV files.
//
// Axis lines (samples/model/tracker_s500_315.csv; `volcomp build tracker --points FILE`): axis
//   (X|Y|Z), x_cmd_mm, y_cmd_mm, z_cmd_mm, x_mm, y_mm, z_mm and optionally cos_x, cos_y, cos_z
//   (printed direction cosines). Each line moves only its own axis from 0 in equal steps.
// Lattice (`volcomp build tracker --lattice FILE`): x_cmd_mm, y_cmd_mm, z_cmd_mm, x_mm, y_mm,
//   z_mm, every node of an equally spaced lattice exactly once (≥ 2 nodes per axis), any order;
//   other columns ignored. The command also reads SpatialAnalyzer exports there
//   (tracker_lattice_file.hpp); TrackerLatticeFromReadings is the lattice check both share.
// Lengths in mm. Failures name the file and line (kInputInvalid; kIoError when the file cannot
// be read); data returned pass model::ValidateTrackerData / TrackerLattice::Create's checks of
// shape.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/tracker.hpp"
#include "volcomp/model/tracker_lattice.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::datasets {

Expected<model::TrackerData> TrackerDataFromCsv(const tools::CsvTable& csv);
Expected<model::TrackerData> LoadTrackerCsv(const std::string& path);

/// One lattice reading: the commanded node, the tracker's reading (mm) and the source line.
struct TrackerLatticeReading {
  model::Vec3 command_mm;
  model::Vec3 reading_mm;
  std::size_t line = 0;
};

/// The lattice of `readings` (any order; every node of an equally spaced lattice exactly once,
/// ≥ 2 nodes per axis). Failures are "source:line: ..." (kInputInvalid), `file_line` for
/// the file as a whole (0: "source: ...").
Expected<model::TrackerLatticeData> TrackerLatticeFromReadings(
    const std::string& source,
    std::size_t file_line,
    const std::vector<TrackerLatticeReading>& readings);

Expected<model::TrackerLatticeData> TrackerLatticeFromCsv(const tools::CsvTable& csv);
Expected<model::TrackerLatticeData> LoadTrackerLatticeCsv(const std::string& path);

}  // namespace volcomp::datasets
