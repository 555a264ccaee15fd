// Laser-tracker point-set methods of the dissertation's chapter 2: tangential static, interval and
// quasi-differential correction (Pimushkin 2023, §2.1-2.3, eqs. 2.2-2.18, Appendices Б, В, Г), on
// three straight measurement lines through a common origin, one per axis, nodes every u mm from
// commanded 0. Interval i runs from node i to node i+1; its direction vector is printed in the row
// of node i+1. The direction vectors are the printed cosines (signs dropped, as printed), unit
// vectors recomputed from the readings (signed) or the displacement per commanded mm (scaled, only
// meaningful with the quasi-differential method); docs/table-builders.md §4 compares them.
// Lengths in mm. Invalid data and singular direction matrices are failures (kInvalidArgument,
// kInputInvalid), never exceptions.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/inverse.hpp"
#include "volcomp/model/vec3.hpp"

namespace volcomp::model {

struct TrackerNode {
  double q_mm = 0;   // commanded travel of the line's axis
  Vec3 p_mm;         // averaged tracker reading
  Vec3 printed_cos;  // direction cosines of the interval ending here, as printed (optional)
};

struct TrackerData {
  std::string name;
  std::array<std::vector<TrackerNode>, 3> lines;  // X, Y, Z lines; node 0 at q = 0
  bool has_printed_cosines = false;
};

/// kInvalidArgument unless every line has ≥ 3 nodes, starts at q = 0 and has equally spaced,
/// increasing q.
Outcome ValidateTrackerData(const TrackerData& data);

enum class CosineSource { kPrinted, kSigned, kScaled };
enum class OriginSource { kExtrapolated, kMeasured };

struct TrackerOptions {
  CosineSource cosines = CosineSource::kSigned;
  /// kExtrapolated: r01 back-extrapolated from X nodes s and s+1 (s = static_interval) as in
  /// §2.1 / the appendices; kMeasured: the measured origin node.
  OriginSource origin = OriginSource::kExtrapolated;
  int static_interval = 1;  // the appendices use nodes 15 and 30 mm (interval 1) on every axis
};

struct TrackerStaticResult {
  Vec3 r01_mm;
  Mat3 g;  // columns: direction vectors of the X, Y, Z intervals
  Vec3 command_mm;
};

struct TrackerIntervalResult {
  std::array<int, 3> n = {0, 0, 0};  // interval of the target on each axis, trunc(r/u)
  Vec3 r01_mm;
  Mat3 g;
  Vec3 command_mm;
};

struct TrackerQuasiResult {
  std::array<int, 3> n = {0, 0, 0};
  Vec3 r_mm;      // R of (2.17): origin plus the completed intervals
  Mat3 g;         // G_M of (2.18)
  Vec3 gamma_mm;  // γ = G_M⁻¹ (r − R)
  Vec3 command_mm;
};

/// The direction-vector field of one data set, precomputed, and the three methods on it.
class TrackerModel {
 public:
  /// kInvalidArgument for invalid data, kPrinted without printed cosines, two equal consecutive
  /// nodes or a static interval outside the data.
  static Expected<TrackerModel> Create(const TrackerData& data, const TrackerOptions& options);

  int intervals(int axis) const { return static_cast<int>(cc_[axis].size()); }
  double step_mm(int axis) const { return step_mm_[axis]; }
  /// CC[i] of an axis (i clamped to the table).
  const Vec3& interval_vector(int axis, int i) const;
  /// r01 per the options (used by the static and quasi-differential methods).
  const Vec3& origin_mm() const { return r01_; }
  /// Origin back-extrapolated from X nodes i and i+1 with q1T = q of node i (§2.1, Appendix В).
  Vec3 OriginFromXInterval(int i) const;
  const TrackerOptions& options() const { return options_; }

  // The three methods fail (kInputInvalid) when their direction matrix is singular.
  /// Appendix Б: one calibration matrix from interval `static_interval` of each axis.
  Expected<TrackerStaticResult> Static(const Vec3& target_mm) const;
  /// Appendix В: the target's cell; discontinuous at cell borders (11-41 µm on the 315 data).
  Expected<TrackerIntervalResult> Interval(const Vec3& target_mm) const;
  /// Appendix Г / eqs. 2.15-2.18: completed intervals summed, the last one solved for.
  Expected<TrackerQuasiResult> QuasiDifferential(const Vec3& target_mm) const;

  /// The forward map the quasi-differential method assumes (separable, piecewise linear, knots at
  /// the nodes): r(q) = r01 + Σ_axes [Σ_{i<m} u·CC[i] + (q − m·u)·CC[m]]; linear extrapolation
  /// with the end intervals outside the table.
  Vec3 Position_mm(const Vec3& command_mm) const;
  /// Static method's forward map: r01 + G·q (affine).
  Vec3 StaticPosition_mm(const Vec3& command_mm) const;
  /// Exact inverse of Position_mm by iteration (the appendix form deviates ≤ 0.13 µm from it).
  InverseSolution ExactInverse(const Vec3& target_mm, double tolerance_mm = 1e-8) const;

 private:
  TrackerModel(const TrackerData& data, const TrackerOptions& options)
      : data_(data), options_(options) {}
  int CellIndex(int axis, double value_mm) const;

  TrackerData data_;
  TrackerOptions options_;
  std::array<std::vector<Vec3>, 3> cc_;
  std::array<std::vector<Vec3>, 3> cum_;  // cum_[a][m] = Σ_{i<m} u·CC[i]
  std::array<double, 3> step_mm_ = {0, 0, 0};
  Vec3 r01_;
};

}  // namespace volcomp::model
