// LinuxCNC joint compensation files ([JOINT_n] COMP_FILE, COMP_FILE_TYPE) from positioning tests:
// one "nominal forward reverse" line per node in machine units, nominals increasing, at most
// kLinuxcncMaxCompEntries lines. COMP_FILE_TYPE 1 holds the trims (added to the command), type 0
// the positions reached (trim = nominal − forward). The trims are the 1-D corrections of
// builders::BuildAxis1d (ReverseMode::kTables), the correction an AXIS1D table applies; without
// reverse deviations the reverse trims equal the forward ones. LinuxCNC's reading of the file:
// docs/linuxcnc.md §5.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/positioning.hpp"

namespace volcomp::exporters {

/// EMCMOT_COMP_SIZE of LinuxCNC 2.9: more lines are not loaded.
inline constexpr std::size_t kLinuxcncMaxCompEntries = 256;

enum class LinuxcncCompType { kPositions = 0, kTrims = 1 };

struct LinuxcncCompRow {
  double nominal = 0;  // mm (deg)
  double forward = 0;  // type 1: trim added moving up; type 0: position reached moving up
  double reverse = 0;
};

struct LinuxcncComp {
  LinuxcncCompType type = LinuxcncCompType::kTrims;
  std::vector<LinuxcncCompRow> rows;
  double max_residual = 0;  // of the inversion, µm (arcsec)
};

/// kInvalidArgument naming the problem: BuildAxis1d's, or more rows than LinuxCNC loads (the
/// message names the count, the limit and a spacing that fits).
Expected<LinuxcncComp> BuildLinuxcncComp(const model::PositioningData& data,
                                         LinuxcncCompType type,
                                         double spacing);

/// The file text: one "nominal forward reverse" line per row, 6 decimals, nothing else (LinuxCNC
/// stops reading at the first line that is not three numbers, so a file carries no comments).
std::string FormatLinuxcncComp(const LinuxcncComp& comp);

/// The INI lines that load `comp_file` for joint `joint` (0..15): [JOINT_n], COMP_FILE and
/// COMP_FILE_TYPE, each with its line end.
std::string LinuxcncJointIni(int joint, const std::string& comp_file, LinuxcncCompType type);

}  // namespace volcomp::exporters
