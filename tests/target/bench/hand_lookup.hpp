// A hand-scheduled Thumb-2 form of GridLookup::LookupInt16 (bench only, not product code).
//
// Purpose: a measured floor for the 3-component int16 lookup under the cycle model. It does the
// same arithmetic as the C++ kernel (LocateFast per dimension, the same Q0.32/Q1.31 weights, 24
// SMLAWB/SMLAWT, the same rounding) with every register assigned by hand: no stack traffic
// beyond the callee-saved registers, constants read with LDM, all 14 usable registers live in
// the row phase. The bench checks it against GridLookup::LookupInt16 on every position it times,
// so the figure belongs to a correct kernel. docs/mcu-target.md ("The lookup budgets") uses the
// figure.
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
  int32_t round;   // 2^(shift - 1)
  uint32_t shift;  // 7 + frac_bits
};
static_assert(sizeof(void*) != 4 || offsetof(HandLookupConstants, data) == 60, "asm offsets");
static_assert(sizeof(void*) != 4 || offsetof(HandLookupConstants, shift) == 76, "asm offsets");

/// Fills `k` for an int16 GRID3 (as GridLookup::Init() does); false for other element types.
bool PrepareHandLookup(const table::Grid3View& grid, HandLookupConstants* k);

}  // namespace volcomp::target

/// The kernel: out_q8[c] as GridLookup::LookupInt16(pos_steps, out_q8) computes it.
extern "C" void volcomp_hand_lookup_int16(const volcomp::target::HandLookupConstants* k,
                                          const int32_t* pos_steps,
                                          int32_t* out_q8);
