// AxisLookup and WrapTracker preparation.
#include "volcomp/axis_lookup.hpp"

namespace volcomp {

Status AxisLookup::Init(const table::Axis1dView& view) {
  if (view.forward == nullptr) return Error::kNotReady;
  loc_.Init(view.dim);
  forward_ = view.forward;
  reverse_ = view.reverse != nullptr ? view.reverse : view.forward;
  backlash_q8_ = view.backlash_q8;
  frac_bits_ = view.frac_bits;
  period_steps_ = view.period_steps;
  origin_steps_ = view.dim.origin_steps;
  axis_ = view.axis;
  type_ = view.type;
  return Status::Ok();
}

void WrapTracker::Init(int32_t pos_steps, int32_t origin_steps, uint32_t period_steps) {
  period_ = period_steps == 0 ? 1 : period_steps;
  origin_ = origin_steps;
  int64_t o = (static_cast<int64_t>(pos_steps) - origin_) % period_;
  if (o < 0) o += period_;
  offset_ = static_cast<uint32_t>(o);
}

}  // namespace volcomp
