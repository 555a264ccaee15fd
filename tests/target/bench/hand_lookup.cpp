// The hand-scheduled int16 lookup (see hand_lookup.hpp) and its constants.
#include "hand_lookup.hpp"

#include "volcomp/cell_locator.hpp"

namespace volcomp::target {

bool PrepareHandLookup(const table::Grid3View& grid, HandLookupConstants* k) {
  if (!grid.present || grid.type != table::ElementType::kInt16) return false;
  for (int d = 0; d < 3; ++d) {
    LatticeLocator loc;
    loc.Init(grid.dim[d]);
    k->dim[d] = {grid.axis[d], loc.dim().lo, loc.dim().span, loc.dim().recip_lo,
                 loc.dim().recip_hi};
  }
  k->data = grid.data;
  k->stride_y = 6u * grid.dim[0].nodes;
  k->stride_z = k->stride_y * grid.dim[1].nodes;
  k->shift = 7u + grid.frac_bits;
  k->round = static_cast<int32_t>(1u << (k->shift - 1u));
  return true;
}

}  // namespace volcomp::target

// r0 = constants, r1 = positions, r2 = out. Register use in the row phase: r0 h0, r1 row pointer
// (z0), r2 a0, r3 stride_y, r4 row pointer (z1), r5 x1 weight, r6 x0 weight, r7 x1y1, r8 a1,
// r9 tz (Q1.31), r10 x0y1, r11 a2, r12 h1, lr the element word.
extern "C" __attribute__((naked, section(".volcomp_hot.hand_lookup"))) void
volcomp_hand_lookup_int16(const volcomp::target::HandLookupConstants*, const int32_t*, int32_t*) {
  __asm volatile(
      // The two corner rows of one y level (x0 and x1 nodes each): z0 at r1 with weights r6, r5;
      // z1 at r4 with r0, r12.
      ".macro volcomp_hand_rows\n"
      "ldr     lr, [r1]\n"
      "smlawb  r2, r6, lr, r2\n"
      "smlawt  r8, r6, lr, r8\n"
      "ldr     lr, [r1, #4]\n"
      "smlawb  r11, r6, lr, r11\n"
      "smlawt  r2, r5, lr, r2\n"
      "ldr     lr, [r1, #8]\n"
      "smlawb  r8, r5, lr, r8\n"
      "smlawt  r11, r5, lr, r11\n"
      "ldr     lr, [r4]\n"
      "smlawb  r2, r0, lr, r2\n"
      "smlawt  r8, r0, lr, r8\n"
      "ldr     lr, [r4, #4]\n"
      "smlawb  r11, r0, lr, r11\n"
      "smlawt  r2, r12, lr, r2\n"
      "ldr     lr, [r4, #8]\n"
      "smlawb  r8, r12, lr, r8\n"
      "smlawt  r11, r12, lr, r11\n"
      ".endm\n"
      "push    {r0, r2, r4, r5, r6, r7, r8, r9, r10, r11, lr}\n"
      // x: clamp (QSUB, USAT, min with span), then cell:frac = u * recip / 2^32.
      "ldmia   r0!, {r3, r4, r5, r6, r7}\n"
      "ldr     r3, [r1, r3, lsl #2]\n"
      "qsub    r3, r3, r4\n"
      "usat    r3, #31, r3\n"
      "cmp     r3, r5\n"
      "it      hi\n"
      "movhi   r3, r5\n"
      "umull   r4, r5, r3, r6\n"
      "movs    r6, #0\n"
      "umlal   r5, r6, r3, r7\n"  // r5 = fx, r6 = cx
      // y
      "ldmia   r0!, {r3, r4, r7, r8, r9}\n"
      "ldr     r3, [r1, r3, lsl #2]\n"
      "qsub    r3, r3, r4\n"
      "usat    r3, #31, r3\n"
      "cmp     r3, r7\n"
      "it      hi\n"
      "movhi   r3, r7\n"
      "umull   r4, r7, r3, r8\n"
      "movs    r8, #0\n"
      "umlal   r7, r8, r3, r9\n"  // r7 = fy, r8 = cy
      // z
      "ldmia   r0!, {r3, r4, r9, r10, r11}\n"
      "ldr     r3, [r1, r3, lsl #2]\n"
      "qsub    r3, r3, r4\n"
      "usat    r3, #31, r3\n"
      "cmp     r3, r9\n"
      "it      hi\n"
      "movhi   r3, r9\n"
      "umull   r4, r9, r3, r10\n"
      "movs    r10, #0\n"
      "umlal   r9, r10, r3, r11\n"  // r9 = fz, r10 = cz
      // Corner address p = data + 6 cx + cy sy + cz sz; q = p + sz; accumulators = round.
      "ldmia   r0, {r1, r3, r4, r11}\n"
      "add     r6, r6, r6, lsl #1\n"
      "add     r1, r1, r6, lsl #1\n"
      "mla     r1, r8, r3, r1\n"
      "mla     r1, r10, r4, r1\n"
      "add     r4, r1, r4\n"
      "mov     r2, r11\n"
      "mov     r8, r11\n"
      // Weights: x0 = ~fx, x1 = fx; x0y1, x1y1 = x * fy (high words); x0y0, x1y0 = x - xy1.
      "mvn     r6, r5\n"
      "umull   r0, r10, r6, r7\n"
      "umull   r0, r7, r5, r7\n"
      "sub     r6, r6, r10\n"
      "sub     r5, r5, r7\n"
      "lsr     r9, r9, #1\n"
      // y0: h = xy0 * tz; z0 weights (xy0 >> 1) - h, z1 weights h.
      "umull   lr, r0, r6, r9\n"
      "umull   lr, r12, r5, r9\n"
      "rsb     r6, r0, r6, lsr #1\n"
      "rsb     r5, r12, r5, lsr #1\n"
      "volcomp_hand_rows\n"
      // y1: the same with x0y1, x1y1 one y stride further.
      "add     r1, r1, r3\n"
      "add     r4, r4, r3\n"
      "umull   lr, r0, r10, r9\n"
      "umull   lr, r12, r7, r9\n"
      "rsb     r6, r0, r10, lsr #1\n"
      "rsb     r5, r12, r7, lsr #1\n"
      "volcomp_hand_rows\n"
      // out = acc >> shift (r0 = constants, r3 = out again).
      "pop     {r0, r3}\n"
      "ldr     r1, [r0, #76]\n"
      "asr     r2, r2, r1\n"
      "asr     r8, r8, r1\n"
      "asr     r11, r11, r1\n"
      "stmia   r3, {r2, r8, r11}\n"
      "pop     {r4, r5, r6, r7, r8, r9, r10, r11, pc}\n");
}
