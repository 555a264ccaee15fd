// What a table asks of the board's limits: per corrected axis, the largest correction and how fast
// the correction changes with the motion of each input axis. The PC tool compares these with the
// board's installation (max correction 0x2015, max correction rate 0x2016, max input rate 0x201E)
// before a table is uploaded or activated, so a table the board would clamp or rate-limit is
// refused instead of being applied in part without a word.
//
// Bounds, from the image's node values (trilinear and linear interpolation stay within them):
//   largest correction: max over nodes of |grid component| + max |AXIS1D value| (forward and
//     reverse, backlash included) of the axis;
//   gradient: for each input axis b, the largest difference between neighbouring nodes along b
//     divided by the node spacing (steps of correction per input step). Within a cell the partial
//     derivative is a blend of its edges' differences, so this bounds it everywhere. The rate bound
//     of axis a is the sum over input axes b of gradient(a, b) x fastest input rate of b; the
//     backlash jump at a reversal is left out (the limiter ramps it by design).
#pragma once

#include <array>
#include <vector>

#include "volcomp/table/table_format.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp::image {

struct AxisDemand {
  double max_correction_steps = 0;  // largest |correction| the table asks for on this axis
  /// d(correction of this axis) / d(position of input axis b), largest magnitude, per board axis.
  std::array<double, table::kMaxAxes> gradient{};
};

/// One entry per axis of the image (board axis order).
std::vector<AxisDemand> TableDemands(const table::TableView& view);

}  // namespace volcomp::image
