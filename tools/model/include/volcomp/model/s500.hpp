// The STAN S500 machining centre of the dissertation, compiled in (no input files needed).
//
// Data: Pimushkin (STANKIN, 2023) Tables 3.2-3.4 (Renishaw XL-80: X 0-400 mm every 20 mm, Y 0-280
// every 10, Z 0-200 every 10), Tables 3.5/3.6 (M_max/M_min), and the out-of-squareness that the
// laser-tracker lines of the 315 mm cube (Tables 2.10-2.12) show: mean axis directions
// X = (1, 0.000496, 0.000138), Y = (0.000612, 1, 0.000322), Z = (0.000317, 0.000199, 1)
// (digest dissertation-ch1-2.md §3.7), i.e. X·Y = 1108.5 µrad, X·Z = 455.0 µrad, Y·Z = 520.9 µrad
// (angles below 90°). The dissertation itself gives no squareness values; these come from a
// different measurement run than Tables 3.2-3.4 (see docs/table-builders.md).
//
// Kinematic chain: the dissertation does not state it. §3.1 says "the position of the longitudinal
// axis is invariant, while the positions of the transverse and vertical axes depend on the target",
// read here as the serial order X → Y → Z from the workpiece to the tool (chain "|XYZ").
#pragma once

#include "volcomp/model/dissertation.hpp"
#include "volcomp/model/rigid_body.hpp"

namespace volcomp::model {

/// Tables 3.2 (axis 0 = X), 3.3 (1 = Y), 3.4 (2 = Z); angular columns converted to µrad.
AxisErrorTable S500AxisTable(int axis);
/// The three tables in axis order.
std::array<AxisErrorTable, 3> S500AxisTables();
/// Rows n_x of Table 3.2, n_y of 3.3, n_z of 3.4 exactly as printed (grid node of Tables 3.7-3.13).
/// Throws std::out_of_range for a row that does not exist.
PointErrors S500PointErrorsAtNode(int nx, int ny, int nz);
/// Table 3.5 (hypothetical point M_max) and Table 3.6 (M_min), as printed.
PointErrors S500MaxErrors();
PointErrors S500MinErrors();
/// The squareness described above in the convention of rigid_body.hpp:
/// C0Y = −1108.5 µrad, B0Z = +455.0 µrad, A0Z = −520.9 µrad.
Squareness S500Squareness();

struct S500Options {
  bool include_squareness = true;
  Vec3 tool_offset_mm;           // 0: the tables' measuring point
  Order order = Order::kSecond;  // exact rotations
  KinematicChain chain;          // default: X → Y → Z, all "relative" error functions
};

/// The physical 21-parameter model of the S500 (the simulator's default machine).
Model S500Model(const S500Options& options = {});

/// The dissertation's formulation on the same tables, with r = (10, 10, 10) mm as in every printed
/// table; `order`/`which` select δ (kFirst) or δ+/δ− (kSecond with kPlus/kMinus).
Model S500DissertationModel(Order order = Order::kFirst,
                            DissertationCase which = DissertationCase::kPlus,
                            double k = 1.0);

}  // namespace volcomp::model
