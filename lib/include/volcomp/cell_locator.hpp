// Position (steps) -> lattice cell and fraction, with no division on the lookup path.
//
// A lattice dimension has nodes at origin + i*spacing, i = 0..nodes-1. Locate() clamps the
// position to [origin, origin + (nodes-1)*spacing], finds the cell i in [0, nodes-2] and the
// fraction t = (pos - node_i) / spacing in [0, 1] as Q2.30 (1.0 = 2^30), exactly up to
// |t_q30 - t*2^30| < 2. Division is replaced by two precomputed reciprocals (Init() divides, once,
// at table activation): an InvariantDivider for the index and a normalised 32-bit reciprocal for
// the fraction (spacing scaled into (2^30, 2^31] so the reciprocal keeps 32 significant bits).
#pragma once

#include <cstdint>

#include "volcomp/invariant_divider.hpp"
#include "volcomp/table_image.hpp"

namespace volcomp {

struct CellPosition {
  uint32_t cell = 0;   // 0..nodes-2
  uint32_t t_q30 = 0;  // 0..2^30
};

class CellLocator {
 public:
  static constexpr uint32_t kOneQ30 = 1u << 30;

  /// Precomputes the reciprocals. `dim` must have passed table validation (nodes >= 2,
  /// spacing >= 1, extent within int32).
  void Init(const table::Dimension& dim);

  /// ISR-safe, constant time, no division.
  CellPosition Locate(int32_t pos_steps) const {
    int32_t p = pos_steps < lo_ ? lo_ : pos_steps;
    p = p > hi_ ? hi_ : p;
    const uint32_t u = static_cast<uint32_t>(p) - static_cast<uint32_t>(lo_);
    const QuotientRemainder qr = index_.Divide(u);
    uint32_t q = qr.quotient, r = qr.remainder;
    const uint32_t top = 0u - static_cast<uint32_t>(q > last_cell_);  // pos at the last node
    q += top;
    r += spacing_ & top;
    const uint32_t t =
        static_cast<uint32_t>((static_cast<uint64_t>(r << norm_shift_) * recip_frac_) >> 32);
    return CellPosition{q, t};
  }

 private:
  int32_t lo_ = 0;
  int32_t hi_ = 0;
  uint32_t spacing_ = 1;
  uint32_t last_cell_ = 0;
  InvariantDivider index_;   // u / spacing
  uint32_t recip_frac_ = 0;  // floor(2^62 / (spacing << norm_shift))
  uint32_t norm_shift_ = 0;  // spacing << norm_shift in (2^30, 2^31]
};

}  // namespace volcomp
