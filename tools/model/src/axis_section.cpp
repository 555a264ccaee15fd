// AXIS1D section of one axis from its positioning test (see axis_section.hpp).
#include "volcomp/model/axis_section.hpp"

#include <stdexcept>
#include <string>

#include "volcomp/model/image_glue.hpp"

namespace volcomp::model {

AxisSection BuildAxisSection(const PositioningData& data,
                             Axis1dOptions options,
                             const image::AxisDef& axis,
                             uint8_t index,
                             bool wrap) {
  const bool rotary = axis.kind == table::AxisKind::kRotary;
  if (data.rotary != rotary) {
    throw std::invalid_argument(std::string("axis ") + axis.name +
                                (rotary ? " is rotary: give position_deg and *_arcsec columns"
                                        : " is linear: give position_mm and *_um columns"));
  }
  options.unit_per_step = axis.units_per_step();
  AxisSection s;
  s.table = BuildAxis1d(data, options);
  s.section = ToAxisCorrections(s.table, index, axis, rotary, wrap && rotary);
  return s;
}

}  // namespace volcomp::model
