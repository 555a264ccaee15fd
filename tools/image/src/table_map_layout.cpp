// Geometry of the table map's slice panels.
#include "table_map_layout.hpp"

#include <algorithm>
#include <cmath>

namespace volcomp::image {
namespace {

constexpr double kPlotPx = 260;  // the longer side of a lattice's extent
constexpr int kArrowCells = 10;  // at most about this many arrow spacings across a plot

const int kPlaneDims[3][2] = {{0, 1}, {0, 2}, {1, 2}};

// The largest (smallest) of `steps` x 10^k at or below (above) x > 0; `steps` ascending in
// [1, 10].
template <size_t N>
double Round(double x, const double (&steps)[N], bool up) {
  const double mag = std::pow(10.0, std::floor(std::log10(x)));
  const double f = x / mag;
  if (up) {
    for (double s : steps) {
      if (f <= s * (1 + 1e-12)) return s * mag;
    }
    return 10 * mag;
  }
  for (size_t i = N; i-- > 0;) {
    if (f >= steps[i] * (1 - 1e-12)) return steps[i] * mag;
  }
  return mag;
}

constexpr double kOneTwoFive[] = {1, 2, 5};
constexpr double kColourSteps[] = {1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8};

}  // namespace

int PlaneOf(const MapSlice& slice) { return slice.u == 0 ? (slice.v == 1 ? 0 : 1) : 2; }

std::string PlaneName(const TableMap& map, int plane) {
  return std::string(1, map.axes[map.dim[kPlaneDims[plane][0]].axis].name) +
         map.axes[map.dim[kPlaneDims[plane][1]].axis].name;
}

double NiceFloor(double x) {
  return x > 0 && std::isfinite(x) ? Round(x, kOneTwoFive, false) : 1.0;
}
double ColourLimit(double x) {
  return x > 0 && std::isfinite(x) ? Round(x, kColourSteps, true) : 1.0;
}

PlaneLayout LayoutPlane(const TableMap& map, int plane) {
  PlaneLayout l;
  l.u = kPlaneDims[plane][0];
  l.v = kPlaneDims[plane][1];
  const MapDimension& du = map.dim[l.u];
  const MapDimension& dv = map.dim[l.v];
  l.u0 = du.from;
  l.u1 = du.to;
  l.v0 = dv.from;
  l.v1 = dv.to;
  const double eu = l.u1 - l.u0, ev = l.v1 - l.v0;
  const auto linear = [&](uint8_t axis) { return !map.axes[axis].rotary; };
  l.length_plot = linear(du.axis) && linear(dv.axis) && linear(map.component_axis[l.u]) &&
                  linear(map.component_axis[l.v]);
  if (linear(du.axis) && linear(dv.axis)) {
    l.px_per_u = l.px_per_v = kPlotPx / std::max(eu, ev);
  } else {
    l.px_per_u = kPlotPx / eu;
    l.px_per_v = kPlotPx / ev;
  }
  l.plot_w = eu * l.px_per_u;
  l.plot_h = ev * l.px_per_v;
  // Room for the colour cells of the edge samples: half a sample gap.
  const auto half_gap = [](const MapDimension& d, double px_per) {
    double g = 0;
    for (size_t i = 1; i < d.sample_pos.size(); ++i) {
      g = std::max(g, (d.sample_pos[i] - d.sample_pos[i - 1]) * px_per / 2);
    }
    return g;
  };
  l.pad = std::max({10.0, half_gap(du, l.px_per_u), half_gap(dv, l.px_per_v)});

  const auto stride = [](const MapDimension& d) {
    const int cells = static_cast<int>(d.nodes - 1);
    return std::max(d.node_stride, (cells + kArrowCells - 1) / kArrowCells);
  };
  l.arrow_stride_u = stride(du);
  l.arrow_stride_v = stride(dv);

  // The arrows: the longest in-plane vector on any slice of the plane about 0.9 of the spacing
  // of the drawn nodes, at a 1-2-5 scale.
  double longest = 0;
  for (const MapSlice& s : map.slices) {
    if (PlaneOf(s) != plane) continue;
    for (size_t i = 0; i < s.value.size(); i += 3) {
      longest = std::max(longest, std::hypot(s.value[i + l.u], s.value[i + l.v]));
    }
  }
  if (longest <= 0) return l;
  const double arrow_room = 0.9 * std::min(du.spacing * l.arrow_stride_u * l.px_per_u,
                                           dv.spacing * l.arrow_stride_v * l.px_per_v);
  const double gain = arrow_room / longest;
  if (l.length_plot) {
    const double px_per_um = l.px_per_u * 1e-3;
    l.magnification = NiceFloor(gain / px_per_um);
    l.arrow_px_per_unit = l.magnification * px_per_um;
  } else {
    l.arrow_px_per_unit = NiceFloor(gain);
  }
  return l;
}

}  // namespace volcomp::image
