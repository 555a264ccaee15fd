// Does a table fit the board it is going to? Before `upload` transfers and `activate` activates a
// table, the PC tool reads the board's installation (axis count 0x2000:4, and per axis name
// 0x2010, kind 0x2011, units per step 0x2012, max correction 0x2015, max correction rate 0x2016,
// max input rate 0x201E) and compares it with what the table asks (image/table_demands.hpp):
//   * axis count, names, kinds and units per step must match (the board would refuse the table);
//   * the table's largest correction must not exceed the max correction (the board would clamp);
//   * its gradient x the fastest input rates must not exceed the max correction rate (the board
//     would rate-limit the correction while the machine moves fast).
// The last two are refused unless the caller allows them (`--allow-clamp`); then they are warned
// about, and the board shows them in force (0x2134-0x2136, EMCY 0xFF20).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "command.hpp"
#include "volcomp/canopen_client/node_objects.hpp"
#include "volcomp/config/board_settings.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp::cli {

struct BoardAxis {
  char name = '?';
  uint32_t kind = 0;
  uint32_t resolution_e9 = 0;
  int32_t max_correction_steps = 0;
  uint32_t max_rate_steps_s = 0;
  uint32_t max_input_rate_hz = 0;
};

struct BoardInstallation {
  std::vector<BoardAxis> axes;
  bool settings_pending = false;  // edited settings not yet in force (the values read are those)
};

/// Reads the installation objects (kCommunication when the board does not answer).
Expected<BoardInstallation> ReadInstallation(canopen_client::NodeObjects& node);

struct FitProblem {
  bool limit = false;  // a clamp or rate limit (allowed with --allow-clamp), else a mismatch
  std::string message;
};

/// Everything about `view` the board at `board` would refuse, clamp or rate-limit.
std::vector<FitProblem> CheckTableFits(const table::TableView& view,
                                       const BoardInstallation& board);

/// Reads the installation and checks `view` against it: writes warnings to `warnings` as they
/// arise (settings not yet in force, the limits allowed), and fails (kInvalidArgument, exit 1)
/// naming every problem when there is a mismatch, or a limit and not `allow_limits`. Returns the
/// problems that were allowed.
Expected<std::vector<FitProblem>> RequireTableFits(canopen_client::NodeObjects& node,
                                                   const table::TableView& view,
                                                   bool allow_limits,
                                                   std::ostream& warnings);

/// The installation a board settings file describes (the file `config save` writes).
BoardInstallation InstallationOf(const BoardSettings& s);

/// Axes whose home position (AxisConfig::home_position_steps, where the board references) lies
/// outside the table's lattice along that axis (its GRID3 dimension, or its AXIS1D table unless
/// it wraps): there the board holds the lattice's edge value. One message per such axis.
std::vector<std::string> HomeOutsideLattice(const table::TableView& view, const BoardSettings& s);

/// A build's `--board FILE` (the board's settings file), `--bank-bytes N`, `--allow-clamp`.
struct BoardFileCheck {
  std::string path;
  BoardSettings settings;
  uint32_t bank_bytes = 0;  // 0: not given
  bool allow_clamp = false;
};
/// Reads the options (and the file, as `config apply` does); nullopt without --board. A usage
/// failure for --bank-bytes or --allow-clamp without --board.
Expected<std::optional<BoardFileCheck>> ParseBoardFileCheck(Args& args);

/// The image `bytes` against the board file, before it is written: fails (kInvalidArgument)
/// naming every problem on a mismatch (axes, units per step), an image larger than bank_bytes, a
/// clamp or rate limit unless allow_clamp. `*warnings` gets the limits allowed and the home
/// positions outside the lattice. `*report` (JSON): file, image_bytes, bank_bytes (0: not given),
/// problems, warnings.
Outcome CheckImageAgainstBoardFile(const BoardFileCheck& check,
                                   const std::vector<uint8_t>& bytes,
                                   std::vector<std::string>* warnings,
                                   JsonValue* report);

}  // namespace volcomp::cli
