// The lattice file of `volcomp build tracker --lattice FILE`, in any of its formats: the tracker
// CSV (tracker_csv.hpp) or a SpatialAnalyzer export (sa_points.hpp).
//
// Formats (recognised by content unless forced):
//   - SA XML (the first non-blank character is '<'): each POINT pairs its NOMINAL (the commanded
//     node) with its ACTUAL (the tracker's reading).
//   - SA ASCII (the first non-blank line is a `//` header or holds three numbers): measured points
//     only. Each is paired BY NAME with a nominal point of `nominals_path`, an SA ASCII file of
//     nominal points (same name rule) or a CSV with columns name, x_cmd_mm, y_cmd_mm, z_cmd_mm.
//     Every name must be in both files: a point without a partner is refused naming it (a lattice
//     with a hole cannot be built, and an extra reading dropped silently would hide a mistake).
//   - otherwise the tracker CSV (x_cmd_mm..z_cmd_mm, x_mm..z_mm).
// SA coordinates are in `sa_unit` (the working frame's unit); the CSVs are in mm.
//
// Plausibility (SA formats; kInputInvalid naming the value and the limit): the nominal points
// must span at least kSaMinimumSpan_mm along some axis (less is a frame in metres or inches read
// as mm), and no reading may lie more than kSaMaximumDeviation_mm from its nominal (a wrong
// pairing or unit).
#pragma once

#include <optional>
#include <string>

#include "volcomp/datasets/sa_points.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/tracker_lattice.hpp"

namespace volcomp::datasets {

inline constexpr double kSaMinimumSpan_mm = 1.0;
inline constexpr double kSaMaximumDeviation_mm = 10.0;

enum class LatticeFormat { kAuto, kCsv, kSaAscii, kSaXml };

struct LatticeFileOptions {
  LatticeFormat format = LatticeFormat::kAuto;
  std::optional<std::string> nominals_path;  // SA ASCII only (required there, refused elsewhere)
  std::optional<SaUnit> sa_unit;             // SA files only (default mm; refused with a CSV)
  std::optional<int> sa_name_fields;  // name parts of the ASCII lines (default: the non-numbers)
};

struct LoadedLattice {
  model::TrackerLatticeData data;
  LatticeFormat format = LatticeFormat::kCsv;  // as read (never kAuto)
};

/// "csv", "sa-ascii", "sa-xml" ("auto" for kAuto).
const char* LatticeFormatName(LatticeFormat format);

/// The lattice of `path` ("-": standard input); failures name the file and line (kIoError when
/// a file cannot be read, kUsage for options that do not fit the format).
Expected<LoadedLattice> LoadTrackerLatticeFile(const std::string& path,
                                               const LatticeFileOptions& options);

}  // namespace volcomp::datasets
