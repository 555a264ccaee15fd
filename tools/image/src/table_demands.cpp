// Largest correction and gradients of a table image, from its node values.
#include "volcomp/image/table_demands.hpp"

#include <algorithm>
#include <cmath>

namespace volcomp::image {

std::vector<AxisDemand> TableDemands(const table::TableView& v) {
  std::vector<AxisDemand> out(v.axis_count);
  if (v.grid.present) {
    const table::Grid3View& g = v.grid;
    const uint32_t n[3] = {g.dim[0].nodes, g.dim[1].nodes, g.dim[2].nodes};
    const auto value = [&](uint32_t i, uint32_t j, uint32_t k, int c) {
      const uint32_t node = (k * n[1] + j) * n[0] + i;
      return table::ElementSteps(g.data, g.type, g.frac_bits, node * 3 + static_cast<uint32_t>(c));
    };
    std::array<double, 3> max_abs{};
    std::array<std::array<double, 3>, 3> max_step{};  // [component][dimension]
    for (uint32_t k = 0; k < n[2]; ++k) {
      for (uint32_t j = 0; j < n[1]; ++j) {
        for (uint32_t i = 0; i < n[0]; ++i) {
          for (int c = 0; c < 3; ++c) {
            const double here = value(i, j, k, c);
            max_abs[c] = std::max(max_abs[c], std::fabs(here));
            if (i + 1 < n[0])
              max_step[c][0] = std::max(max_step[c][0], std::fabs(value(i + 1, j, k, c) - here));
            if (j + 1 < n[1])
              max_step[c][1] = std::max(max_step[c][1], std::fabs(value(i, j + 1, k, c) - here));
            if (k + 1 < n[2])
              max_step[c][2] = std::max(max_step[c][2], std::fabs(value(i, j, k + 1, c) - here));
          }
        }
      }
    }
    for (int c = 0; c < 3; ++c) {
      AxisDemand& d = out[g.axis[c]];
      d.max_correction_steps += max_abs[c];
      for (int dim = 0; dim < 3; ++dim) {
        d.gradient[g.axis[dim]] += max_step[c][dim] / g.dim[dim].spacing_steps;
      }
    }
  }
  for (uint8_t t = 0; t < v.axis1d_count; ++t) {
    const table::Axis1dView& a = v.axis1d[t];
    // Moving forward: the forward values; moving negative: the reverse values (or the forward
    // ones) plus the backlash.
    const double backlash = a.backlash_q8 / 256.0;
    double max_abs = 0, max_step = 0;
    for (int dir = 0; dir < 2; ++dir) {
      const uint8_t* values = dir == 1 && a.reverse != nullptr ? a.reverse : a.forward;
      const double offset = dir == 1 ? backlash : 0.0;
      for (uint32_t i = 0; i < a.dim.nodes; ++i) {
        const double here = table::ElementSteps(values, a.type, a.frac_bits, i);
        max_abs = std::max(max_abs, std::fabs(here + offset));
        if (i + 1 < a.dim.nodes) {
          max_step = std::max(
              max_step, std::fabs(table::ElementSteps(values, a.type, a.frac_bits, i + 1) - here));
        }
      }
    }
    AxisDemand& d = out[a.axis];
    d.max_correction_steps += max_abs;
    d.gradient[a.axis] += max_step / a.dim.spacing_steps;
  }
  return out;
}

}  // namespace volcomp::image
