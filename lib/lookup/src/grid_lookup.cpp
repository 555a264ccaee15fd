// GridLookup preparation and the kernels: the same arithmetic as the reference template
// GridLookup::Interpolate<Loader> in grid_lookup.hpp, arranged for the Cortex-M4, written once as
// the parts Begin / AccumulateZ0 / FinishZ1 over an element kernel (Int16, Int32, Float32 below);
// the whole Lookup() is the same parts run back to back:
//   * the cell and fraction of each dimension come from LocateFast() (QSUB/USAT clamp, UMULL +
//     UMLAL) with the constants of a dimension read together;
//   * the z-level weights are formed per row right before they are used, so no more than two
//     x weights and the three accumulators are live at a time (no spills);
//   * a corner row (two neighbouring x nodes, 3 components each) is contiguous: int16 rows are
//     read as three 32-bit words (halfword aligned: LDR allows that on the M4) and each element
//     is taken as the bottom or top half by SMLAWB/SMLAWT, so no element is loaded on its own.
#include "volcomp/lookup/grid_lookup.hpp"

#include <cstddef>

// GCC's pre-register-allocation scheduler hoists the loads of later rows and then spills; the
// kernels are written in the order that keeps register pressure low, so keep that order (for the
// whole file: the kernels are templates whose pieces are inlined from the element kernels).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("no-schedule-insns")
#endif
#define VOLCOMP_KERNEL

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

// ---- Element kernels ---------------------------------------------------------------------------
// What differs between element types: the y-level weights Begin() keeps (Q0.32, or float bits),
// the z-level weights of a row, how a row of two nodes is accumulated (RowInt16 / RowInt32 /
// RowF32), how the first row starts the sums, where the sums wait between the parts (Partial::acc)
// and how they become Q8. The kernels in GridLookup are templates over these.
namespace grid_kernel {

// The fixed-point levels and z weights (interp_arith.hpp), the same for int16 and int32 tables.
struct FixedPointLevels {
  using W = int32_t;                          // Q1.31 weight
  using L = uint32_t;                         // x-y levels Q0.32, tz Q1.31
  static constexpr bool kAnyRowOrder = true;  // exact sums (see the kernels)
  static L FromBits(uint32_t b) { return b; }
  static uint32_t ToBits(L v) { return v; }
  static void Levels(
      const LatticeCell& cx, const LatticeCell& cy, const LatticeCell& cz, L xy[4], L* tz) {
    const uint32_t x1 = cx.frac_q32, x0 = ~cx.frac_q32;
    const uint32_t x0y1 = MulHiU32(x0, cy.frac_q32), x1y1 = MulHiU32(x1, cy.frac_q32);
    xy[0] = x0 - x0y1;
    xy[1] = x1 - x1y1;
    xy[2] = x0y1;
    xy[3] = x1y1;
    *tz = cz.frac_q32 >> 1;
  }
  static W Lower(L xy, L tz) { return static_cast<int32_t>((xy >> 1) - MulHiU32(xy, tz)); }
  static W Upper(L xy, L tz) { return static_cast<int32_t>(MulHiU32(xy, tz)); }
};

struct Int16 : FixedPointLevels {
  using Acc = int32_t;
  static constexpr uint32_t kNodeBytes = 6;
  static void Row(const uint8_t* p, W w0, W w1, Acc& a0, Acc& a1, Acc& a2) {
    RowInt16(p, w0, w1, a0, a1, a2);
  }
  static void FirstRow(const uint8_t* p, W w0, W w1, int32_t round, Acc& a0, Acc& a1, Acc& a2) {
    a0 = a1 = a2 = round;
    Row(p, w0, w1, a0, a1, a2);
  }
  static void Save(Acc a0, Acc a1, Acc a2, uint32_t acc[6]) {
    acc[0] = static_cast<uint32_t>(a0);
    acc[1] = static_cast<uint32_t>(a1);
    acc[2] = static_cast<uint32_t>(a2);
  }
  static void Restore(const uint32_t acc[6], Acc& a0, Acc& a1, Acc& a2) {
    a0 = static_cast<int32_t>(acc[0]);
    a1 = static_cast<int32_t>(acc[1]);
    a2 = static_cast<int32_t>(acc[2]);
  }
  static void ToQ8(Acc a0, Acc a1, Acc a2, uint32_t shift, int32_t out_q8[3]) {
    out_q8[0] = a0 >> shift;
    out_q8[1] = a1 >> shift;
    out_q8[2] = a2 >> shift;
  }
};

struct Int32 : FixedPointLevels {
  using Acc = int64_t;
  static constexpr uint32_t kNodeBytes = 12;
  static void Row(const uint8_t* p, W w0, W w1, Acc& a0, Acc& a1, Acc& a2) {
    RowInt32(p, w0, w1, a0, a1, a2);
  }
  static void FirstRow(const uint8_t* p, W w0, W w1, int32_t round, Acc& a0, Acc& a1, Acc& a2) {
    a0 = a1 = a2 = round;
    Row(p, w0, w1, a0, a1, a2);
  }
  static void Save(Acc a0, Acc a1, Acc a2, uint32_t acc[6]) {
    __builtin_memcpy(&acc[0], &a0, sizeof a0);
    __builtin_memcpy(&acc[2], &a1, sizeof a1);
    __builtin_memcpy(&acc[4], &a2, sizeof a2);
  }
  static void Restore(const uint32_t acc[6], Acc& a0, Acc& a1, Acc& a2) {
    __builtin_memcpy(&a0, &acc[0], sizeof a0);
    __builtin_memcpy(&a1, &acc[2], sizeof a1);
    __builtin_memcpy(&a2, &acc[4], sizeof a2);
  }
  static void ToQ8(Acc a0, Acc a1, Acc a2, uint32_t shift, int32_t out_q8[3]) {
    out_q8[0] = Shr64Low(a0, shift);  // shift is 23..31
    out_q8[1] = Shr64Low(a1, shift);
    out_q8[2] = Shr64Low(a2, shift);
  }
};

// float32: the reference order of the sum (k = 0..7: z0 rows y0, y1, then z1 rows) is kept,
// because float addition is not associative. The reference starts from 0.0f; starting from the
// first product instead differs only in the sign of a zero sum, which gives the same Q8 value.
struct Float32 {
  using Acc = float;
  using W = float;
  using L = float;  // TrilinearWeightsF's x-y levels and tz (kept as float bits in a Partial)
  static constexpr uint32_t kNodeBytes = 12;
  static constexpr bool kAnyRowOrder = false;  // float addition is not associative
  static L FromBits(uint32_t b) { return BitsToFloat(b); }
  static uint32_t ToBits(L v) { return FloatToBits(v); }
  static void Levels(
      const LatticeCell& cx, const LatticeCell& cy, const LatticeCell& cz, L xy[4], L* tz) {
    const float x1 = Q32ToFloat(cx.frac_q32), x0 = 1.0f - x1, ty = Q32ToFloat(cy.frac_q32);
    const float x1y1 = x1 * ty, x0y1 = x0 * ty;
    xy[0] = x0 - x0y1;
    xy[1] = x1 - x1y1;
    xy[2] = x0y1;
    xy[3] = x1y1;
    *tz = Q32ToFloat(cz.frac_q32);
  }
  static W Lower(L xy, L tz) { return xy - xy * tz; }
  static W Upper(L xy, L tz) { return xy * tz; }
  static void FirstRow(const uint8_t* p, W w0, W w1, int32_t, Acc& a0, Acc& a1, Acc& a2) {
    a0 = w0 * LoadF32(p);
    a1 = w0 * LoadF32(p + 4);
    a2 = w0 * LoadF32(p + 8);
    a0 = a0 + w1 * LoadF32(p + 12);
    a1 = a1 + w1 * LoadF32(p + 16);
    a2 = a2 + w1 * LoadF32(p + 20);
  }
  static void Row(const uint8_t* p, W w0, W w1, Acc& a0, Acc& a1, Acc& a2) {
    RowF32(p, w0, w1, a0, a1, a2);
  }
  static void Save(Acc a0, Acc a1, Acc a2, uint32_t acc[6]) {
    acc[0] = FloatToBits(a0);
    acc[1] = FloatToBits(a1);
    acc[2] = FloatToBits(a2);
  }
  static void Restore(const uint32_t acc[6], Acc& a0, Acc& a1, Acc& a2) {
    a0 = BitsToFloat(acc[0]);
    a1 = BitsToFloat(acc[1]);
    a2 = BitsToFloat(acc[2]);
  }
  static void ToQ8(Acc a0, Acc a1, Acc a2, uint32_t, int32_t out_q8[3]) {
    FloatsToQ8(a0, a1, a2, out_q8);
  }
};

}  // namespace grid_kernel

namespace {

// A Partial's levels, read from their bits where they are used.
template <class K>
struct LevelBits {
  const uint32_t* bits;
  typename K::L operator[](int i) const { return K::FromBits(bits[i]); }
};

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
  // The offsets grid_lookup_cm4.cpp reads (per dimension: axis, lo, span, recip_lo, recip_hi).
  static_assert(
      sizeof(void*) != 4 ||
          (sizeof(Dim) == 20 && offsetof(GridLookup, data_) == 60 &&
           offsetof(GridLookup, stride_y_) == 64 && offsetof(GridLookup, stride_z_) == 68 &&
           offsetof(GridLookup, round_) == 72 && offsetof(GridLookup, shift_) == 76),
      "Cortex-M4 kernel offsets");
  for (int d = 0; d < 3; ++d) {
    axis_[d] = grid.axis[d];
    loc_[d].Init(grid.dim[d]);
    dim_[d].axis = grid.axis[d];
    dim_[d].lattice = loc_[d].dim();
  }
  return Status::Ok();
}

// ---- The kernels ------------------------------------------------------------------------------
// Fixed point: the order of the products does not matter (int16: each product truncated on its
// own, then exact int32 sums; int32: exact int64 sums); float32 keeps the reference's order, which
// is this one (z0 rows, then z1 rows).

// The cell's first corner and the fractions of `pos_steps` (LocateFast per dimension, the
// constants of a dimension read together), for nodes of `node_bytes`.
inline const uint8_t* GridLookup::Locate(const int32_t* pos_steps,
                                         uint32_t node_bytes,
                                         LatticeCell cell[3]) const {
  cell[0] = LocateFast(pos_steps[dim_[0].axis], dim_[0].lattice);
  cell[1] = LocateFast(pos_steps[dim_[1].axis], dim_[1].lattice);
  cell[2] = LocateFast(pos_steps[dim_[2].axis], dim_[2].lattice);
  return data_ + cell[0].cell * node_bytes + cell[1].cell * stride_y_ + cell[2].cell * stride_z_;
}

// The lower z level's two rows (the first one starts the sums), and the upper level's two.
template <class K, class Levels, class L, class Acc>
inline void GridLookup::SumLower(
    const uint8_t* p, const Levels& xy, L tz, Acc& a0, Acc& a1, Acc& a2) const {
  K::FirstRow(p, K::Lower(xy[0], tz), K::Lower(xy[1], tz), round_, a0, a1, a2);
  K::Row(p + stride_y_, K::Lower(xy[2], tz), K::Lower(xy[3], tz), a0, a1, a2);
}

template <class K, class Levels, class L, class Acc>
inline void GridLookup::SumUpper(
    const uint8_t* p, const Levels& xy, L tz, Acc& a0, Acc& a1, Acc& a2) const {
  p += stride_z_;
  K::Row(p, K::Upper(xy[0], tz), K::Upper(xy[1], tz), a0, a1, a2);
  K::Row(p + stride_y_, K::Upper(xy[2], tz), K::Upper(xy[3], tz), a0, a1, a2);
}

// The parts back to back. Fixed point visits the rows y0z0, y0z1, y1z0, y1z1 instead (any order
// gives the same sums): a row pair's two z weights then come from one product, formed right before
// use, and fewer values are live.
template <class K>
VOLCOMP_KERNEL void GridLookup::LookupAs(const int32_t* pos_steps, int32_t out_q8[3]) const {
  LatticeCell c[3];
  const uint8_t* p = Locate(pos_steps, K::kNodeBytes, c);
  typename K::L xy[4], tz;
  K::Levels(c[0], c[1], c[2], xy, &tz);
  typename K::Acc a0, a1, a2;
  if (K::kAnyRowOrder) {
    K::FirstRow(p, K::Lower(xy[0], tz), K::Lower(xy[1], tz), round_, a0, a1, a2);
    K::Row(p + stride_z_, K::Upper(xy[0], tz), K::Upper(xy[1], tz), a0, a1, a2);
    p += stride_y_;
    K::Row(p, K::Lower(xy[2], tz), K::Lower(xy[3], tz), a0, a1, a2);
    K::Row(p + stride_z_, K::Upper(xy[2], tz), K::Upper(xy[3], tz), a0, a1, a2);
  } else {
    // The reference's order; the eight weights first (independent, so no result waits between
    // them and the products).
    const typename K::W w0 = K::Lower(xy[0], tz), w1 = K::Lower(xy[1], tz),
                        w2 = K::Lower(xy[2], tz), w3 = K::Lower(xy[3], tz),
                        w4 = K::Upper(xy[0], tz), w5 = K::Upper(xy[1], tz),
                        w6 = K::Upper(xy[2], tz), w7 = K::Upper(xy[3], tz);
    K::FirstRow(p, w0, w1, round_, a0, a1, a2);
    K::Row(p + stride_y_, w2, w3, a0, a1, a2);
    p += stride_z_;
    K::Row(p, w4, w5, a0, a1, a2);
    K::Row(p + stride_y_, w6, w7, a0, a1, a2);
  }
  K::ToQ8(a0, a1, a2, shift_, out_q8);
}

template void GridLookup::LookupAs<grid_kernel::Int32>(const int32_t*, int32_t*) const;
#if !VOLCOMP_GRID_LOOKUP_CM4  // else hand-scheduled (grid_lookup_cm4.cpp)
template void GridLookup::LookupAs<grid_kernel::Int16>(const int32_t*, int32_t*) const;
template void GridLookup::LookupAs<grid_kernel::Float32>(const int32_t*, int32_t*) const;
#endif

// ---- The lookup in three parts (the compensator spreads it over its runs) ----------------------
// An if-chain on the element type, not a switch (a jump table would be an indirect jump, which the
// static cycle bound of toolchain/cyclemodel refuses).

// The levels wait in the Partial as bits.
template <class K>
inline void GridLookup::BeginAs(const LatticeCell c[3], Partial* s) const {
  typename K::L xy[4], tz;
  K::Levels(c[0], c[1], c[2], xy, &tz);
  s->xy[0] = K::ToBits(xy[0]);
  s->xy[1] = K::ToBits(xy[1]);
  s->xy[2] = K::ToBits(xy[2]);
  s->xy[3] = K::ToBits(xy[3]);
  s->tz = K::ToBits(tz);
}

VOLCOMP_KERNEL void GridLookup::Begin(const int32_t* pos_steps, Partial* s) const {
  LatticeCell c[3];
  s->corner = Locate(pos_steps, node_bytes_, c);
  if (type_ == table::ElementType::kFloat32) {
    BeginAs<grid_kernel::Float32>(c, s);
  } else {
    BeginAs<grid_kernel::Int16>(c, s);  // the same levels for int32
  }
}

template <class K>
inline void GridLookup::AccumulateZ0As(Partial* s) const {
  typename K::Acc a0, a1, a2;
  SumLower<K>(s->corner, LevelBits<K>{s->xy}, K::FromBits(s->tz), a0, a1, a2);
  K::Save(a0, a1, a2, s->acc);
}

template <class K>
inline void GridLookup::FinishZ1As(const Partial& s, int32_t out_q8[3]) const {
  typename K::Acc a0, a1, a2;
  K::Restore(s.acc, a0, a1, a2);
  SumUpper<K>(s.corner, LevelBits<K>{s.xy}, K::FromBits(s.tz), a0, a1, a2);
  K::ToQ8(a0, a1, a2, shift_, out_q8);
}

VOLCOMP_KERNEL void GridLookup::AccumulateZ0(Partial* s) const {
  if (type_ == table::ElementType::kInt16) {
    AccumulateZ0As<grid_kernel::Int16>(s);
  } else if (type_ == table::ElementType::kInt32) {
    AccumulateZ0As<grid_kernel::Int32>(s);
  } else {
    AccumulateZ0As<grid_kernel::Float32>(s);
  }
}

VOLCOMP_KERNEL void GridLookup::FinishZ1(const Partial& s, int32_t out_q8[3]) const {
  if (type_ == table::ElementType::kInt16) {
    FinishZ1As<grid_kernel::Int16>(s, out_q8);
  } else if (type_ == table::ElementType::kInt32) {
    FinishZ1As<grid_kernel::Int32>(s, out_q8);
  } else {
    FinishZ1As<grid_kernel::Float32>(s, out_q8);
  }
}

}  // namespace volcomp
