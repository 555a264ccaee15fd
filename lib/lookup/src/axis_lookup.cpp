// AxisLookup and WrapTracker preparation.
#include "volcomp/lookup/axis_lookup.hpp"

namespace volcomp {

Status AxisLookup::Init(const table::Axis1dView& view) {
  if (view.forward == nullptr) return Error::kNotReady;
  loc_.Init(view.dim);
  dim_ = loc_.dim();
  shift_ = (view.type == table::ElementType::kInt32 ? 23u : 7u) + view.frac_bits;
  round_ = static_cast<int32_t>(1u << (shift_ - 1u));
  forward_ = view.forward;
  reverse_ = view.reverse != nullptr ? view.reverse : view.forward;
  backlash_q8_ = view.backlash_q8;
  frac_bits_ = view.frac_bits;
  period_steps_ = view.period_steps;
  period_divider_.Init(view.period_steps == 0 ? 1u : view.period_steps);
  origin_steps_ = view.dim.origin_steps;
  axis_ = view.axis;
  type_ = view.type;
  return Status::Ok();
}

int32_t AxisLookup::Lookup(int32_t pos_steps, bool reverse) const {
  const LatticeCell c = LocateFast(pos_steps, dim_);
  const uint8_t* values = reverse ? reverse_ : forward_;
  const int32_t backlash = reverse ? backlash_q8_ : 0;
  const uint32_t w1 = c.frac_q32 >> 1, w0 = ~c.frac_q32 >> 1;
  if (type_ == table::ElementType::kInt16) {
    // Nodes i and i + 1: the bottom and top halves of one (halfword-aligned) word.
    const int32_t v = LoadWordUnaligned(values + c.cell * 2u);
    int32_t acc = MulAddWordHalf(round_, static_cast<int32_t>(w0), v);
    acc = MulAddWordTop(acc, static_cast<int32_t>(w1), v);
    return (acc >> shift_) + backlash;
  }
  const uint8_t* p = values + c.cell * 4u;
  if (type_ == table::ElementType::kInt32) {
    int32_t v0, v1;
    __builtin_memcpy(&v0, p, sizeof v0);
    __builtin_memcpy(&v1, p + 4, sizeof v1);
    int64_t acc = MulAddLong(round_, static_cast<int32_t>(w0), v0);
    acc = MulAddLong(acc, static_cast<int32_t>(w1), v1);
    const uint32_t lo = static_cast<uint32_t>(acc), hi = static_cast<uint32_t>(acc >> 32);
    return static_cast<int32_t>((lo >> shift_) | (hi << (32u - shift_))) + backlash;
  }
  float v0, v1;
  __builtin_memcpy(&v0, p, sizeof v0);
  __builtin_memcpy(&v1, p + 4, sizeof v1);
  const float t = static_cast<float>(c.frac_q32) * (1.0f / 4294967296.0f);
  // The reference's 0.0f + (1 - t) * v0 differs from (1 - t) * v0 only in the sign of a zero,
  // which rounds to the same Q8 value.
  return FloatToQ8((1.0f - t) * v0 + t * v1) + backlash;
}

void WrapTracker::Init(int32_t pos_steps, int32_t origin_steps, uint32_t period_steps) {
  InvariantDivider d;
  d.Init(period_steps == 0 ? 1u : period_steps);
  Init(pos_steps, origin_steps, d);
}

}  // namespace volcomp
