// The six error functions of one linear axis, tabulated against that axis's own position.
//
// Naming follows ISO 230-1: for a moving axis K the linear errors are E_XK, E_YK, E_ZK (error
// motion of the tool point along x, y, z while K moves) and the angular errors E_AK, E_BK, E_CK
// (rotations about x, y, z, right-handed). The dissertation writes the same six functions as
// δ_kx, δ_ky, δ_kz and ε_kx, ε_ky, ε_kz (first index = moving axis, second = direction; Table 3.1).
//
// Units: positions in mm, linear errors in µm, angular errors in µrad (1 µm/mm = 1000 µrad).
// Between rows the functions are linear (the tables are samples of continuous functions); outside
// the table the end rows are held constant, so a model never extrapolates a slope into the unknown.
// A table is made by Create (kInvalidArgument for rows a table cannot hold); a default-constructed
// one is empty.
#pragma once

#include <cstddef>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/vec3.hpp"

namespace volcomp::model {

/// Error motions of one axis at one position.
struct AxisErrorSample {
  Vec3 linear_um;     // E_XK, E_YK, E_ZK
  Vec3 angular_urad;  // E_AK, E_BK, E_CK
};

class AxisErrorTable {
 public:
  AxisErrorTable() = default;
  /// Rows at strictly increasing positions (at least 2, all finite); kInvalidArgument naming the
  /// row otherwise.
  static Expected<AxisErrorTable> Create(std::vector<double> position_mm,
                                         std::vector<AxisErrorSample> rows);

  std::size_t size() const { return position_mm_.size(); }
  bool empty() const { return position_mm_.empty(); }
  double position_mm(std::size_t i) const { return position_mm_[i]; }
  const AxisErrorSample& row(std::size_t i) const { return rows_[i]; }
  double min_mm() const { return position_mm_.front(); }
  double max_mm() const { return position_mm_.back(); }
  /// Row spacing when the rows are equally spaced (to 1e-9 mm), else 0.
  double uniform_spacing_mm() const { return uniform_spacing_mm_; }

  /// Errors at a position: linear interpolation between rows, end rows held outside the table.
  AxisErrorSample Sample(double position_mm) const;

  /// The same functions sampled every `step_mm` from min_mm() up to `max_mm` (linear
  /// interpolation of the columns, as the dissertation's Tables 4.5-4.7 refine Tables 3.2-3.4);
  /// kInvalidArgument for a step that is not positive or a range that ends before min_mm().
  Expected<AxisErrorTable> Resampled(double step_mm, double max_mm) const;

 private:
  std::vector<double> position_mm_;
  std::vector<AxisErrorSample> rows_;
  double uniform_spacing_mm_ = 0.0;
};

}  // namespace volcomp::model
