// The measured error of one axis as the controllers' tables take it (Siemens, Heidenhain, Fanuc
// writers): error = actual − nominal (ISO 230-2 deviation), the mean per target and direction of
// a positioning test (model/positioning.hpp), either at the test's own positions or resampled
// to an equally spaced grid (linear interpolation between the test positions), optionally
// shifted so the forward error is 0 at a reference position and negated (--negate). This is
// volcomp's one internal convention; each writer states and applies its controller's own sign
// and unit on top of it. Units: positions mm (deg on a rotary axis), errors µm (arcsec).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/positioning.hpp"

namespace volcomp::exporters {

struct ErrorTableOptions {
  double spacing = 0;             // > 0: resample to this grid from the first test position,
                                  // mm (deg); 0: the test's own positions
  std::optional<double> zero_at;  // mm (deg): subtract the forward error there from both
                                  // directions (a reference point the controller zeroes)
  bool negate = false;            // flip the sign of every error (after zeroing)
};

struct ErrorTable {
  bool rotary = false;
  std::vector<double> position;    // mm (deg), increasing
  std::vector<double> forward_um;  // error moving positive, µm (arcsec)
  std::vector<double> reverse_um;  // moving negative; empty when one direction was measured
  double spacing = 0;              // the common gap, mm (deg); 0 when the gaps differ
  double tested_to = 0;            // the last test position, mm (deg)
  double uncovered = 0;            // tested travel past the last grid node, mm (deg), ≥ 0
  std::optional<double> zero_at;   // as given
  bool negated = false;
};

/// kInvalidArgument naming the value and the limit: a spacing longer than the tested travel, a
/// zero_at outside the tested travel.
Expected<ErrorTable> BuildErrorTable(const model::PositioningData& data,
                                     const ErrorTableOptions& options);

/// µm → mm, or arcsec → deg on a rotary axis: the unit of every table written.
double ToMachineUnits(double error_um, bool rotary);

/// The table's common spacing, or kInvalidArgument for a table whose gaps differ, naming the
/// first two different gaps, `controller` (which needs equal spacing) and the fix (--spacing).
Expected<double> RequireEqualSpacing(const ErrorTable& table, const std::string& controller);

/// Success, or kInvalidArgument when `points` exceeds `limit`: the message names the count,
/// `controller` with its limit and the spacing that fits the travel (--spacing).
Expected<void> RequirePointLimit(const ErrorTable& table,
                                 std::size_t limit,
                                 const std::string& controller);

}  // namespace volcomp::exporters
