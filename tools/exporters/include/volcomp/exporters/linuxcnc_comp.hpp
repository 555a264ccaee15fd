// LinuxCNC joint compensation files ([JOINT_n] COMP_FILE, COMP_FILE_TYPE) from positioning tests:
// one "nominal forward reverse" line per node in machine units ([TRAJ] LINEAR_UNITS: mm or inch;
// deg on a rotary joint), nominals increasing, at most
// kLinuxcncMaxCompEntries lines. COMP_FILE_TYPE 1 holds the trims (added to the command), type 0
// the positions reached (trim = nominal − forward). The trims are the 1-D corrections of
// builders::BuildAxis1d (ReverseMode::kTables), the correction an AXIS1D table applies; without
// reverse deviations the reverse trims equal the forward ones; the nominals stop at the last tested
// position. The INI lines go into the machine's existing [JOINT_n] sections
// (MergeLinuxcncJointIni). LinuxCNC's reading of the file and the INI: docs/linuxcnc.md §5.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/exporters/error_table.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/positioning.hpp"

namespace volcomp::exporters {

/// EMCMOT_COMP_SIZE of LinuxCNC 2.9: more lines are not loaded.
inline constexpr std::size_t kLinuxcncMaxCompEntries = 256;

enum class LinuxcncCompType { kPositions = 0, kTrims = 1 };

struct LinuxcncCompRow {
  double nominal = 0;  // machine units: mm or in (deg)
  double forward = 0;  // type 1: trim added moving up; type 0: position reached moving up
  double reverse = 0;
};

struct LinuxcncComp {
  LinuxcncCompType type = LinuxcncCompType::kTrims;
  LengthUnit unit = LengthUnit::kMm;  // of every row on a linear joint
  std::vector<LinuxcncCompRow> rows;
  double max_residual = 0;  // of the inversion, µm (arcsec)
};

/// Rows on the lattice of BuildAxis1d (`spacing` in `unit`, deg on a rotary axis; 0: the test's),
/// the last one at the last tested position rather than past it (LinuxCNC's nominals need not be
/// equally spaced); the rows in `unit` (6 decimals in the file: 1 nm, or 0.000001 in = 25 nm).
/// kInvalidArgument naming the problem: BuildAxis1d's, or more rows than LinuxCNC loads (the
/// message names the count, the limit and a spacing that fits).
Expected<LinuxcncComp> BuildLinuxcncComp(const model::PositioningData& data,
                                         LinuxcncCompType type,
                                         double spacing,
                                         LengthUnit unit = LengthUnit::kMm);

/// The machine's linear unit as LinuxCNC reads it from an INI file's text: the first [TRAJ]
/// section's LINEAR_UNITS, a word (mm, metric; in, inch, imperial) or machine units per mm (1.0;
/// 1/25.4). nullopt when there is none; kInvalidArgument naming `source`, the line and the value
/// for any other value.
Expected<std::optional<LengthUnit>> LinuxcncLinearUnits(const std::string& ini,
                                                        const std::string& source);

/// The file text: one "nominal forward reverse" line per row, 6 decimals, nothing else (LinuxCNC
/// stops reading at the first line that is not three numbers, so a file carries no comments).
std::string FormatLinuxcncComp(const LinuxcncComp& comp);

/// The INI lines that load `comp_file` for joint `joint` (0..15): [JOINT_n], COMP_FILE and
/// COMP_FILE_TYPE, each with its line end.
std::string LinuxcncJointIni(int joint, const std::string& comp_file, LinuxcncCompType type);

/// One joint's compensation file for MergeLinuxcncJointIni.
struct LinuxcncJointComp {
  int joint = 0;  // 0..15
  std::string comp_file;
  LinuxcncCompType type = LinuxcncCompType::kTrims;
};

struct LinuxcncIniMerge {
  std::string text;                   // the INI text with the lines merged
  std::vector<std::string> warnings;  // complete sentences naming `source` and its lines
};

/// Merges COMP_FILE and COMP_FILE_TYPE of each of `joints` into `ini` (a LinuxCNC INI file's
/// text, named `source` in warnings), every other line unchanged: into the joint's existing
/// [JOINT_n] section (after its last key), replacing the values it already has (a warning names
/// the old one), or in a new section at the end when the file has none. LinuxCNC reads a key from
/// the first section of a name only (a second [JOINT_n] header, as `cat joints.ini >> machine.ini`
/// makes, leaves COMP_FILE ignored without a message): a file that repeats a joint's header gets
/// the lines in the first one and a warning naming the repeats' lines.
LinuxcncIniMerge MergeLinuxcncJointIni(const std::string& ini,
                                       const std::vector<LinuxcncJointComp>& joints,
                                       const std::string& source);

}  // namespace volcomp::exporters
