// Trilinear interpolation of the GRID3 correction vector at a position (the per-tick hot path).
//
// GridLookup::Init() takes a validated Grid3View and precomputes the cell locators and byte strides
// (may divide; call at activation). Lookup() clamps the position to the grid (values at the
// boundary hold outside), finds the cell, forms the 8 trilinear weights once and sums the 8 corner
// values of each of the 3 components: no division, no data-dependent branch except the clamp,
// constant time. Output: the 3 components in Q24.8 steps; component c corrects axis axis(c).
//
// Accuracy (tests/lib/grid_lookup_test.cpp measures it): int16/int32 tables are within 1 LSB of
// the Q8 output (2^-8 step) of the exact real-valued trilinear interpolation; float32 tables
// within 1 LSB + 2^-20 relative (see docs/table-image-format.md).
#pragma once

#include <cstdint>

#include "volcomp/cell_locator.hpp"
#include "volcomp/interp_arith.hpp"
#include "volcomp/status.hpp"
#include "volcomp/table_image.hpp"

namespace volcomp {

class GridLookup {
 public:
  /// Prepares for `grid` (which must be present and valid); the image must outlive the lookup.
  Status Init(const table::Grid3View& grid);

  /// Correction at `pos_steps` (indexed by board axis; only axis(0..2) are read), Q24.8 steps.
  void Lookup(const int32_t* pos_steps, int32_t out_q8[3]) const {
    switch (type_) {
      case table::ElementType::kInt16:
        Interpolate<LoadInt16>(pos_steps, out_q8);
        break;
      case table::ElementType::kInt32:
        Interpolate<LoadInt32>(pos_steps, out_q8);
        break;
      case table::ElementType::kFloat32:
        Interpolate<LoadFloat32>(pos_steps, out_q8);
        break;
    }
  }

  /// The same computation for an explicit element loader (benchmarks and cycle tests call this).
  template <class Loader>
  void Interpolate(const int32_t* pos_steps, int32_t out_q8[3]) const;

  uint8_t axis(int d) const { return axis_[d]; }
  table::ElementType element_type() const { return type_; }

 private:
  CellLocator loc_[3];
  uint32_t stride_[3] = {0, 0, 0};  // bytes between neighbouring nodes along each dimension
  uint8_t axis_[3] = {0, 1, 2};
  uint32_t shift_ = 22;  // FixedQ30::ToQ8 shift
  table::ElementType type_ = table::ElementType::kInt16;
  const uint8_t* data_ = nullptr;
};

template <class Loader>
void GridLookup::Interpolate(const int32_t* pos_steps, int32_t out_q8[3]) const {
  using A = typename Loader::Arith;
  const CellPosition cx = loc_[0].Locate(pos_steps[axis_[0]]);
  const CellPosition cy = loc_[1].Locate(pos_steps[axis_[1]]);
  const CellPosition cz = loc_[2].Locate(pos_steps[axis_[2]]);
  const uint8_t* base = data_ + cx.cell * stride_[0] + cy.cell * stride_[1] + cz.cell * stride_[2];

  // Weights: x first, then y, then z; each pair is (parent - child, child) so they sum to One().
  const typename A::Weight tx = A::FromQ30(cx.t_q30), ty = A::FromQ30(cy.t_q30),
                           tz = A::FromQ30(cz.t_q30);
  const typename A::Weight x1 = tx, x0 = A::One() - tx;
  const typename A::Weight x1y1 = A::Mul(x1, ty), x1y0 = x1 - x1y1;
  const typename A::Weight x0y1 = A::Mul(x0, ty), x0y0 = x0 - x0y1;
  typename A::Weight w[8];
  w[1] = x1y0;  // temporarily hold the xy weights in the z0 slots
  w[0] = x0y0;
  w[2] = x0y1;
  w[3] = x1y1;
  for (int k = 0; k < 4; ++k) {
    w[k + 4] = A::Mul(w[k], tz);
    w[k] -= w[k + 4];
  }
  const uint32_t sx = stride_[0], sy = stride_[1], sz = stride_[2];
  const uint32_t offset[8] = {0, sx, sy, sx + sy, sz, sz + sx, sz + sy, sz + sx + sy};
  for (uint32_t c = 0; c < 3; ++c) {
    typename A::Acc acc = A::Zero();
    for (int k = 0; k < 8; ++k) {
      acc = A::Mac(acc, w[k], Loader::Load(base + offset[k] + c * Loader::kSize));
    }
    out_q8[c] = A::ToQ8(acc, shift_);
  }
}

}  // namespace volcomp
