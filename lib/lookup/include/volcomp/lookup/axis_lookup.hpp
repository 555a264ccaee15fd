// Linear interpolation of an AXIS1D table: correction of one axis from its own position and its
// direction of motion (forward table, reverse table or forward + backlash), with rotary wrap.
//
// Init() takes a validated Axis1dView (the image must outlive the lookup). Lookup() clamps to the
// table (end values hold outside), no division. For wrap tables the caller passes the position
// already reduced into [origin, origin + period) (see WrapTracker). Output: Q24.8 steps.
#pragma once

#include <cstdint>
#include <type_traits>

#include "volcomp/base/interp_arith.hpp"
#include "volcomp/base/invariant_divider.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/lookup/cell_locator.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp {

class AxisLookup {
 public:
  Status Init(const table::Axis1dView& view);

  /// `reverse` = the axis last moved in the negative direction. The hot path: LocateFast(), the
  /// two nodes of an int16 table read as one word (SMLAWB/SMLAWT), the rounding term folded into
  /// the accumulator; bit-identical to LookupReference().
  int32_t Lookup(int32_t pos_steps, bool reverse) const;

  /// The clear reference: one template for every element type (tests compare Lookup() with it).
  int32_t LookupReference(int32_t pos_steps, bool reverse) const {
    const uint8_t* values = reverse ? reverse_ : forward_;
    const int32_t backlash = reverse ? backlash_q8_ : 0;
    switch (type_) {
      case table::ElementType::kInt16:
        return Interpolate<LoadInt16>(values, pos_steps) + backlash;
      case table::ElementType::kInt32:
        return Interpolate<LoadInt32>(values, pos_steps) + backlash;
      case table::ElementType::kFloat32:
        return Interpolate<LoadFloat32>(values, pos_steps) + backlash;
    }
    return 0;
  }

  uint8_t axis() const { return axis_; }
  bool wraps() const { return period_steps_ != 0; }
  uint32_t period_steps() const { return period_steps_; }
  /// The period as a divisor without a divide instruction (WrapTracker::Init in a compensation
  /// run).
  const InvariantDivider& period_divider() const { return period_divider_; }
  int32_t origin_steps() const { return origin_steps_; }

 private:
  // Linear interpolation between the two nodes of the cell: weights (~frac) >> 1 and frac >> 1
  // (Q1.31, the x level of interp_arith.hpp), or the same in float for float32 tables.
  template <class Loader>
  int32_t Interpolate(const uint8_t* values, int32_t pos_steps) const {
    const LatticeCell c = loc_.Locate(pos_steps);
    const uint8_t* p = values + c.cell * Loader::kSize;
    typename Loader::Acc acc = Loader::Zero();
    if constexpr (std::is_floating_point_v<typename Loader::Value>) {
      const float t = static_cast<float>(c.frac_q32) * (1.0f / 4294967296.0f);
      acc = Loader::Mac(acc, 1.0f - t, Loader::Load(p));
      acc = Loader::Mac(acc, t, Loader::Load(p + Loader::kSize));
    } else {
      acc = Loader::Mac(acc, static_cast<int32_t>(~c.frac_q32 >> 1), Loader::Load(p));
      acc =
          Loader::Mac(acc, static_cast<int32_t>(c.frac_q32 >> 1), Loader::Load(p + Loader::kSize));
    }
    return Loader::ToQ8(acc, frac_bits_);
  }

  // Hot fields first, in the order Lookup() reads them.
  LatticeDim dim_;
  const uint8_t* forward_ = nullptr;
  const uint8_t* reverse_ = nullptr;  // == forward_ when the table has no reverse part
  int32_t backlash_q8_ = 0;
  int32_t round_ = 0;   // fixed point: 2^(shift_ - 1)
  uint32_t shift_ = 0;  // fixed point: 7 + f (int16), 23 + f (int32)
  table::ElementType type_ = table::ElementType::kInt16;
  uint8_t axis_ = 0;
  uint32_t frac_bits_ = 0;
  uint32_t period_steps_ = 0;
  int32_t origin_steps_ = 0;
  InvariantDivider period_divider_;  // period_steps_ (1 without wrap)
  LatticeLocator loc_;               // the reference's locator (same constants as dim_)
};

/// Keeps a rotary position reduced modulo a period, updated by small deltas (no division in
/// Update()). Precondition: |delta| per Update() < period (validation bounds the period to the
/// extent of a table, < 2^31 steps, so 32-bit arithmetic holds every intermediate).
class WrapTracker {
 public:
  /// Sets the tracked position from an absolute one (divides; call at activation).
  void Init(int32_t pos_steps, int32_t origin_steps, uint32_t period_steps);
  /// Init() with the period as a prepared divisor (AxisLookup::period_divider()): no divide
  /// instruction, so a compensation run may call it (referencing, table switch).
  __attribute__((always_inline)) void Init(int32_t pos_steps,
                                           int32_t origin_steps,
                                           const InvariantDivider& period) {
    period_ = period.divisor();
    origin_ = origin_steps;
    // pos - origin lies in (-2^32, 2^32): its magnitude and sign in 32 bits, the remainder of the
    // magnitude by the prepared divisor, mirrored into [0, period) for a negative difference.
    const bool below = pos_steps < origin_steps;
    const uint32_t p = static_cast<uint32_t>(pos_steps), o = static_cast<uint32_t>(origin_steps);
    const uint32_t r = period.Divide(below ? o - p : p - o).remainder;
    offset_ = below && r != 0 ? period_ - r : r;
  }
  /// Advances by `delta_steps` and returns origin + ((pos - origin) mod period).
  int32_t Update(int32_t delta_steps) {
    // offset + delta lies in (-period, 2 * period): one correction either way.
    uint32_t o = offset_ + static_cast<uint32_t>(delta_steps);
    o = (delta_steps < 0 && static_cast<int32_t>(o) < 0) ? o + period_ : o;
    o = o >= period_ ? o - period_ : o;
    offset_ = o;
    return position();
  }
  int32_t position() const {
    return static_cast<int32_t>(static_cast<uint32_t>(origin_) + offset_);
  }

 private:
  uint32_t period_ = 1;
  int32_t origin_ = 0;
  uint32_t offset_ = 0;
};

}  // namespace volcomp
