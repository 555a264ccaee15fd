// A straightness test as a cross-axis table (SINUMERIK CEC, siemens_comp.hpp): the error of the
// output axis (e.g. Y) measured while the input axis (e.g. X) moves, E_YX of ISO 230-1, is a
// positioning-test file whose deviations are the lateral readings (actual − nominal of the
// output axis, µm) at the input axis's targets. A straightness interferometer or a straightedge
// gives the readings about an arbitrary line (its own alignment), so ISO 230-1 (3.4.8)
// evaluates straightness about a reference line: the least-squares line (the default) or the
// line through the end points. The slope that is removed is the angle between the two axes'
// alignment and the optics, not a property of the machine alone: the axes' squareness (C0Y, B0Z,
// A0Z) is measured and compensated separately. Units: positions mm, errors µm, slope µm/m.
#pragma once

#include "volcomp/exporters/error_table.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::exporters {

enum class StraightnessLine {
  kLeastSquares,  // the least-squares line of every reading (both directions pooled)
  kEndPoints,     // the line through the first and last mean (both directions pooled)
  kNone,          // the readings as they are
};

struct StraightnessReference {
  double slope_um_per_m = 0;  // the line removed
  double offset_um = 0;       // its value at position 0
};

/// Subtracts the reference line from both directions of `table`; if the table was zeroed at a
/// position (zero_at), it is zeroed there again (forward error 0, linear interpolation).
/// kInvalidArgument for a rotary table or fewer than 2 positions.
Expected<StraightnessReference> RemoveReferenceLine(ErrorTable* table, StraightnessLine line);

}  // namespace volcomp::exporters
