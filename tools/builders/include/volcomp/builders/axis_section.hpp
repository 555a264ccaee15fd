// One axis of `volcomp build axis`: the AXIS1D table from the mean deviations of a positioning test
// (axis1d.hpp), snapped to the axis's steps, as the image section for that axis. Shared by the
// command and the simulator's demo.
#pragma once

#include <cstdint>

#include "volcomp/builders/axis1d.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/model/positioning.hpp"

namespace volcomp::builders {

struct AxisSection {
  Axis1dTable table;               // positions mm (deg), corrections µm (arcsec)
  image::AxisCorrections section;  // in steps of the axis
};

/// Builds axis `axis` (image axis number `index`) from `data`; options.unit_per_step is taken
/// from the axis. `wrap`: rotary wrap-around (the table must span 360°). kInvalidArgument when
/// the data's kind (linear/rotary) is not the axis's or BuildAxis1d refuses the data,
/// kInputInvalid when a position is not a whole number of steps.
Expected<AxisSection> BuildAxisSection(const model::PositioningData& data,
                                       Axis1dOptions options,
                                       const image::AxisDef& axis,
                                       uint8_t index,
                                       bool wrap);

}  // namespace volcomp::builders
