// The STAN S500 machining centre of the dissertation, compiled in (no input files needed).
//
// Data: Pimushkin (STANKIN, 2023) Tables 3.2-3.4 (Renishaw XL-80 parametric errors of X, Y, Z),
// Tables 3.5/3.6 (M_max/M_min), the laser-tracker axis lines of Tables 2.10-2.12 (315 mm cube,
// the data of Appendices Б-Г) and 2.6-2.8 (240 mm cube), and the out-of-squareness those lines
// show (the dissertation gives none; see docs/table-builders.md for the values and their source).
//
// Kinematic chain: the dissertation does not state it. §3.1 says "the position of the longitudinal
// axis is invariant, while the positions of the transverse and vertical axes depend on the target",
// read here as the serial order X → Y → Z from the workpiece to the tool (chain "|XYZ").
#pragma once

#include <array>
#include <optional>
#include <string>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/dissertation.hpp"
#include "volcomp/model/rigid_body.hpp"
#include "volcomp/model/tracker.hpp"

namespace volcomp::datasets {

/// Tables 3.2 (axis 0 = X), 3.3 (1 = Y), 3.4 (2 = Z); angular columns converted to µrad.
/// kInvalidArgument for another axis.
Expected<model::AxisErrorTable> S500AxisTable(int axis);
/// The three tables in axis order.
std::array<model::AxisErrorTable, 3> S500AxisTables();
/// Rows n_x of Table 3.2, n_y of 3.3, n_z of 3.4 exactly as printed (grid node of Tables
/// 3.7-3.13); kInvalidArgument for a row that does not exist.
Expected<model::PointErrors> S500PointErrorsAtNode(int nx, int ny, int nz);
/// Table 3.5 (hypothetical point M_max) and Table 3.6 (M_min), as printed.
model::PointErrors S500MaxErrors();
model::PointErrors S500MinErrors();
/// The squareness in the convention of rigid_body.hpp (C0Y, B0Z, A0Z in µrad).
model::Squareness S500Squareness();

struct S500Options {
  bool include_squareness = true;
  model::Vec3 tool_offset_mm;                  // 0: the tables' measuring point
  model::Order order = model::Order::kSecond;  // exact rotations
  model::KinematicChain chain;  // default: X → Y → Z, all "relative" error functions
};

/// The physical 21-parameter model of the S500 (the simulator's default machine).
model::Model S500Model(const S500Options& options = {});

/// The dissertation's formulation on the same tables, with r = (10, 10, 10) mm as in every printed
/// table; `order`/`which` select δ (kFirst) or δ+/δ− (kSecond with kPlus/kMinus).
model::Model S500DissertationModel(model::Order order = model::Order::kFirst,
                                   model::DissertationCase which = model::DissertationCase::kPlus,
                                   double k = 1.0);

/// The laser-tracker axis lines of Tables 2.10-2.12 (315 mm cube) and 2.6-2.8 (240 mm cube),
/// cosines as printed (signs dropped).
model::TrackerData S500Tracker315();
model::TrackerData S500Tracker240();
/// The built-in tracker lines by the name the commands use: "s500-315" or "s500-240" (nullopt for
/// another name).
std::optional<model::TrackerData> S500TrackerNamed(const std::string& name);

}  // namespace volcomp::datasets
