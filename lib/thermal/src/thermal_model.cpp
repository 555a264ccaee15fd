// The thermal model's evaluation, its slew limit and its fault policy.
#include "volcomp/thermal/thermal_model.hpp"

namespace volcomp::thermal {
namespace {

bool Within(float v, float limit) { return v >= -limit && v <= limit; }  // false for NaN
float Abs(float v) { return v < 0.0f ? -v : v; }

}  // namespace

Status ValidateThermalModel(const ThermalModel& m) {
  if (m.axis_count < 1 || m.axis_count > kMaxModelAxes) return Error::kThermalBadAxisCount;
  // Range checks are false for NaN, so they also refuse values that are not finite.
  const bool ok = m.slew_um_s > 0.0f && m.slew_um_s <= kMaxSlew_um_s && m.hold_ms <= kMaxHold_ms;
  if (!ok) return Error::kThermalBadModel;
  for (uint8_t j = 0; j < kMaxChannels; ++j) {
    if (m.calibrated_low_cC[j] > m.calibrated_high_cC[j]) return Error::kThermalBadModel;
  }
  for (uint8_t a = 0; a < kMaxModelAxes; ++a) {
    const AxisModel& x = m.axis[a];
    if (!Within(x.p0_mm, kMaxPosition_mm) || !Within(x.reach_mm, kMaxPosition_mm) ||
        x.reach_mm < 0.0f) {
      return Error::kThermalBadModel;
    }
    for (uint8_t j = 0; j < kMaxChannels; ++j) {
      // Coefficients only on the channels the model uses, of the axes it has.
      const bool used = a < m.axis_count && ((m.channel_mask >> j) & 1u) != 0;
      const float o = x.offset_um_per_K[j], s = x.slope_um_per_K_m[j];
      if (!Within(o, kMaxThermalCoefficient) || !Within(s, kMaxThermalCoefficient) ||
          (!used && (o != 0.0f || s != 0.0f))) {
        return Error::kThermalBadModel;
      }
    }
  }
  return Status::Ok();
}

Status ThermalCorrection::Configure(const ThermalModel& model, uint32_t period_ms) {
  if (period_ms < 1 || period_ms > 1000) return Error::kInvalidArgument;
  VOLCOMP_TRY(ValidateThermalModel(model));
  // The applied terms carry over: a new model is approached at the slew limit, never jumped to. A
  // new p0 re-expresses the applied offset (O' = O + S (p0' - p0): the same correction at every
  // position); an axis keeps the larger of its reaches; axes the new model lacks fade out.
  for (uint8_t a = 0; a < model.axis_count; ++a) {
    offset_um_[a] += slope_um_mm_[a] * (model.axis[a].p0_mm - p0_mm_[a]);
    p0_mm_[a] = model.axis[a].p0_mm;
    if (model.axis[a].reach_mm > reach_mm_[a]) reach_mm_[a] = model.axis[a].reach_mm;
  }
  model_ = model;
  period_ms_ = period_ms;
  held_ms_ = 0;
  status_ = ThermalStatus();
  status_.active = true;
  return Status::Ok();
}

void ThermalCorrection::Clear() {
  status_.active = false;
  held_ms_ = 0;
}

void ThermalCorrection::Evaluate(const TemperatureChannels& channels) {
  float rise_K[kMaxChannels] = {};
  uint8_t unusable = 0;
  status_.fault_mask = 0;
  status_.outside_mask = 0;
  for (uint8_t j = 0; j < kMaxChannels; ++j) {
    if (((model_.channel_mask >> j) & 1u) == 0) continue;
    const ChannelState s = channels.state(j);
    if (s != ChannelState::kValid) unusable |= static_cast<uint8_t>(1u << j);
    if (IsFault(s)) status_.fault_mask |= static_cast<uint8_t>(1u << j);
    int16_t t = channels.value_cC(j);
    if (t < model_.calibrated_low_cC[j] || t > model_.calibrated_high_cC[j]) {
      status_.outside_mask |= static_cast<uint8_t>(1u << j);
      t = t < model_.calibrated_low_cC[j] ? model_.calibrated_low_cC[j]
                                          : model_.calibrated_high_cC[j];
    }
    rise_K[j] = static_cast<float>(t - model_.reference_cC[j]) * 0.01f;
  }
  status_.outside_mask &= static_cast<uint8_t>(~unusable);  // a held value is not "outside"
  for (uint8_t a = 0; a < kMaxModelAxes; ++a) {
    const AxisModel& x = model_.axis[a];  // zero coefficients beyond axis_count
    float offset = 0.0f, slope_per_m = 0.0f;
    for (uint8_t j = 0; j < kMaxChannels; ++j) {
      offset += x.offset_um_per_K[j] * rise_K[j];
      slope_per_m += x.slope_um_per_K_m[j] * rise_K[j];
    }
    model_offset_um_[a] = offset;
    model_slope_um_mm_[a] = slope_per_m * 0.001f;
  }
  // Hold, then fade: the slew goes toward the applied terms themselves (no change) while holding.
  if (unusable != 0) {
    held_ms_ = held_ms_ + period_ms_ < held_ms_ ? UINT32_MAX : held_ms_ + period_ms_;
  } else {
    held_ms_ = 0;
  }
  status_.holding = unusable != 0 && held_ms_ <= model_.hold_ms;
  status_.fading = unusable != 0 && !status_.holding;
}

void ThermalCorrection::Slew(const float* offset_um, const float* slope_um_mm) {
  const float max_change_um = model_.slew_um_s * static_cast<float>(period_ms_) * 0.001f;
  status_.slewing = false;
  for (uint8_t a = 0; a < kMaxModelAxes; ++a) {
    const float d_offset = offset_um[a] - offset_um_[a];
    const float d_slope = slope_um_mm[a] - slope_um_mm_[a];
    const float change = Abs(d_offset) + Abs(d_slope) * reach_mm_[a];
    float k = 1.0f;
    if (change > max_change_um) {
      k = max_change_um / change;
      status_.slewing = true;
    }
    offset_um_[a] += k * d_offset;
    slope_um_mm_[a] += k * d_slope;
  }
}

void ThermalCorrection::Update(const TemperatureChannels& channels) {
  static constexpr float kZero[kMaxModelAxes] = {};
  if (!status_.active) {
    Slew(kZero, kZero);
    return;
  }
  Evaluate(channels);
  if (status_.holding) return;
  if (status_.fading) {
    Slew(kZero, kZero);
  } else {
    Slew(model_offset_um_, model_slope_um_mm_);
  }
}

}  // namespace volcomp::thermal
