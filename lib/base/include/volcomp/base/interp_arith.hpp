// Arithmetic of the interpolators, shared by the clear reference (GridLookup::Interpolate<Loader>)
// and the hot path (GridLookup::Lookup and its parts): Q1.31 weights from Q0.32 fractions (high
// words of 32x32 multiplies only) and one element policy per type (int16, int32, float32) giving a
// Q8 result within 1 LSB of the exact interpolation. Freestanding; float32 needs -ffp-contract=off.
// The weights, policies and error bound: docs/table-image-format.md, "Interpolation and accuracy".
#pragma once

#include <cstdint>

#if defined(__ARM_FEATURE_DSP)
#include <arm_acle.h>
#endif

namespace volcomp {

/// High word of the 64-bit product (UMULL on Cortex-M4).
inline uint32_t MulHiU32(uint32_t a, uint32_t b) {
  return static_cast<uint32_t>((static_cast<uint64_t>(a) * b) >> 32);
}

/// acc + floor(w * v16 / 2^16) with v16 the low halfword of v as signed (SMLAWB).
inline int32_t MulAddWordHalf(int32_t acc, int32_t w, int32_t v) {
#if defined(__ARM_FEATURE_DSP)
  return __smlawb(w, v, acc);
#else
  const int64_t p = static_cast<int64_t>(w) * static_cast<int16_t>(v);
  return static_cast<int32_t>(static_cast<uint32_t>(acc) +
                              static_cast<uint32_t>(static_cast<int32_t>(p >> 16)));
#endif
}

/// acc + floor(w * v16 / 2^16) with v16 the high halfword of v as signed (SMLAWT).
inline int32_t MulAddWordTop(int32_t acc, int32_t w, int32_t v) {
#if defined(__ARM_FEATURE_DSP)
  return __smlawt(w, v, acc);
#else
  const int64_t p = static_cast<int64_t>(w) * static_cast<int16_t>(static_cast<uint32_t>(v) >> 16);
  return static_cast<int32_t>(static_cast<uint32_t>(acc) +
                              static_cast<uint32_t>(static_cast<int32_t>(p >> 16)));
#endif
}

/// a - b saturated to the int32 range (QSUB).
inline int32_t SubSat(int32_t a, int32_t b) {
#if defined(__ARM_FEATURE_DSP)
  return __qsub(a, b);
#else
  const int64_t d = static_cast<int64_t>(a) - b;
  return static_cast<int32_t>(d > INT32_MAX ? INT32_MAX : (d < INT32_MIN ? INT32_MIN : d));
#endif
}

/// a + b saturated to the int32 range (QADD).
inline int32_t AddSat(int32_t a, int32_t b) {
#if defined(__ARM_FEATURE_DSP)
  return __qadd(a, b);
#else
  const int64_t s = static_cast<int64_t>(a) + b;
  return static_cast<int32_t>(s > INT32_MAX ? INT32_MAX : (s < INT32_MIN ? INT32_MIN : s));
#endif
}

/// acc + w * v, exactly in 64 bits (SMLAL). GCC 12 knows that the weights are non-negative and
/// then multiplies them as unsigned (UMULL + MLA + ADDS/ADC); the one-instruction form is written
/// out for the Cortex-M4 (C reference below, the same value).
inline int64_t MulAddLong(int64_t acc, int32_t w, int32_t v) {
#if defined(__ARM_ARCH_7EM__) && defined(__GNUC__)
  __asm__("smlal %Q0, %R0, %1, %2" : "+r"(acc) : "r"(w), "r"(v));
  return acc;
#else
  return acc + static_cast<int64_t>(w) * v;
#endif
}

/// max(v, 0) for any int32 v, as uint32 (USAT #31).
inline uint32_t SatUnsigned31(int32_t v) {
#if defined(__ARM_FEATURE_SAT)
  return static_cast<uint32_t>(__usat(v, 31));
#else
  return v < 0 ? 0u : static_cast<uint32_t>(v);
#endif
}

/// Four bytes at any address (one LDR on a Cortex-M4, which allows unaligned word loads), in the
/// host's byte order (little-endian on every supported target).
inline int32_t LoadWordUnaligned(const uint8_t* p) {
  int32_t v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

/// The eight trilinear weights in Q1.31 (index bit 0 = x, bit 1 = y, bit 2 = z).
struct TrilinearWeights {
  int32_t w[8];
  TrilinearWeights(uint32_t tx, uint32_t ty, uint32_t tz) {
    const uint32_t x1 = tx, x0 = ~tx;
    const uint32_t x1y1 = MulHiU32(x1, ty), x1y0 = x1 - x1y1;
    const uint32_t x0y1 = MulHiU32(x0, ty), x0y0 = x0 - x0y1;
    const uint32_t tz31 = tz >> 1;
    const uint32_t xy[4] = {x0y0, x1y0, x0y1, x1y1};
#pragma GCC unroll 4
    for (int k = 0; k < 4; ++k) {
      const uint32_t hi = MulHiU32(xy[k], tz31);
      w[k + 4] = static_cast<int32_t>(hi);
      w[k] = static_cast<int32_t>((xy[k] >> 1) - hi);
    }
  }
};

/// Float weights from the same fractions (the float32 table path).
struct TrilinearWeightsF {
  float w[8];
  TrilinearWeightsF(uint32_t tx_q32, uint32_t ty_q32, uint32_t tz_q32) {
    constexpr float kQ32 = 1.0f / 4294967296.0f;
    const float tx = static_cast<float>(tx_q32) * kQ32, ty = static_cast<float>(ty_q32) * kQ32,
                tz = static_cast<float>(tz_q32) * kQ32;
    const float x1 = tx, x0 = 1.0f - tx;
    const float x1y1 = x1 * ty, x1y0 = x1 - x1y1;
    const float x0y1 = x0 * ty, x0y0 = x0 - x0y1;
    const float xy[4] = {x0y0, x1y0, x0y1, x1y1};
#pragma GCC unroll 4
    for (int k = 0; k < 4; ++k) {
      w[k + 4] = xy[k] * tz;
      w[k] = xy[k] - w[k + 4];
    }
  }
};

/// Q8 rounding of a float sum, half away from zero.
inline int32_t FloatToQ8(float acc) {
  const float s = acc * 256.0f;
  return static_cast<int32_t>(s < 0.0f ? s - 0.5f : s + 0.5f);
}

/// Element policies: how a raw little-endian element is loaded and accumulated.
struct LoadInt16 {
  static constexpr uint32_t kSize = 2;
  using Value = int32_t;
  using Acc = int32_t;
  static int32_t Load(const uint8_t* p) {
    int16_t v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  }
  static constexpr Acc Zero() { return 0; }
  static Acc Mac(Acc acc, int32_t w_q31, int32_t v) { return MulAddWordHalf(acc, w_q31, v); }
  /// `frac_bits` of the table (0..8).
  static int32_t ToQ8(Acc acc, uint32_t frac_bits) {
    const uint32_t shift = 7u + frac_bits;
    return static_cast<int32_t>(static_cast<uint32_t>(acc) + (1u << (shift - 1u))) >> shift;
  }
};
struct LoadInt32 {
  static constexpr uint32_t kSize = 4;
  using Value = int32_t;
  using Acc = int64_t;
  static int32_t Load(const uint8_t* p) {
    int32_t v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  }
  static constexpr Acc Zero() { return 0; }
  static Acc Mac(Acc acc, int32_t w_q31, int32_t v) {
    return acc + static_cast<int64_t>(w_q31) * v;
  }
  static int32_t ToQ8(Acc acc, uint32_t frac_bits) {
    const uint32_t shift = 23u + frac_bits;
    return static_cast<int32_t>((acc + (int64_t{1} << (shift - 1u))) >> shift);
  }
};
struct LoadFloat32 {
  static constexpr uint32_t kSize = 4;
  using Value = float;
  using Acc = float;
  static float Load(const uint8_t* p) {
    float v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  }
  static constexpr Acc Zero() { return 0.0f; }
  static Acc Mac(Acc acc, float w, float v) { return acc + w * v; }
  static int32_t ToQ8(Acc acc, uint32_t /*frac_bits*/) { return FloatToQ8(acc); }
};

}  // namespace volcomp
