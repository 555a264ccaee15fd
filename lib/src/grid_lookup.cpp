// GridLookup preparation and the hot-path kernels: the same arithmetic as the reference template
// GridLookup::Interpolate<Loader> in grid_lookup.hpp, arranged for the Cortex-M4:
//   * the cell and fraction of each dimension come from LocateFast() (QSUB/USAT clamp, UMULL +
//     UMLAL) with the constants of a dimension read together;
//   * the weights are formed per (y, z) row pair right before they are used, so no more than two
//     x weights and the three accumulators are live at a time (no spills);
//   * a corner row (two neighbouring x nodes, 3 components each) is contiguous: int16 rows are
//     read as three 32-bit words (halfword aligned: LDR allows that on the M4) and each element
//     is taken as the bottom or top half by SMLAWB/SMLAWT, so no element is loaded on its own.
#include "volcomp/grid_lookup.hpp"

// GCC's pre-register-allocation scheduler hoists the loads of later rows and then spills; the
// kernels are written in the order that keeps register pressure low, so keep that order.
#if defined(__GNUC__) && !defined(__clang__)
#define VOLCOMP_KERNEL __attribute__((optimize("no-schedule-insns")))
#else
#define VOLCOMP_KERNEL
#endif

namespace volcomp {
namespace {

// int16 row at p: words w0 = {x0c0, x0c1}, w1 = {x0c2, x1c0}, w2 = {x1c1, x1c2} (bottom, top).
inline void RowInt16(
    const uint8_t* p, int32_t wx0, int32_t wx1, int32_t& a0, int32_t& a1, int32_t& a2) {
  const int32_t w0 = LoadWordUnaligned(p), w1 = LoadWordUnaligned(p + 4),
                w2 = LoadWordUnaligned(p + 8);
  a0 = MulAddWordHalf(a0, wx0, w0);
  a1 = MulAddWordTop(a1, wx0, w0);
  a2 = MulAddWordHalf(a2, wx0, w1);
  a0 = MulAddWordTop(a0, wx1, w1);
  a1 = MulAddWordHalf(a1, wx1, w2);
  a2 = MulAddWordTop(a2, wx1, w2);
}

inline int32_t LoadI32(const uint8_t* p) {
  int32_t v;
  __builtin_memcpy(&v, __builtin_assume_aligned(p, 4), sizeof v);
  return v;
}

// int32 row: 6 words; exact 64-bit sums (SMLAL).
inline void RowInt32(
    const uint8_t* p, int32_t wx0, int32_t wx1, int64_t& a0, int64_t& a1, int64_t& a2) {
  a0 = MulAddLong(a0, wx0, LoadI32(p));
  a1 = MulAddLong(a1, wx0, LoadI32(p + 4));
  a2 = MulAddLong(a2, wx0, LoadI32(p + 8));
  a0 = MulAddLong(a0, wx1, LoadI32(p + 12));
  a1 = MulAddLong(a1, wx1, LoadI32(p + 16));
  a2 = MulAddLong(a2, wx1, LoadI32(p + 20));
}

// Low word of a >> s for 0 < s < 32 (no test for s >= 32 as a general 64-bit shift needs).
inline int32_t Shr64Low(int64_t a, uint32_t s) {
  const uint32_t lo = static_cast<uint32_t>(a), hi = static_cast<uint32_t>(a >> 32);
  return static_cast<int32_t>((lo >> s) | (hi << (32u - s)));
}

inline float LoadF32(const uint8_t* p) {
  float v;
  __builtin_memcpy(&v, __builtin_assume_aligned(p, 4), sizeof v);
  return v;
}

// float32 row: the reference's order within a row (x0 then x1 for each component).
inline void RowF32(const uint8_t* p, float wx0, float wx1, float& a0, float& a1, float& a2) {
  a0 = a0 + wx0 * LoadF32(p);
  a1 = a1 + wx0 * LoadF32(p + 4);
  a2 = a2 + wx0 * LoadF32(p + 8);
  a0 = a0 + wx1 * LoadF32(p + 12);
  a1 = a1 + wx1 * LoadF32(p + 16);
  a2 = a2 + wx1 * LoadF32(p + 20);
}

inline float Q32ToFloat(uint32_t t) { return static_cast<float>(t) * (1.0f / 4294967296.0f); }

inline float BitsToFloat(uint32_t b) {
  float f;
  __builtin_memcpy(&f, &b, sizeof f);
  return f;
}
inline uint32_t FloatToBits(float f) {
  uint32_t b;
  __builtin_memcpy(&b, &f, sizeof b);
  return b;
}

// FloatToQ8() of the reference (interp_arith.hpp), written out so the three share one 256.
inline void FloatsToQ8(float a0, float a1, float a2, int32_t out_q8[3]) {
  const float q8 = 256.0f;
  a0 = a0 * q8;
  a1 = a1 * q8;
  a2 = a2 * q8;
  out_q8[0] = static_cast<int32_t>(a0 < 0.0f ? a0 - 0.5f : a0 + 0.5f);
  out_q8[1] = static_cast<int32_t>(a1 < 0.0f ? a1 - 0.5f : a1 + 0.5f);
  out_q8[2] = static_cast<int32_t>(a2 < 0.0f ? a2 - 0.5f : a2 + 0.5f);
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
  node_bytes_ = node_bytes;
  stride_y_ = stride_[1];
  stride_z_ = stride_[2];
  shift_ = (grid.type == table::ElementType::kInt32 ? 23u : 7u) + grid.frac_bits;
  round_ = static_cast<int32_t>(1u << (shift_ - 1u));
  for (int d = 0; d < 3; ++d) {
    axis_[d] = grid.axis[d];
    loc_[d].Init(grid.dim[d]);
    dim_[d].axis = grid.axis[d];
    dim_[d].lattice = loc_[d].dim();
  }
  return Status::Ok();
}

// Fixed-point kernels: the order of the products does not matter (int16: each product truncated
// on its own, then exact int32 sums; int32: exact int64 sums), so rows are visited y0z0, y0z1,
// y1z0, y1z1, which lets the z-level weights be formed just before they are used.
VOLCOMP_KERNEL void GridLookup::LookupInt16(const int32_t* pos_steps, int32_t out_q8[3]) const {
  const LatticeCell cx = LocateFast(pos_steps[dim_[0].axis], dim_[0].lattice);
  const LatticeCell cy = LocateFast(pos_steps[dim_[1].axis], dim_[1].lattice);
  const LatticeCell cz = LocateFast(pos_steps[dim_[2].axis], dim_[2].lattice);
  const uint8_t* p = data_ + cx.cell * 6u + cy.cell * stride_y_ + cz.cell * stride_z_;
  const uint32_t x1 = cx.frac_q32, x0 = ~cx.frac_q32;
  const uint32_t x0y1 = MulHiU32(x0, cy.frac_q32), x1y1 = MulHiU32(x1, cy.frac_q32);
  const uint32_t x0y0 = x0 - x0y1, x1y0 = x1 - x1y1;
  const uint32_t tz31 = cz.frac_q32 >> 1;
  int32_t a0 = round_, a1 = round_, a2 = round_;
  uint32_t h0 = MulHiU32(x0y0, tz31), h1 = MulHiU32(x1y0, tz31);
  RowInt16(p, static_cast<int32_t>((x0y0 >> 1) - h0), static_cast<int32_t>((x1y0 >> 1) - h1), a0,
           a1, a2);
  RowInt16(p + stride_z_, static_cast<int32_t>(h0), static_cast<int32_t>(h1), a0, a1, a2);
  p += stride_y_;
  h0 = MulHiU32(x0y1, tz31);
  h1 = MulHiU32(x1y1, tz31);
  RowInt16(p, static_cast<int32_t>((x0y1 >> 1) - h0), static_cast<int32_t>((x1y1 >> 1) - h1), a0,
           a1, a2);
  RowInt16(p + stride_z_, static_cast<int32_t>(h0), static_cast<int32_t>(h1), a0, a1, a2);
  const uint32_t shift = shift_;
  out_q8[0] = a0 >> shift;
  out_q8[1] = a1 >> shift;
  out_q8[2] = a2 >> shift;
}

VOLCOMP_KERNEL void GridLookup::LookupInt32(const int32_t* pos_steps, int32_t out_q8[3]) const {
  const LatticeCell cx = LocateFast(pos_steps[dim_[0].axis], dim_[0].lattice);
  const LatticeCell cy = LocateFast(pos_steps[dim_[1].axis], dim_[1].lattice);
  const LatticeCell cz = LocateFast(pos_steps[dim_[2].axis], dim_[2].lattice);
  const uint8_t* p = data_ + cx.cell * 12u + cy.cell * stride_y_ + cz.cell * stride_z_;
  const uint32_t x1 = cx.frac_q32, x0 = ~cx.frac_q32;
  const uint32_t x0y1 = MulHiU32(x0, cy.frac_q32), x1y1 = MulHiU32(x1, cy.frac_q32);
  const uint32_t x0y0 = x0 - x0y1, x1y0 = x1 - x1y1;
  const uint32_t tz31 = cz.frac_q32 >> 1;
  const int64_t round = round_;
  int64_t a0 = round, a1 = round, a2 = round;
  uint32_t h0 = MulHiU32(x0y0, tz31), h1 = MulHiU32(x1y0, tz31);
  RowInt32(p, static_cast<int32_t>((x0y0 >> 1) - h0), static_cast<int32_t>((x1y0 >> 1) - h1), a0,
           a1, a2);
  RowInt32(p + stride_z_, static_cast<int32_t>(h0), static_cast<int32_t>(h1), a0, a1, a2);
  p += stride_y_;
  h0 = MulHiU32(x0y1, tz31);
  h1 = MulHiU32(x1y1, tz31);
  RowInt32(p, static_cast<int32_t>((x0y1 >> 1) - h0), static_cast<int32_t>((x1y1 >> 1) - h1), a0,
           a1, a2);
  RowInt32(p + stride_z_, static_cast<int32_t>(h0), static_cast<int32_t>(h1), a0, a1, a2);
  const uint32_t shift = shift_;  // 23..31
  out_q8[0] = Shr64Low(a0, shift);
  out_q8[1] = Shr64Low(a1, shift);
  out_q8[2] = Shr64Low(a2, shift);
}

// float32: the reference order of the sum (k = 0..7: z0 rows y0, y1, then z1 rows) is kept,
// because float addition is not associative. The reference starts from 0.0f; starting from the
// first product instead differs only in the sign of a zero sum, which gives the same Q8 value.
VOLCOMP_KERNEL void GridLookup::LookupFloat32(const int32_t* pos_steps, int32_t out_q8[3]) const {
  const LatticeCell cx = LocateFast(pos_steps[dim_[0].axis], dim_[0].lattice);
  const LatticeCell cy = LocateFast(pos_steps[dim_[1].axis], dim_[1].lattice);
  const LatticeCell cz = LocateFast(pos_steps[dim_[2].axis], dim_[2].lattice);
  const uint32_t sy = stride_y_, sz = stride_z_;
  const uint8_t* p = data_ + cx.cell * 12u + cy.cell * sy + cz.cell * sz;
  const TrilinearWeightsF tw(cx.frac_q32, cy.frac_q32, cz.frac_q32);
  float a0 = tw.w[0] * LoadF32(p), a1 = tw.w[0] * LoadF32(p + 4), a2 = tw.w[0] * LoadF32(p + 8);
  a0 = a0 + tw.w[1] * LoadF32(p + 12);
  a1 = a1 + tw.w[1] * LoadF32(p + 16);
  a2 = a2 + tw.w[1] * LoadF32(p + 20);
  const uint8_t* rows[3] = {p + sy, p + sz, p + sz + sy};
#pragma GCC unroll 3
  for (int r = 0; r < 3; ++r) {
    const float w0 = tw.w[2 * r + 2], w1 = tw.w[2 * r + 3];
    a0 = a0 + w0 * LoadF32(rows[r]);
    a1 = a1 + w0 * LoadF32(rows[r] + 4);
    a2 = a2 + w0 * LoadF32(rows[r] + 8);
    a0 = a0 + w1 * LoadF32(rows[r] + 12);
    a1 = a1 + w1 * LoadF32(rows[r] + 16);
    a2 = a2 + w1 * LoadF32(rows[r] + 20);
  }
  FloatsToQ8(a0, a1, a2, out_q8);
}

// ---- The lookup in three parts (the control tick spreads it over ticks) ------------------------

VOLCOMP_KERNEL void GridLookup::Begin(const int32_t* pos_steps, Partial* s) const {
  const LatticeCell cx = LocateFast(pos_steps[dim_[0].axis], dim_[0].lattice);
  const LatticeCell cy = LocateFast(pos_steps[dim_[1].axis], dim_[1].lattice);
  const LatticeCell cz = LocateFast(pos_steps[dim_[2].axis], dim_[2].lattice);
  s->corner = data_ + cx.cell * node_bytes_ + cy.cell * stride_y_ + cz.cell * stride_z_;
  if (type_ == table::ElementType::kFloat32) {
    // TrilinearWeightsF's x and y levels.
    const float x1 = Q32ToFloat(cx.frac_q32), x0 = 1.0f - x1, ty = Q32ToFloat(cy.frac_q32);
    const float x1y1 = x1 * ty, x0y1 = x0 * ty;
    s->xy[0] = FloatToBits(x0 - x0y1);
    s->xy[1] = FloatToBits(x1 - x1y1);
    s->xy[2] = FloatToBits(x0y1);
    s->xy[3] = FloatToBits(x1y1);
    s->tz = FloatToBits(Q32ToFloat(cz.frac_q32));
  } else {
    const uint32_t x1 = cx.frac_q32, x0 = ~cx.frac_q32;
    const uint32_t x0y1 = MulHiU32(x0, cy.frac_q32), x1y1 = MulHiU32(x1, cy.frac_q32);
    s->xy[0] = x0 - x0y1;
    s->xy[1] = x1 - x1y1;
    s->xy[2] = x0y1;
    s->xy[3] = x1y1;
    s->tz = cz.frac_q32 >> 1;
  }
}

VOLCOMP_KERNEL void GridLookup::AccumulateZ0(Partial* s) const {
  const uint8_t* p = s->corner;
  const uint32_t sy = stride_y_;
  switch (type_) {
    case table::ElementType::kInt16: {
      const uint32_t tz = s->tz;
      int32_t a0 = round_, a1 = round_, a2 = round_;
#pragma GCC unroll 2
      for (uint32_t y = 0; y < 2; ++y) {
        const uint32_t x0y = s->xy[2 * y], x1y = s->xy[2 * y + 1];
        RowInt16(p + (y ? sy : 0u), static_cast<int32_t>((x0y >> 1) - MulHiU32(x0y, tz)),
                 static_cast<int32_t>((x1y >> 1) - MulHiU32(x1y, tz)), a0, a1, a2);
      }
      s->acc[0] = static_cast<uint32_t>(a0);
      s->acc[1] = static_cast<uint32_t>(a1);
      s->acc[2] = static_cast<uint32_t>(a2);
      break;
    }
    case table::ElementType::kInt32: {
      const uint32_t tz = s->tz;
      int64_t a0 = round_, a1 = round_, a2 = round_;
#pragma GCC unroll 2
      for (uint32_t y = 0; y < 2; ++y) {
        const uint32_t x0y = s->xy[2 * y], x1y = s->xy[2 * y + 1];
        RowInt32(p + (y ? sy : 0u), static_cast<int32_t>((x0y >> 1) - MulHiU32(x0y, tz)),
                 static_cast<int32_t>((x1y >> 1) - MulHiU32(x1y, tz)), a0, a1, a2);
      }
      __builtin_memcpy(&s->acc[0], &a0, sizeof a0);
      __builtin_memcpy(&s->acc[2], &a1, sizeof a1);
      __builtin_memcpy(&s->acc[4], &a2, sizeof a2);
      break;
    }
    case table::ElementType::kFloat32: {
      const float tz = BitsToFloat(s->tz);
      float xy = BitsToFloat(s->xy[0]);
      float w0 = xy - xy * tz;
      xy = BitsToFloat(s->xy[1]);
      float w1 = xy - xy * tz;
      // The first product starts the sum (see LookupFloat32).
      float a0 = w0 * LoadF32(p), a1 = w0 * LoadF32(p + 4), a2 = w0 * LoadF32(p + 8);
      a0 = a0 + w1 * LoadF32(p + 12);
      a1 = a1 + w1 * LoadF32(p + 16);
      a2 = a2 + w1 * LoadF32(p + 20);
      xy = BitsToFloat(s->xy[2]);
      w0 = xy - xy * tz;
      xy = BitsToFloat(s->xy[3]);
      w1 = xy - xy * tz;
      RowF32(p + sy, w0, w1, a0, a1, a2);
      s->acc[0] = FloatToBits(a0);
      s->acc[1] = FloatToBits(a1);
      s->acc[2] = FloatToBits(a2);
      break;
    }
  }
}

VOLCOMP_KERNEL void GridLookup::FinishZ1(const Partial& s, int32_t out_q8[3]) const {
  const uint8_t* p = s.corner + stride_z_;
  const uint32_t sy = stride_y_;
  switch (type_) {
    case table::ElementType::kInt16: {
      const uint32_t tz = s.tz;
      int32_t a0 = static_cast<int32_t>(s.acc[0]), a1 = static_cast<int32_t>(s.acc[1]),
              a2 = static_cast<int32_t>(s.acc[2]);
#pragma GCC unroll 2
      for (uint32_t y = 0; y < 2; ++y) {
        RowInt16(p + (y ? sy : 0u), static_cast<int32_t>(MulHiU32(s.xy[2 * y], tz)),
                 static_cast<int32_t>(MulHiU32(s.xy[2 * y + 1], tz)), a0, a1, a2);
      }
      const uint32_t shift = shift_;
      out_q8[0] = a0 >> shift;
      out_q8[1] = a1 >> shift;
      out_q8[2] = a2 >> shift;
      break;
    }
    case table::ElementType::kInt32: {
      const uint32_t tz = s.tz;
      int64_t a0, a1, a2;
      __builtin_memcpy(&a0, &s.acc[0], sizeof a0);
      __builtin_memcpy(&a1, &s.acc[2], sizeof a1);
      __builtin_memcpy(&a2, &s.acc[4], sizeof a2);
#pragma GCC unroll 2
      for (uint32_t y = 0; y < 2; ++y) {
        RowInt32(p + (y ? sy : 0u), static_cast<int32_t>(MulHiU32(s.xy[2 * y], tz)),
                 static_cast<int32_t>(MulHiU32(s.xy[2 * y + 1], tz)), a0, a1, a2);
      }
      const uint32_t shift = shift_;
      out_q8[0] = Shr64Low(a0, shift);
      out_q8[1] = Shr64Low(a1, shift);
      out_q8[2] = Shr64Low(a2, shift);
      break;
    }
    case table::ElementType::kFloat32: {
      const float tz = BitsToFloat(s.tz);
      float a0 = BitsToFloat(s.acc[0]), a1 = BitsToFloat(s.acc[1]), a2 = BitsToFloat(s.acc[2]);
      RowF32(p, BitsToFloat(s.xy[0]) * tz, BitsToFloat(s.xy[1]) * tz, a0, a1, a2);
      RowF32(p + sy, BitsToFloat(s.xy[2]) * tz, BitsToFloat(s.xy[3]) * tz, a0, a1, a2);
      FloatsToQ8(a0, a1, a2, out_q8);
      break;
    }
  }
}

}  // namespace volcomp
