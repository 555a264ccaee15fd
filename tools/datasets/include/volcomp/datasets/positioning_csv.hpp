// A positioning test (ISO 230-2 / GOST 27843-88) of one axis as the mean deviations per target
// and direction (model/positioning.hpp), from either CSV layout:
//   the means:  position_mm, dev_forward_um [, dev_reverse_um]   (samples/model/positioning_x.csv)
//               position_in, dev_forward_uin [, dev_reverse_uin]   (an inch machine; read as
//               mm and µm: 1 in = 25.4 mm, 1 µin = 0.0254 µm)
//               position_deg, dev_forward_arcsec [, dev_reverse_arcsec]   (rotary axis)
//   the raw readings `volcomp evaluate positioning` reads (target_mm|target_in|target_deg,
//   direction, run, deviation_um ...): tools/metrology groups, checks and averages them with the
//   same checks and warnings as the evaluation (the warnings go into PositioningData::warnings).
// Failures name the file and line (kInputInvalid; kIoError when the file cannot be read).
#pragma once

#include <string>

#include "volcomp/datasets/positioning_file.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/model/positioning.hpp"
#include "volcomp/tools/csv.hpp"

namespace volcomp::datasets {

/// The file as read (positioning_file.hpp): the readings with the preamble's test conditions, or
/// the means; a header of neither layout is a failure at the header line.
Expected<PositioningFile> PositioningFileFromCsv(const tools::CsvTable& csv);

/// Either layout; raw readings are grouped and checked with `grouping` (by default ≥ 5
/// approaches per target and direction). At least 2 target positions.
Expected<model::PositioningData> PositioningFromCsv(
    const tools::CsvTable& csv,
    const metrology::GroupingOptions& grouping = metrology::GroupingOptions{});
Expected<model::PositioningData> LoadPositioningCsv(
    const std::string& path,
    const metrology::GroupingOptions& grouping = metrology::GroupingOptions{});

}  // namespace volcomp::datasets
