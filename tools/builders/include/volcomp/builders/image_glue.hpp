// Builder results (mm, µm) → image sections (steps) for image::BuildImage. Positions that are not
// whole steps are failures (kInputInvalid naming the axis).
#pragma once

#include <cstdint>
#include <vector>

#include "volcomp/builders/axis1d.hpp"
#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_builder.hpp"
#include "volcomp/model/lattice.hpp"

namespace volcomp::builders {

/// The GRID3 of a correction grid for image axes `axes` (component/dimension c ↔ axes[c], linear,
/// mm). Origin and spacing must be whole steps (MakeGridAxes guarantees it); corrections are
/// converted to steps of their component's axis.
Expected<image::GridCorrections> ToGridCorrections(const model::CorrectionGrid& grid,
                                                   const std::vector<image::AxisDef>& axes);

/// The AXIS1D of a 1-D table for image axis `axis_index` (positions mm or deg, corrections µm or
/// arcsec). `wrap`: rotary wrap-around, the table must span exactly 360°.
Expected<image::AxisCorrections> ToAxisCorrections(const Axis1dTable& table,
                                                   uint8_t axis_index,
                                                   const image::AxisDef& axis,
                                                   bool rotary,
                                                   bool wrap);

/// Length of the least significant bit of an element with `frac_bits` for an axis, in µm (or
/// arcsec for rotary axes): 2^-frac_bits steps.
double LsbUm(const image::AxisDef& axis, uint8_t frac_bits);

}  // namespace volcomp::builders
