// Reciprocals for CellLocator (runs at table activation, may divide).
#include "volcomp/cell_locator.hpp"

namespace volcomp {

void CellLocator::Init(const table::Dimension& dim) {
  spacing_ = dim.spacing_steps;
  lo_ = dim.origin_steps;
  hi_ = static_cast<int32_t>(static_cast<int64_t>(lo_) +
                             static_cast<int64_t>(dim.nodes - 1u) * spacing_);
  last_cell_ = dim.nodes - 2u;
  index_.Init(spacing_);
  norm_shift_ = 0;
  while ((static_cast<uint64_t>(spacing_) << norm_shift_) <= (1ull << 30)) ++norm_shift_;
  recip_frac_ =
      static_cast<uint32_t>((1ull << 62) / (static_cast<uint64_t>(spacing_) << norm_shift_));
}

void LatticeLocator::Init(const table::Dimension& dim) {
  d_.lo = dim.origin_steps;
  d_.span = static_cast<uint32_t>(static_cast<uint64_t>(dim.nodes - 1u) * dim.spacing_steps);
  const uint64_t recip = ~uint64_t{0} / dim.spacing_steps;
  d_.recip_lo = static_cast<uint32_t>(recip);
  d_.recip_hi = static_cast<uint32_t>(recip >> 32);
}

}  // namespace volcomp
