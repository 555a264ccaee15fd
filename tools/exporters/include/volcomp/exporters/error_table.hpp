// The measured error of one axis as the controllers' tables take it (Siemens, Heidenhain, Fanuc
// writers): error = actual − nominal (ISO 230-2 deviation), the mean per target and direction of
// a positioning test (model/positioning.hpp), either at the test's own positions or resampled
// to an equally spaced grid (linear interpolation between the test positions), optionally
// shifted so the forward error is 0 at a reference position and negated (--negate). This is
// volcomp's one internal convention; each writer states and applies its controller's own sign
// and unit on top of it. Units: errors µm (arcsec); positions in the machine's unit (LengthUnit:
// mm, or inches for an inch machine; deg on a rotary axis in both).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/metrology/inch.hpp"
#include "volcomp/model/positioning.hpp"

namespace volcomp::exporters {

/// The machine's length unit, the unit a controller's table holds positions and values in on a
/// linear axis (LinuxCNC: [TRAJ] LINEAR_UNITS; SINUMERIK: the basic system, MD10240; FANUC: the
/// increment system). A rotary axis is in degrees with either.
enum class LengthUnit { kMm, kInch };

using metrology::kMmPerInch;

/// "mm", "in", or "deg" on a rotary axis.
const char* UnitName(LengthUnit unit, bool rotary);

/// Millimetres in one machine unit of a linear axis: 1 or 25.4.
double MmPerUnit(LengthUnit unit);

/// A position of a linear axis in mm in the machine's unit (inches rounded to 1e-9 in, so that
/// 203.2 mm is 8 in, not 7.999999999999997).
double FromMm(double position_mm, LengthUnit unit);

struct ErrorTableOptions {
  LengthUnit unit = LengthUnit::kMm;  // of the positions below and of the table
  double spacing = 0;                 // > 0: resample to this grid from the first test position,
                                      // machine units (deg); 0: the test's own positions
  std::optional<double> zero_at;      // machine units (deg): subtract the forward error there from
                                      // both directions (a reference point the controller zeroes)
  bool negate = false;                // flip the sign of every error (after zeroing)
};

struct ErrorTable {
  bool rotary = false;
  LengthUnit unit = LengthUnit::kMm;  // of every position below (a rotary axis: deg)
  std::vector<double> position;       // machine units (deg), increasing
  std::vector<double> forward_um;     // error moving positive, µm (arcsec)
  std::vector<double> reverse_um;     // moving negative; empty when one direction was measured
  double spacing = 0;                 // the common gap, machine units; 0 when the gaps differ
  double tested_to = 0;               // the last test position, machine units
  double uncovered = 0;               // tested travel past the last grid node, ≥ 0
  std::optional<double> zero_at;      // as given
  bool negated = false;
};

/// kInvalidArgument naming the value and the limit: a spacing longer than the tested travel, a
/// zero_at outside the tested travel.
Expected<ErrorTable> BuildErrorTable(const model::PositioningData& data,
                                     const ErrorTableOptions& options);

/// µm → mm (inches with LengthUnit::kInch), or arcsec → deg on a rotary axis: the unit of every
/// table written.
double ToMachineUnits(double error_um, bool rotary, LengthUnit unit = LengthUnit::kMm);

/// The table's common spacing, or kInvalidArgument for a table whose gaps differ, naming the
/// first two different gaps, `controller` (which needs equal spacing) and the fix (--spacing).
Expected<double> RequireEqualSpacing(const ErrorTable& table, const std::string& controller);

/// Success, or kInvalidArgument when `points` exceeds `limit`: the message names the count,
/// `controller` with its limit and the spacing that fits the travel (--spacing).
Expected<void> RequirePointLimit(const ErrorTable& table,
                                 std::size_t limit,
                                 const std::string& controller);

}  // namespace volcomp::exporters
