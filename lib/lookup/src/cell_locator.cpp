// The lattice reciprocal (runs at table activation, may divide).
#include "volcomp/lookup/cell_locator.hpp"

namespace volcomp {

void LatticeLocator::Init(const table::Dimension& dim) {
  d_.lo = dim.origin_steps;
  d_.span = static_cast<uint32_t>(static_cast<uint64_t>(dim.nodes - 1u) * dim.spacing_steps);
  const uint64_t recip = ~uint64_t{0} / dim.spacing_steps;
  d_.recip_lo = static_cast<uint32_t>(recip);
  d_.recip_hi = static_cast<uint32_t>(recip >> 32);
}

}  // namespace volcomp
