// Position (steps) -> lattice cell and fraction, with no division on the lookup path.
//
// A lattice dimension has nodes at origin + i*spacing, i = 0..nodes-1. The locator clamps the
// position to [origin, origin + (nodes-1)*spacing] and finds the cell in [0, nodes-2] and the
// fraction within it; Init() divides once, at table activation, to form the reciprocal.
#pragma once

#include <cstdint>

#include "volcomp/base/interp_arith.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp {

/// The hot-path locator: position -> (cell, fraction as Q0.32), one 32x64-bit multiply.
///
/// Init() precomputes recip = floor((2^64 - 1) / spacing) (64 bits, at activation). Locate()
/// clamps u = pos - origin to [0, span] (span = (nodes-1)*spacing) and forms the 64-bit cell
/// coordinate X = floor(u * recip / 2^32) = cell * 2^32 + frac. Because recip < 2^64 / spacing,
/// X is always slightly below the exact u * 2^32 / spacing (by less than 2 units of 2^-32 cells):
///   * off the nodes the cell is exact and frac is within 2 * 2^-32 of the exact fraction;
///   * on a node (u = m * spacing, m >= 1) the result is cell m - 1 with frac = 2^32 - 1 or
///     2^32 - 2, i.e. the end of the previous cell; the interpolated value is the same to within
///     2^-31 of a corner difference, and the last node needs no special case (cell <= nodes - 2
///     for every u <= span, proved by X < u * 2^32 / spacing <= (nodes - 1) * 2^32).
/// So the fraction never reaches 1.0 and fits in 32 bits. Cost on a Cortex-M4: clamp (5-7
/// instructions) + UMULL + UMLAL; no division, no data-dependent branch.
struct LatticeCell {
  uint32_t cell = 0;      // 0..nodes-2
  uint32_t frac_q32 = 0;  // [0, 2^32)
};

/// The constants of one lattice dimension, in the hot path's load order.
struct LatticeDim {
  int32_t lo = 0;
  uint32_t span = 0;      // (nodes - 1) * spacing <= table::kMaxExtentSteps (2^31 - 1)
  uint32_t recip_lo = 0;  // low word of floor((2^64 - 1) / spacing)
  uint32_t recip_hi = 0;  // high word
};

class LatticeLocator {
 public:
  /// `dim` must have passed table validation (nodes >= 2, spacing >= 1, extent within int32).
  void Init(const table::Dimension& dim);

  /// The clear reference (LocateFast() must give the same result for every position).
  LatticeCell Locate(int32_t pos_steps) const {
    uint32_t u = static_cast<uint32_t>(pos_steps) - static_cast<uint32_t>(d_.lo);
    u = pos_steps < d_.lo ? 0u : u;
    u = u > d_.span ? d_.span : u;
    const uint64_t x =
        ((static_cast<uint64_t>(u) * d_.recip_lo) >> 32) + static_cast<uint64_t>(u) * d_.recip_hi;
    return LatticeCell{static_cast<uint32_t>(x >> 32), static_cast<uint32_t>(x)};
  }

  const LatticeDim& dim() const { return d_; }

 private:
  LatticeDim d_;
};

/// The hot-path form of LatticeLocator::Locate(), for the Cortex-M4: the clamp is QSUB (pos - lo
/// saturated: a true difference above INT32_MAX is above span too, because validation bounds the
/// extent to 2^31 - 1), USAT (max with 0) and one compare (min with span); then
/// UMULL + UMLAL. Bit-identical to Locate() (tests/reference/hot_path_reference_test.cpp).
inline LatticeCell LocateFast(int32_t pos_steps, const LatticeDim& d) {
  uint32_t u = SatUnsigned31(SubSat(pos_steps, d.lo));
  u = u > d.span ? d.span : u;
  const uint64_t x =
      ((static_cast<uint64_t>(u) * d.recip_lo) >> 32) + static_cast<uint64_t>(u) * d.recip_hi;
  return LatticeCell{static_cast<uint32_t>(x >> 32), static_cast<uint32_t>(x)};
}

}  // namespace volcomp
