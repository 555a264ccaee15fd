// Conversion of builder results to image sections (see image_glue.hpp).
#include "volcomp/builders/image_glue.hpp"

#include <cmath>
#include <string>

namespace volcomp::builders {
namespace {

using model::Vec3;

Unexpected<Failure> Invalid(const std::string& message) {
  return Fail(Error::kInputInvalid, message);
}

Expected<int64_t> WholeSteps(double value, double unit_per_step, const std::string& what) {
  const double steps = value / unit_per_step;
  const double rounded = std::round(steps);
  if (std::fabs(steps - rounded) > 1e-6 * std::fmax(1.0, std::fabs(steps))) {
    return Invalid(what + " is not a whole number of steps");
  }
  if (rounded < -2147483648.0 || rounded > 2147483647.0) {
    return Invalid(what + " does not fit in 32-bit steps");
  }
  return static_cast<int64_t>(rounded);
}

}  // namespace

Expected<image::GridCorrections> ToGridCorrections(const model::CorrectionGrid& grid,
                                                   const std::vector<image::AxisDef>& axes) {
  if (axes.size() < 3) return Invalid("a GRID3 needs three axes");
  image::GridCorrections g;
  for (int d = 0; d < 3; ++d) {
    const std::size_t ud = static_cast<std::size_t>(d);
    const double unit = axes[ud].units_per_step();
    const std::string name = std::string("axis ") + axes[ud].name;
    g.axis[ud] = static_cast<uint8_t>(d);
    g.lattice[ud].nodes = grid.axes[ud].nodes;
    VOLCOMP_TRY_ASSIGN(const int64_t origin,
                       WholeSteps(grid.axes[ud].origin_mm, unit, name + " grid origin"));
    g.lattice[ud].origin_steps = static_cast<int32_t>(origin);
    VOLCOMP_TRY_ASSIGN(const int64_t spacing,
                       WholeSteps(grid.axes[ud].spacing_mm, unit, name + " grid spacing"));
    if (spacing < 1) return Invalid(name + ": grid spacing below one step");
    g.lattice[ud].spacing_steps = static_cast<uint32_t>(spacing);
  }
  g.correction_steps.reserve(grid.correction_mm.size() * 3);
  for (const Vec3& c : grid.correction_mm) {
    for (int d = 0; d < 3; ++d) {
      g.correction_steps.push_back(c[d] / axes[static_cast<std::size_t>(d)].units_per_step());
    }
  }
  return g;
}

Expected<image::AxisCorrections> ToAxisCorrections(const Axis1dTable& table,
                                                   uint8_t axis_index,
                                                   const image::AxisDef& axis,
                                                   bool rotary,
                                                   bool wrap) {
  const double unit = axis.units_per_step();
  const std::string name = std::string("axis ") + axis.name;
  // Corrections: µm → mm, arcsec → deg, then steps.
  const double to_units = rotary ? 1.0 / 3600.0 : 1e-3;
  image::AxisCorrections a;
  a.axis = axis_index;
  a.lattice.nodes = static_cast<uint32_t>(table.forward.size());
  VOLCOMP_TRY_ASSIGN(const int64_t origin, WholeSteps(table.origin, unit, name + " origin"));
  a.lattice.origin_steps = static_cast<int32_t>(origin);
  VOLCOMP_TRY_ASSIGN(const int64_t spacing, WholeSteps(table.spacing, unit, name + " spacing"));
  if (spacing < 1) return Invalid(name + ": spacing below one step");
  a.lattice.spacing_steps = static_cast<uint32_t>(spacing);
  for (double v : table.forward) a.forward_steps.push_back(v * to_units / unit);
  for (double v : table.reverse) a.reverse_steps.push_back(v * to_units / unit);
  a.backlash_steps = table.backlash * to_units / unit;
  if (wrap) {
    const double span = table.spacing * static_cast<double>(table.forward.size() - 1);
    if (!rotary || std::fabs(span - 360.0) > 1e-9) {
      return Invalid(name + ": wrap-around needs a rotary table spanning exactly 360°");
    }
    a.wrap_period_steps = static_cast<uint32_t>(spacing) * (a.lattice.nodes - 1);
  }
  return a;
}

double LsbUm(const image::AxisDef& axis, uint8_t frac_bits) {
  const double lsb_units = axis.units_per_step() * std::ldexp(1.0, -static_cast<int>(frac_bits));
  return axis.kind == table::AxisKind::kRotary ? lsb_units * 3600.0 : lsb_units * 1e3;
}

}  // namespace volcomp::builders
