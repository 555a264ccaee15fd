// The whole int16 and float32 lookups (GridLookup::LookupAs, what Lookup() runs) for the
// Cortex-M4F, written in Thumb-2 with every register assigned by hand: the same arithmetic as the
// C++ kernels in grid_lookup.cpp (LocateFast per dimension; int16: the same Q0.32/Q1.31 weights, 24
// SMLAWB/SMLAWT and rounding; float32: TrilinearWeightsF, the reference's order of the 8 products
// per component, FloatToQ8), without stack traffic beyond the callee-saved registers: constants
// read with LDM, float nodes with VLDM. GCC's code for the same C++ is 201 / 261 cycles on the
// model's static bound, these 177 / 216 (docs/mcu-target.md). They read GridLookup's hot fields
// at fixed offsets (checked in GridLookup::Init()). The C++ kernels stay the host's and the
// int32 version; the tests compare both with the reference template on the target
// (qemu.hot_path_reference, the golden vectors).
#include "volcomp/lookup/grid_lookup.hpp"

#if VOLCOMP_GRID_LOOKUP_CM4

namespace volcomp {

// The locate shared by both kernels (r0 = this (the hot fields), advanced to `data`; r1 =
// positions): per dimension clamp (QSUB, USAT, min with span), then cell:frac = u * recip / 2^32.
// Leaves r5 = fx, r6 = cx, r7 = fy, r8 = cy, r9 = fz, r10 = cz; uses r3, r4, r11.
__asm(
    ".macro volcomp_grid_locate\n"
    // x
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
    ".endm\n");

// r0 = this (the hot fields), r1 = positions, r2 = out. Register use in the row phase: r0 h0, r1
// row pointer (z0), r2 a0, r3 stride_y, r4 row pointer (z1), r5 x1 weight, r6 x0 weight, r7 x1y1,
// r8 a1, r9 tz (Q1.31), r10 x0y1, r11 a2, r12 h1, lr the element word.
template <>
__attribute__((naked)) void GridLookup::LookupAs<grid_kernel::Int16>(const int32_t*,
                                                                     int32_t*) const {
  __asm volatile(
      // The two corner rows of one y level (x0 and x1 nodes each): z0 at r1 with weights r6, r5;
      // z1 at r4 with r0, r12.
      ".macro volcomp_grid_rows\n"
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
      "volcomp_grid_locate\n"
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
      "volcomp_grid_rows\n"
      // y1: the same with x0y1, x1y1 one y stride further.
      "add     r1, r1, r3\n"
      "add     r4, r4, r3\n"
      "umull   lr, r0, r10, r9\n"
      "umull   lr, r12, r7, r9\n"
      "rsb     r6, r0, r10, lsr #1\n"
      "rsb     r5, r12, r7, lsr #1\n"
      "volcomp_grid_rows\n"
      // out = acc >> shift (r0 = this (the hot fields), r3 = out again).
      "pop     {r0, r3}\n"
      "ldr     r1, [r0, #76]\n"
      "asr     r2, r2, r1\n"
      "asr     r8, r8, r1\n"
      "asr     r11, r11, r1\n"
      "stmia   r3, {r2, r8, r11}\n"
      "pop     {r4, r5, r6, r7, r8, r9, r10, r11, pc}\n");
}

// r0 = this (the hot fields), r1 = positions, r2 = out (kept). After volcomp_grid_locate: corner
// address, weights in s8..s15 (w0..w7, TrilinearWeightsF), accumulators s0..s2, one node's three
// elements in s3..s5 (VLDM with write-back walks a row: x0 node, then x1 node).
template <>
__attribute__((naked)) void GridLookup::LookupAs<grid_kernel::Float32>(const int32_t*,
                                                                       int32_t*) const {
  __asm volatile(
      // One corner node at r: products with weight w added to the accumulators.
      ".macro volcomp_grid_node r, w\n"
      "vldmia  \\r!, {s3, s4, s5}\n"
      "vmul.f32 s3, \\w, s3\n"
      "vmul.f32 s4, \\w, s4\n"
      "vmul.f32 s5, \\w, s5\n"
      "vadd.f32 s0, s0, s3\n"
      "vadd.f32 s1, s1, s4\n"
      "vadd.f32 s2, s2, s5\n"
      ".endm\n"
      "push    {r4, r5, r6, r7, r8, r9, r10, r11, lr}\n"
      "volcomp_grid_locate\n"
      // Corner address p = data + 12 cx + cy sy + cz sz; q = p + sz; r3 = sy - 24 (row to row
      // after a row's two VLDM write-backs).
      "ldmia   r0, {r1, r3, r4}\n"
      "add     r6, r6, r6, lsl #1\n"
      "add     r1, r1, r6, lsl #2\n"
      "mla     r1, r8, r3, r1\n"
      "mla     r1, r10, r4, r1\n"
      "add     r4, r1, r4\n"
      "sub     r3, r3, #24\n"
      // Fractions to float (exact scaling by 2^-32), then TrilinearWeightsF.
      "vmov    s0, s1, r5, r7\n"
      "vmov    s2, r9\n"
      "vcvt.f32.u32 s0, s0, #32\n"
      "vcvt.f32.u32 s1, s1, #32\n"
      "vcvt.f32.u32 s2, s2, #32\n"
      "vmov.f32 s3, #1.0\n"
      "vsub.f32 s3, s3, s0\n"    // x0
      "vmul.f32 s4, s0, s1\n"    // x1y1
      "vmul.f32 s5, s3, s1\n"    // x0y1
      "vsub.f32 s6, s0, s4\n"    // x1y0
      "vsub.f32 s7, s3, s5\n"    // x0y0
      "vmul.f32 s12, s7, s2\n"   // w4
      "vmul.f32 s13, s6, s2\n"   // w5
      "vmul.f32 s14, s5, s2\n"   // w6
      "vmul.f32 s15, s4, s2\n"   // w7
      "vsub.f32 s8, s7, s12\n"   // w0
      "vsub.f32 s9, s6, s13\n"   // w1
      "vsub.f32 s10, s5, s14\n"  // w2
      "vsub.f32 s11, s4, s15\n"  // w3
      // k = 0 starts the sums, k = 1..7 add in the reference's order.
      "vldmia  r1!, {s3, s4, s5}\n"
      "vmul.f32 s0, s8, s3\n"
      "vmul.f32 s1, s8, s4\n"
      "vmul.f32 s2, s8, s5\n"
      "volcomp_grid_node r1, s9\n"
      "add     r1, r1, r3\n"
      "volcomp_grid_node r1, s10\n"
      "volcomp_grid_node r1, s11\n"
      "volcomp_grid_node r4, s12\n"
      "volcomp_grid_node r4, s13\n"
      "add     r4, r4, r3\n"
      "volcomp_grid_node r4, s14\n"
      "volcomp_grid_node r4, s15\n"
      // FloatToQ8: s = a * 256, s -/+ 0.5 by the sign (MI: false for NaN, as in C), truncate.
      "mov     r3, #0x43800000\n"
      "vmov    s6, r3\n"
      "vmov.f32 s7, #0.5\n"
      "vmul.f32 s0, s0, s6\n"
      "vmul.f32 s1, s1, s6\n"
      "vmul.f32 s2, s2, s6\n"
      "vcmp.f32 s0, #0\n"
      "vmrs    APSR_nzcv, fpscr\n"
      "ite     mi\n"
      "vsubmi.f32 s0, s0, s7\n"
      "vaddpl.f32 s0, s0, s7\n"
      "vcmp.f32 s1, #0\n"
      "vmrs    APSR_nzcv, fpscr\n"
      "ite     mi\n"
      "vsubmi.f32 s1, s1, s7\n"
      "vaddpl.f32 s1, s1, s7\n"
      "vcmp.f32 s2, #0\n"
      "vmrs    APSR_nzcv, fpscr\n"
      "ite     mi\n"
      "vsubmi.f32 s2, s2, s7\n"
      "vaddpl.f32 s2, s2, s7\n"
      "vcvt.s32.f32 s0, s0\n"
      "vcvt.s32.f32 s1, s1\n"
      "vcvt.s32.f32 s2, s2\n"
      "vstmia  r2, {s0, s1, s2}\n"
      "pop     {r4, r5, r6, r7, r8, r9, r10, r11, pc}\n");
}

}  // namespace volcomp

#endif  // VOLCOMP_GRID_LOOKUP_CM4
