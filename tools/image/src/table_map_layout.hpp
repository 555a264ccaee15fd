// The table map's plot geometry (shared by the figures and by the scale factors the map reports):
// lattice positions to pixels of a slice panel, and the arrows' gain.
#pragma once

#include <cstdint>
#include <string>

#include "volcomp/image/table_map.hpp"

namespace volcomp::image {

/// Plane p of a map: 0 = lattice dimensions (0, 1), 1 = (0, 2), 2 = (1, 2).
int PlaneOf(const MapSlice& slice);
/// The plane's axis names, e.g. "XZ".
std::string PlaneName(const TableMap& map, int plane);

/// The largest 1, 2 or 5 x 10^k at or below `x`; 1 for x <= 0.
double NiceFloor(double x);
/// The colour bar's limit for a largest |value| `x`: the smallest of 1, 1.2, 1.5, 2, 2.5, 3, 4,
/// 5, 6, 8 x 10^k at or above it (a round number, at most 25 % above x); 1 for x <= 0.
double ColourLimit(double x);

struct PlaneLayout {
  int u = 0, v = 1;
  double left = 56, top = 28, bottom = 48, right = 14;  // margins around the frame, px
  double pad = 10;                                      // frame to lattice extent, px
  double plot_w = 0, plot_h = 0;                        // the lattice's extent, px
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;                // the lattice's extent, display units
  double px_per_u = 0, px_per_v = 0;
  int arrow_stride_u = 1, arrow_stride_v = 1;  // arrows at every n-th node
  bool length_plot = false;  // both axes and both in-plane components linear: one scale
  double arrow_px_per_unit = 0;
  double magnification = 0;  // µm of drawing per µm of correction (length plots), else 0

  /// Whether node (i, j) of the plane carries an arrow.
  bool ArrowAt(int32_t node_u, int32_t node_v) const {
    return node_u >= 0 && node_v >= 0 && node_u % arrow_stride_u == 0 &&
           node_v % arrow_stride_v == 0;
  }
  double X(double u_pos) const { return left + pad + (u_pos - u0) * px_per_u; }
  double Y(double v_pos) const { return top + pad + plot_h - (v_pos - v0) * px_per_v; }
  double frame_w() const { return plot_w + 2 * pad; }
  double frame_h() const { return plot_h + 2 * pad; }
  double width() const { return left + frame_w() + right; }
  double height() const { return top + frame_h() + bottom; }
};

/// The layout of plane `plane` of `map` (its slices must be filled in).
PlaneLayout LayoutPlane(const TableMap& map, int plane);

}  // namespace volcomp::image
