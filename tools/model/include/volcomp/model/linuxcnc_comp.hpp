// LinuxCNC joint compensation files ([JOINT_n] COMP_FILE, COMP_FILE_TYPE) from positioning tests.
//
// LinuxCNC (src/emc/motion/usrmotintf.cc usrmotLoadComp, control.c) reads one
// "nominal forward reverse" triplet per line, in machine units, nominals increasing, at most
// kLinuxcncMaxCompEntries lines. While a joint moves up it adds the forward trim, moving down the
// reverse trim, linearly interpolated at the commanded joint position (the nominal); at rest it
// keeps the last trim. COMP_FILE_TYPE 1: the file holds the trims themselves (added to the
// command). COMP_FILE_TYPE 0: the file holds positions, and the trim is nominal − forward
// (nominal − reverse): "forward" is where the uncompensated axis arrives when commanded to the
// nominal position moving up.
//
// The trims are the 1-D corrections of BuildAxis1d (the exact inverse of the measured mean
// deviations, ReverseMode::kTables): the same correction an AXIS1D table on the board applies.
// Without reverse deviations the reverse trims equal the forward ones. Type 0 and type 1 files of
// the same data therefore give LinuxCNC identical trims.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/model/axis1d.hpp"

namespace volcomp::model {

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

/// Throws std::invalid_argument naming the problem: BuildAxis1d's, or more rows than LinuxCNC
/// loads (the message names the count, the limit and a spacing that fits).
LinuxcncComp BuildLinuxcncComp(const PositioningData& data, LinuxcncCompType type, double spacing);

/// The file text: one "nominal forward reverse" line per row, 6 decimals, nothing else (LinuxCNC
/// stops reading at the first line that is not three numbers, so a file carries no comments).
std::string FormatLinuxcncComp(const LinuxcncComp& comp);

}  // namespace volcomp::model
