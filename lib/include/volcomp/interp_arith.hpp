// Arithmetic policies of the interpolators: one template, fixed-point or float32 arithmetic.
//
// An interpolator computes weights w_k (products of cell fractions, summing to One()) and the sum
// S = sum_k w_k * v_k over the corner values, then converts S to Q24.8 steps.
//
// FixedQ30: weights are Q2.30 in int32; each weight product is truncated, and the last weight of
//   every pair is formed as (parent - sibling), so the weights sum to exactly 2^30. S is exact in
//   int64 (|w| <= 2^30, |v| <= 2^24 LSB). ToQ8 rounds half up. Error bound in
//   docs/table-image-format.md.
// Float32: weights and S in float (compile with -ffp-contract=off on the host so host and target
//   round the same way); ToQ8 rounds half away from zero.
#pragma once

#include <cstdint>

#include "volcomp/byte_order.hpp"

namespace volcomp {

struct FixedQ30 {
  using Weight = int32_t;
  using Acc = int64_t;
  using Value = int32_t;
  static constexpr Weight One() { return 1 << 30; }
  static Weight FromQ30(uint32_t t) { return static_cast<int32_t>(t); }
  static Weight Mul(Weight a, Weight b) {
    return static_cast<int32_t>(
        (static_cast<uint64_t>(static_cast<uint32_t>(a)) * static_cast<uint32_t>(b)) >> 30);
  }
  static constexpr Acc Zero() { return 0; }
  static Acc Mac(Acc acc, Weight w, Value v) { return acc + static_cast<int64_t>(w) * v; }
  /// `shift` = 30 + frac_bits - 8 (22..30).
  static int32_t ToQ8(Acc acc, uint32_t shift) {
    return static_cast<int32_t>((acc + (int64_t{1} << (shift - 1u))) >> shift);
  }
};

struct Float32 {
  using Weight = float;
  using Acc = float;
  using Value = float;
  static constexpr Weight One() { return 1.0f; }
  static Weight FromQ30(uint32_t t) { return static_cast<float>(t) * (1.0f / 1073741824.0f); }
  static Weight Mul(Weight a, Weight b) { return a * b; }
  static constexpr Acc Zero() { return 0.0f; }
  static Acc Mac(Acc acc, Weight w, Value v) { return acc + w * v; }
  static int32_t ToQ8(Acc acc, uint32_t /*shift*/) {
    const float s = acc * 256.0f;
    return static_cast<int32_t>(s < 0.0f ? s - 0.5f : s + 0.5f);
  }
};

/// Element loaders: raw little-endian storage -> the policy's Value type.
struct LoadInt16 {
  using Arith = FixedQ30;
  static constexpr uint32_t kSize = 2;
  static int32_t Load(const uint8_t* p) {
    int16_t v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  }
};
struct LoadInt32 {
  using Arith = FixedQ30;
  static constexpr uint32_t kSize = 4;
  static int32_t Load(const uint8_t* p) {
    int32_t v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  }
};
struct LoadFloat32 {
  using Arith = Float32;
  static constexpr uint32_t kSize = 4;
  static float Load(const uint8_t* p) {
    float v;
    __builtin_memcpy(&v, p, sizeof v);
    return v;
  }
};

}  // namespace volcomp
