// Laser-tracker readings at every node of a 3-D lattice of commands: the tangential methods of the
// dissertation's chapter 2 without their separability assumption.
//
// The quasi-differential method integrates the tangent vectors of the axes along the path
// (eq. 2.14, r = r_O1 + ∫ Q1(q1)dq1 + Q2(q1,q2)dq2 + Q3(q1,q2,q3)dq3) and then assumes that
// ∂Q2/∂q1 = ∂Q3/∂q1 = ∂Q3/∂q2 = 0, so that three lines through the origin suffice (tracker.hpp).
// Errors of one axis that depend on the position of another (a sagging structure, a load that
// moves with an axis) break that assumption. Measured at every node of a lattice (the grid of
// Jacobians of Masterenko's method, [P] §1.4), the tangent vectors are known in every cell; taking
// them linear across the cell makes the forward map the trilinear interpolation of the measured
// node positions, which passes through every measurement and keeps every cross-axis term.
//
// Data: the commanded node (x, y, z) and the averaged tracker reading (mm, tracker frame
// registered so that the datum reads its command); the file format is in
// volcomp/datasets/tracker_csv.hpp. Lengths in mm.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/inverse.hpp"
#include "volcomp/model/lattice.hpp"
#include "volcomp/model/vec3.hpp"

namespace volcomp::model {

struct TrackerLatticeData {
  std::string name;
  GridAxes lattice;               // the commanded nodes
  std::vector<Vec3> position_mm;  // reading at each node, x fastest (CorrectionGrid order)
};

class TrackerLattice {
 public:
  /// kInvalidArgument unless every axis has ≥ 2 nodes at a positive spacing, the readings number
  /// nx·ny·nz and are finite.
  static Expected<TrackerLattice> Create(TrackerLatticeData data);

  const TrackerLatticeData& data() const { return data_; }

  /// Where the tool goes for `command_mm`: trilinear in the command's cell; beyond the lattice
  /// the boundary cell's trilinear form continues (linear extrapolation).
  Vec3 Position_mm(const Vec3& command_mm) const;
  /// The command that lands on `target_mm` (fixed-point iteration on Position_mm).
  InverseSolution ExactInverse(const Vec3& target_mm, double tolerance_mm = 1e-8) const;

 private:
  explicit TrackerLattice(TrackerLatticeData data) : data_(std::move(data)) {}
  TrackerLatticeData data_;
};

}  // namespace volcomp::model
