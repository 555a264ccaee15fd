// GridLookup preparation and the hot-path kernels (the same arithmetic as the reference template
// GridLookup::Interpolate<Loader> in grid_lookup.hpp, arranged for the Cortex-M4: each corner row
// of two neighbouring nodes is read in one go and the three components are accumulated at once).
#include "volcomp/grid_lookup.hpp"

namespace volcomp {
namespace {

// Node i and i + 1 along x are adjacent: 6 elements (x0: c0 c1 c2, x1: c0 c1 c2).
template <class Loader>
struct Row {
  typename Loader::Value v[6];
  explicit Row(const uint8_t* p) {
    // Validated images are 4-byte aligned and so is every element of an int16 row pair's start
    // to its element size (table_format.hpp): tell the compiler, so it may load words/pairs.
    const auto* a = static_cast<const uint8_t*>(__builtin_assume_aligned(p, Loader::kSize));
#pragma GCC unroll 6
    for (uint32_t e = 0; e < 6; ++e) v[e] = Loader::Load(a + e * Loader::kSize);
  }
};

template <class Loader, class Acc, class W>
inline void AccumulateRow(const uint8_t* p, W w0, W w1, Acc& a0, Acc& a1, Acc& a2) {
  const Row<Loader> r(p);
  a0 = Loader::Mac(a0, w0, r.v[0]);
  a1 = Loader::Mac(a1, w0, r.v[1]);
  a2 = Loader::Mac(a2, w0, r.v[2]);
  a0 = Loader::Mac(a0, w1, r.v[3]);
  a1 = Loader::Mac(a1, w1, r.v[4]);
  a2 = Loader::Mac(a2, w1, r.v[5]);
}

}  // namespace

Status GridLookup::Init(const table::Grid3View& grid) {
  if (!grid.present || grid.data == nullptr) return Error::kNotReady;
  type_ = grid.type;
  data_ = grid.data;
  frac_bits_ = grid.frac_bits;
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

// Fixed-point kernels: the order of the products does not matter (int16: each product truncated
// on its own, then exact int32 sums; int32: exact int64 sums), so rows are visited y0z0, y0z1,
// y1z0, y1z1, which lets the z-level weights be formed just before they are used.
void GridLookup::LookupInt16(const int32_t* pos_steps, int32_t out_q8[3]) const {
  const uint32_t shift = 7u + frac_bits_;
  const LatticeCell cx = loc_[0].Locate(pos_steps[axis_[0]]);
  const LatticeCell cy = loc_[1].Locate(pos_steps[axis_[1]]);
  const LatticeCell cz = loc_[2].Locate(pos_steps[axis_[2]]);
  const uint32_t sy = stride_[1], sz = stride_[2];
  const uint8_t* p = data_ + cx.cell * (3u * LoadInt16::kSize) + cy.cell * sy + cz.cell * sz;
  const uint32_t x1 = cx.frac_q32, x0 = ~cx.frac_q32;
  const uint32_t tz31 = cz.frac_q32 >> 1;
  // The rounding term of ToQ8 is the accumulators' start value (same sum, same result).
  const int32_t round = static_cast<int32_t>(1u << (shift - 1u));
  int32_t a0 = round, a1 = round, a2 = round;
#pragma GCC unroll 2
  for (int y = 0; y < 2; ++y) {
    const uint32_t x1y = y ? MulHiU32(x1, cy.frac_q32) : x1 - MulHiU32(x1, cy.frac_q32);
    const uint32_t x0y = y ? MulHiU32(x0, cy.frac_q32) : x0 - MulHiU32(x0, cy.frac_q32);
    const uint32_t h0 = MulHiU32(x0y, tz31), h1 = MulHiU32(x1y, tz31);
    const uint8_t* row = p + (y ? sy : 0u);
    AccumulateRow<LoadInt16>(row, static_cast<int32_t>((x0y >> 1) - h0),
                             static_cast<int32_t>((x1y >> 1) - h1), a0, a1, a2);
    AccumulateRow<LoadInt16>(row + sz, static_cast<int32_t>(h0), static_cast<int32_t>(h1), a0, a1,
                             a2);
  }
  const int32_t r0 = a0 >> shift, r1 = a1 >> shift, r2 = a2 >> shift;
  out_q8[0] = r0;
  out_q8[1] = r1;
  out_q8[2] = r2;
}

void GridLookup::LookupInt32(const int32_t* pos_steps, int32_t out_q8[3]) const {
  const uint32_t shift = 23u + frac_bits_;
  const LatticeCell cx = loc_[0].Locate(pos_steps[axis_[0]]);
  const LatticeCell cy = loc_[1].Locate(pos_steps[axis_[1]]);
  const LatticeCell cz = loc_[2].Locate(pos_steps[axis_[2]]);
  const uint32_t sy = stride_[1], sz = stride_[2];
  const uint8_t* p = data_ + cx.cell * (3u * LoadInt32::kSize) + cy.cell * sy + cz.cell * sz;
  const uint32_t x1 = cx.frac_q32, x0 = ~cx.frac_q32;
  const uint32_t tz31 = cz.frac_q32 >> 1;
  const int64_t round = int64_t{1} << (shift - 1u);
  int64_t a0 = round, a1 = round, a2 = round;
#pragma GCC unroll 2
  for (int y = 0; y < 2; ++y) {
    const uint32_t x1y = y ? MulHiU32(x1, cy.frac_q32) : x1 - MulHiU32(x1, cy.frac_q32);
    const uint32_t x0y = y ? MulHiU32(x0, cy.frac_q32) : x0 - MulHiU32(x0, cy.frac_q32);
    const uint32_t h0 = MulHiU32(x0y, tz31), h1 = MulHiU32(x1y, tz31);
    const uint8_t* row = p + (y ? sy : 0u);
    AccumulateRow<LoadInt32>(row, static_cast<int32_t>((x0y >> 1) - h0),
                             static_cast<int32_t>((x1y >> 1) - h1), a0, a1, a2);
    AccumulateRow<LoadInt32>(row + sz, static_cast<int32_t>(h0), static_cast<int32_t>(h1), a0, a1,
                             a2);
  }
  const int32_t r0 = static_cast<int32_t>(a0 >> shift), r1 = static_cast<int32_t>(a1 >> shift),
                r2 = static_cast<int32_t>(a2 >> shift);
  out_q8[0] = r0;
  out_q8[1] = r1;
  out_q8[2] = r2;
}

// float32: the reference order of the sum (k = 0..7: z0 rows y0, y1, then z1 rows) is kept,
// because float addition is not associative.
void GridLookup::LookupFloat32(const int32_t* pos_steps, int32_t out_q8[3]) const {
  const LatticeCell cx = loc_[0].Locate(pos_steps[axis_[0]]);
  const LatticeCell cy = loc_[1].Locate(pos_steps[axis_[1]]);
  const LatticeCell cz = loc_[2].Locate(pos_steps[axis_[2]]);
  const uint32_t sy = stride_[1], sz = stride_[2];
  const uint8_t* p = data_ + cx.cell * (3u * LoadFloat32::kSize) + cy.cell * sy + cz.cell * sz;
  const TrilinearWeightsF tw(cx.frac_q32, cy.frac_q32, cz.frac_q32);
  float a0 = 0.0f, a1 = 0.0f, a2 = 0.0f;
  AccumulateRow<LoadFloat32>(p, tw.w[0], tw.w[1], a0, a1, a2);
  AccumulateRow<LoadFloat32>(p + sy, tw.w[2], tw.w[3], a0, a1, a2);
  AccumulateRow<LoadFloat32>(p + sz, tw.w[4], tw.w[5], a0, a1, a2);
  AccumulateRow<LoadFloat32>(p + sz + sy, tw.w[6], tw.w[7], a0, a1, a2);
  const int32_t r0 = FloatToQ8(a0), r1 = FloatToQ8(a1), r2 = FloatToQ8(a2);
  out_q8[0] = r0;
  out_q8[1] = r1;
  out_q8[2] = r2;
}

}  // namespace volcomp
