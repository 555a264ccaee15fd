// AXIS1D section of one axis from its positioning test (see axis_section.hpp).
#include "volcomp/builders/axis_section.hpp"

#include <string>

#include "volcomp/builders/image_glue.hpp"

namespace volcomp::builders {

Expected<AxisSection> BuildAxisSection(const model::PositioningData& data,
                                       Axis1dOptions options,
                                       const image::AxisDef& axis,
                                       uint8_t index,
                                       bool wrap) {
  const bool rotary = axis.kind == table::AxisKind::kRotary;
  if (data.rotary != rotary) {
    return Fail(Error::kInvalidArgument,
                std::string("axis ") + axis.name +
                    (rotary ? " is rotary: give position_deg and *_arcsec columns"
                            : " is linear: give position_mm and *_um columns"));
  }
  options.unit_per_step = axis.units_per_step();
  AxisSection s;
  VOLCOMP_TRY_ASSIGN(s.table, BuildAxis1d(data, options));
  VOLCOMP_TRY_ASSIGN(s.section, ToAxisCorrections(s.table, index, axis, rotary, wrap && rotary));
  return s;
}

}  // namespace volcomp::builders
