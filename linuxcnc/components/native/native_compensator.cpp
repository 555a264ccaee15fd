// Native compensation: configuration from the image, lookup and limiter from lib/.
#include "native/native_compensator.hpp"

#include <cmath>
#include <cstdlib>
#include <utility>

#include "volcomp/table/table_format.hpp"
#include "volcomp/table/table_image.hpp"

namespace volcomp::linuxcnc {

Status NativeCompensator::Load(std::vector<uint8_t> image,
                               uint32_t tick_hz,
                               const NativeLimits& limits) {
  const Result<table::TableView> view = table::ParseImage(image.data(), image.size());
  if (!view.ok()) return view.status();
  if (view->axis_count > kMaxJoints) return Error::kConfigTooManyAxes;
  BoardConfig c;
  c.tick_hz = tick_hz;
  c.pulse_clock_hz = 1000000000u;
  c.axis_count = view->axis_count;
  for (uint8_t a = 0; a < c.axis_count; ++a) {
    AxisConfig& x = c.axis[a];
    x = AxisConfig();
    x.name = view->axes[a].name;
    x.kind = view->axes[a].kind;
    x.resolution_e9 = view->axes[a].resolution_e9;
    x.max_correction_steps = limits.max_correction_steps;
    x.max_correction_rate_steps_s = limits.rate_steps_s;
    x.max_correction_accel_steps_s2 = limits.accel_steps_s2;
    // No step generation here: input and output rates only need to pass the board's checks.
    x.max_input_rate_hz = 1;
    x.drive.max_rate_hz = 1 + limits.rate_steps_s;
  }
  if (loaded_) {
    // A reload keeps the axes and limits in force: the table must be for the same machine.
    if (c.axis_count != config_.axis_count) return Error::kConfigAxisMismatch;
    for (uint8_t a = 0; a < c.axis_count; ++a) {
      if (c.axis[a].name != config_.axis[a].name ||
          c.axis[a].resolution_e9 != config_.axis[a].resolution_e9) {
        return Error::kConfigAxisMismatch;
      }
    }
    c = config_;
  } else {
    VOLCOMP_TRY(comp_.Configure(c, /*ticks_per_run=*/1));  // Run() every servo period
  }
  // The view the prepared table uses points into the bytes: prepare on the vector that keeps them.
  PreparedTable t;
  VOLCOMP_TRY(t.Prepare(*view, c));
  const int slot = loaded_ ? 1 - active_ : 0;
  image_[slot] = std::move(image);  // a moved vector keeps its buffer: the view stays valid
  table_ = t;
  config_ = c;
  comp_.SetTable(table_, last_steps_);
  active_ = slot;
  loaded_ = true;
  return Status::Ok();
}

void NativeCompensator::Tick(const double* pos_mm,
                             bool enable,
                             bool referenced,
                             double* correction_mm) {
  const uint8_t n = config_.axis_count;
  for (uint8_t a = 0; a < n; ++a) {
    last_steps_[a] = static_cast<int32_t>(std::lround(pos_mm[a] / mm_per_step(a)));
  }
  comp_.SetEnabled(enable);
  comp_.SetReferenced(referenced);
  int32_t whole[table::kMaxAxes];
  comp_.Run(last_steps_, whole);
  bool reverse[table::kMaxAxes] = {};
  for (uint8_t a = 0; a < n; ++a) reverse[a] = comp_.reverse(a);
  int32_t wanted_q8[table::kMaxAxes] = {};
  table_.TargetsQ8(last_steps_, last_steps_, reverse, n, wanted_q8);
  clamped_ = false;
  for (uint8_t a = 0; a < n; ++a) {
    const int64_t max_q8 = int64_t{config_.axis[a].max_correction_steps}
                           << table::kCorrectionFracBits;
    if (comp_.engaged() && std::llabs(wanted_q8[a]) > max_q8) clamped_ = true;
    correction_mm[a] =
        comp_.applied_q8(a) / double(1 << table::kCorrectionFracBits) * mm_per_step(a);
  }
}

}  // namespace volcomp::linuxcnc
