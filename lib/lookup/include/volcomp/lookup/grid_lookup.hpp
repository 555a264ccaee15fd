// Trilinear interpolation of the GRID3 correction vector at a position (steps) into 3 components
// in Q24.8 steps (component c corrects axis axis(c)), clamped to the grid. Init() may divide (call
// at activation); Lookup() and its three parts Begin()/AccumulateZ0()/FinishZ1() (what the
// compensator spreads over its runs) do not: constant time, bit-identical to the clear reference
// Interpolate<Loader>(). Arithmetic and accuracy: docs/table-image-format.md, "Interpolation and
// accuracy"; the kernels: docs/mcu-target.md.
#pragma once

#include <cstdint>
#include <type_traits>

#include "volcomp/base/interp_arith.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/lookup/cell_locator.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp {

namespace grid_kernel {
struct Int16;  // the element kernels (grid_lookup.cpp)
struct Int32;
struct Float32;
}  // namespace grid_kernel

class GridLookup {
 public:
  /// Prepares for `grid` (which must be present and valid); the image must outlive the lookup.
  Status Init(const table::Grid3View& grid);

  /// Correction at `pos_steps` (indexed by board axis; only axis(0..2) are read), Q24.8 steps:
  /// the three parts below in one call.
  inline void Lookup(const int32_t* pos_steps, int32_t out_q8[3]) const;

  /// The reference computation for an explicit element loader (tests compare Lookup() with it).
  template <class Loader>
  void Interpolate(const int32_t* pos_steps, int32_t out_q8[3]) const;

  /// The same lookup in three parts, for spreading it over compensation runs (the compensator does
  /// one part per run): Begin() locates the cell and forms the y-level weights, AccumulateZ0()
  /// adds the four corners of the lower z level, FinishZ1() the upper four and writes the result.
  /// Lookup() is these three in sequence: the result is bit-identical.
  struct Partial {
    const uint8_t* corner = nullptr;  // the cell's first corner (x0, y0, z0)
    uint32_t xy[4] = {};              // x0y0, x1y0, x0y1, x1y1: Q0.32, or float bits (float32)
    uint32_t tz = 0;                  // tz >> 1 (Q1.31), or float bits (float32)
    uint32_t acc[6] = {};             // 3 x int32 (int16), 3 x int64 (int32), 3 x float (float32)
  };
  void Begin(const int32_t* pos_steps, Partial* s) const;
  void AccumulateZ0(Partial* s) const;
  void FinishZ1(const Partial& s, int32_t out_q8[3]) const;

  uint8_t axis(int d) const { return axis_[d]; }
  table::ElementType element_type() const { return type_; }

  /// Lookup() for one element kernel (instantiated in grid_lookup.cpp for the three; public so
  /// that the cycle bench can time each).
  template <class K>
  void LookupAs(const int32_t* pos_steps, int32_t out_q8[3]) const;

 private:
  // The kernels' building blocks (grid_lookup.cpp), over an element kernel K.
  const uint8_t* Locate(const int32_t* pos_steps, uint32_t node_bytes, LatticeCell cell[3]) const;
  template <class K>
  void BeginAs(const LatticeCell c[3], Partial* s) const;
  template <class K, class Levels, class L, class Acc>
  void SumLower(const uint8_t* p, const Levels& xy, L tz, Acc& a0, Acc& a1, Acc& a2) const;
  template <class K, class Levels, class L, class Acc>
  void SumUpper(const uint8_t* p, const Levels& xy, L tz, Acc& a0, Acc& a1, Acc& a2) const;
  template <class K>
  void AccumulateZ0As(Partial* s) const;
  template <class K>
  void FinishZ1As(const Partial& s, int32_t out_q8[3]) const;

  // One lattice dimension: the board axis it reads, then the locator constants.
  struct Dim {
    uint32_t axis;
    LatticeDim lattice;
  };
  // Hot fields first, in the order the kernels read them.
  // (The Cortex-M4 kernels, grid_lookup_cm4.cpp, read dim_ to shift_ at fixed offsets.)
  Dim dim_[3];
  const uint8_t* data_ = nullptr;
  uint32_t stride_y_ = 0;    // bytes between neighbouring nodes along y
  uint32_t stride_z_ = 0;    // along z
  int32_t round_ = 0;        // fixed point: 2^(shift_ - 1), the rounding term of ToQ8
  uint32_t shift_ = 0;       // fixed point: 7 + f (int16), 23 + f (int32)
  uint32_t node_bytes_ = 6;  // 3 elements
  uint32_t frac_bits_ = 0;
  LatticeLocator loc_[3];  // the reference's locators (same constants)
  uint32_t stride_[3] = {0, 0, 0};
  uint8_t axis_[3] = {0, 1, 2};
  table::ElementType type_ = table::ElementType::kInt16;
};

// On the Cortex-M4F the whole int16 and float32 lookups are hand-scheduled Thumb-2
// (grid_lookup_cm4.cpp); everywhere else, and for int32, the C++ kernels of grid_lookup.cpp.
#if defined(__ARM_ARCH_7EM__) && defined(__ARM_FP) && !defined(__linux__)
#define VOLCOMP_GRID_LOOKUP_CM4 1
template <>
void GridLookup::LookupAs<grid_kernel::Int16>(const int32_t* pos_steps, int32_t out_q8[3]) const;
template <>
void GridLookup::LookupAs<grid_kernel::Float32>(const int32_t* pos_steps, int32_t out_q8[3]) const;
#else
#define VOLCOMP_GRID_LOOKUP_CM4 0
#endif

inline void GridLookup::Lookup(const int32_t* pos_steps, int32_t out_q8[3]) const {
  if (type_ == table::ElementType::kInt16) {
    LookupAs<grid_kernel::Int16>(pos_steps, out_q8);
  } else if (type_ == table::ElementType::kInt32) {
    LookupAs<grid_kernel::Int32>(pos_steps, out_q8);
  } else {
    LookupAs<grid_kernel::Float32>(pos_steps, out_q8);
  }
}

template <class Loader>
void GridLookup::Interpolate(const int32_t* pos_steps, int32_t out_q8[3]) const {
  const LatticeCell cx = loc_[0].Locate(pos_steps[axis_[0]]);
  const LatticeCell cy = loc_[1].Locate(pos_steps[axis_[1]]);
  const LatticeCell cz = loc_[2].Locate(pos_steps[axis_[2]]);
  const uint8_t* base = data_ + cx.cell * stride_[0] + cy.cell * stride_[1] + cz.cell * stride_[2];
  const uint32_t sx = stride_[0], sy = stride_[1], sz = stride_[2];
  const uint32_t offset[8] = {0, sx, sy, sx + sy, sz, sz + sx, sz + sy, sz + sx + sy};
  using W = typename Loader::Value;
  W w[8];
  if constexpr (std::is_floating_point_v<W>) {
    const TrilinearWeightsF tw(cx.frac_q32, cy.frac_q32, cz.frac_q32);
    for (int k = 0; k < 8; ++k) w[k] = tw.w[k];
  } else {
    const TrilinearWeights tw(cx.frac_q32, cy.frac_q32, cz.frac_q32);
    for (int k = 0; k < 8; ++k) w[k] = tw.w[k];
  }
  for (uint32_t c = 0; c < 3; ++c) {
    typename Loader::Acc acc = Loader::Zero();
    for (int k = 0; k < 8; ++k) {
      acc = Loader::Mac(acc, w[k], Loader::Load(base + offset[k] + c * Loader::kSize));
    }
    out_q8[c] = Loader::ToQ8(acc, frac_bits_);
  }
}

}  // namespace volcomp
