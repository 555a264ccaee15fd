// GridLookup preparation.
#include "volcomp/grid_lookup.hpp"

namespace volcomp {

Status GridLookup::Init(const table::Grid3View& grid) {
  if (!grid.present || grid.data == nullptr) return Error::kNotReady;
  type_ = grid.type;
  data_ = grid.data;
  shift_ = 30u + grid.frac_bits - table::kCorrectionFracBits;
  const uint32_t node_bytes = 3u * table::ElementSize(grid.type);
  stride_[0] = node_bytes;
  stride_[1] = node_bytes * grid.dim[0].nodes;
  stride_[2] = stride_[1] * grid.dim[1].nodes;
  for (int d = 0; d < 3; ++d) {
    axis_[d] = grid.axis[d];
    loc_[d].Init(grid.dim[d]);
  }
  return Status::Ok();
}

}  // namespace volcomp
