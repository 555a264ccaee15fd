// One loader for every file that holds a positioning test of one axis, whatever wrote it:
//   - volcomp's CSV (positioning_csv.hpp): the raw readings (long or wide layout, the test
//     conditions in its `# key: value` preamble) or the mean deviations per target;
//   - a Renishaw LaserXL / Laser10 linear data file `.rtl` (rtl_reader.hpp).
// The format is recognised by content, not by the file name: a file whose first non-blank line
// is a section line `NAME::` (`HEADER::`) is an .rtl, anything else CSV; kCsv / kRtl force one.
// Every command that reads a positioning test (`evaluate positioning`, `build axis`, the
// exports) reads it through ReadPositioningFile and takes what it needs: the readings
// (evaluation) or the mean deviations per target and direction (tables).
// Failures name the file and line (kInputInvalid; kIoError when the file cannot be read).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/datasets/rtl_reader.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/positioning_data.hpp"
#include "volcomp/metrology/test_conditions.hpp"
#include "volcomp/model/positioning.hpp"

namespace volcomp::datasets {

enum class PositioningFormat { kAuto, kCsv, kRtl };

/// "auto", "csv" or "rtl".
const char* PositioningFormatName(PositioningFormat format);

struct PositioningReadOptions {
  PositioningFormat format = PositioningFormat::kAuto;
  RtlOptions rtl;  // .rtl only: directions of the runs, sign, units
  /// Accept a µm (or µin) column whose values are all below 0.1 µm (not all zero): without it
  /// such a column is refused as mm typed as µm (inches typed as µin; a failure naming the
  /// column, the largest value and the fix).
  bool accept_units = false;
};

/// A positioning test as read: either its raw readings or (CSV only) its mean deviations.
struct PositioningFile {
  std::string source;                                  // file name or "<stdin>"
  PositioningFormat format = PositioningFormat::kCsv;  // what was read: kCsv or kRtl
  RtlUnits rtl_units = RtlUnits::kMm;  // .rtl: the units it was read in (converted to mm/µm)
  metrology::TestConditions conditions;
  std::optional<metrology::PositioningData> readings;  // raw readings (CSV or .rtl)
  std::size_t readings_line = 0;  // the line naming the data as a whole (header, DEVIATIONS::)
  std::optional<model::PositioningData> means;  // the CSV layout position_mm, dev_forward_um ...
  bool means_in_inches = false;  // means read from position_in, dev_forward_uin ... (into mm/µm)
  std::vector<std::string> warnings;  // the reader's (.rtl: directions, environment)
};

/// Reads the file at `path` (kIoError when it cannot be read), with the unit plausibility check
/// of every µm or µin deviation column of a linear axis (see PositioningReadOptions::accept_units).
Expected<PositioningFile> ReadPositioningFile(const std::string& path,
                                              const PositioningReadOptions& options = {});
/// The same from text already read; `source` names it in messages.
Expected<PositioningFile> ReadPositioningText(const std::string& text,
                                              const std::string& source,
                                              const PositioningReadOptions& options = {});

/// The mean deviation per target and direction (the tables' input): the file's means, or its
/// readings grouped, checked (with `grouping`) and averaged as `evaluate positioning` does; the
/// reader's warnings come first in the result's warnings. At least 2 target positions.
Expected<model::PositioningData> PositioningMeans(
    const PositioningFile& file,
    const metrology::GroupingOptions& grouping = metrology::GroupingOptions{});

}  // namespace volcomp::datasets
