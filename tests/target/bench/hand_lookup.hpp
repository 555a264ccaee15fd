// Hand-scheduled Thumb-2 forms of the int16 and float32 GridLookup::Lookup() (bench only, not
// product code).
//
// Purpose: a measured floor for the 3-component lookup under the cycle model. Each does the same
// arithmetic as its C++ kernel (LocateFast per dimension; int16: the same Q0.32/Q1.31 weights, 24
// SMLAWB/SMLAWT and rounding; float32: TrilinearWeightsF, the reference's order of the 8 products
// per component, FloatToQ8) with every register assigned by hand: no stack traffic beyond the
// callee-saved registers, constants read with LDM, float nodes read with VLDM. The bench checks
// each against its GridLookup kernel on every position it times, so the figures belong to correct
// kernels. docs/mcu-target.md ("The lookup budgets") uses the figures.
#pragma once

#include <cstddef>
#include <cstdint>

#include "volcomp/table_image.hpp"

namespace volcomp::target {

/// Everything the kernel reads, in its load order (the offsets are part of the assembly).
struct HandLookupConstants {
  struct Dim {
    uint32_t axis;  // board axis whose position this dimension reads
    int32_t lo;
    uint32_t span;
    uint32_t recip_lo;
    uint32_t recip_hi;
  };
  Dim dim[3];
  const uint8_t* data;
  uint32_t stride_y;
  uint32_t stride_z;
  int32_t round;   // int16: 2^(shift - 1); float32: unused
  uint32_t shift;  // int16: 7 + frac_bits; float32: unused
};
static_assert(sizeof(void*) != 4 || offsetof(HandLookupConstants, data) == 60, "asm offsets");
static_assert(sizeof(void*) != 4 || offsetof(HandLookupConstants, shift) == 76, "asm offsets");

/// Fills `k` for an int16 or float32 GRID3 (as GridLookup::Init() does); false for int32.
bool PrepareHandLookup(const table::Grid3View& grid, HandLookupConstants* k);

}  // namespace volcomp::target

/// The kernels: out_q8[c] as GridLookup::Lookup(pos_steps, out_q8) computes it for an int16 /
/// float32 grid.
extern "C" void volcomp_hand_lookup_int16(const volcomp::target::HandLookupConstants* k,
                                          const int32_t* pos_steps,
                                          int32_t* out_q8);
extern "C" void volcomp_hand_lookup_float32(const volcomp::target::HandLookupConstants* k,
                                            const int32_t* pos_steps,
                                            int32_t* out_q8);
