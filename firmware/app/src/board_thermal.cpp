// The thermal correction in the board's main loop.
#include "volcomp/firmware/board_thermal.hpp"

namespace volcomp::firmware {

void BoardThermal::Start(const BoardSettings& settings, Compensator* compensator, uint32_t now_ms) {
  channels_ = thermal::TemperatureChannels();
  for (uint8_t ch = 0; ch < thermal::kMaxChannels; ++ch) {
    // Validated settings: a refusal cannot happen; were it to, the channel stays unused.
    channels_.Configure(ch, settings.temperature[ch], now_ms).IgnoreError();
  }
  correction_ = thermal::ThermalCorrection();
  compensator_ = compensator;
  axis_count_ = settings.board.axis_count;
  for (uint8_t a = 0; a < table::kMaxAxes; ++a) {
    const AxisConfig& axis = settings.board.axis[a];
    const bool linear = a < axis_count_ && axis.kind == table::AxisKind::kLinear;
    resolution_pm_[a] = linear ? axis.resolution_e9 : 0;  // mm per step x 1e9 = pm per step
    terms_[a] = thermal::ThermalTermSteps();
  }
  saturated_ = 0;
  unconfigured_ = 0;
  last_period_ms_ = now_ms;
  compensator_->PublishThermal(terms_, table::kMaxAxes);
}

void BoardThermal::SetModel(const table::TableView& image) {
  if (image.thermal == nullptr) {
    correction_.Clear();
    return;
  }
  // ParseImage() validated the section as ValidateThermalModel() does: Configure() takes it.
  if (!correction_.Configure(table::ReadThermal(image.thermal), kThermalPeriodMs).ok())
    correction_.Clear();
}

void BoardThermal::ClearModel() { correction_.Clear(); }

ThermalEvents BoardThermal::Poll(uint32_t now_ms, hal::TemperatureInputs* sensors) {
  ThermalEvents events;
  const uint32_t since = now_ms - last_period_ms_;
  if (since < kThermalPeriodMs) return events;
  last_period_ms_ = since < 2 * kThermalPeriodMs ? last_period_ms_ + kThermalPeriodMs : now_ms;
  if (sensors != nullptr) {
    for (uint8_t ch = 0; ch < thermal::kMaxChannels; ++ch) {
      const thermal::ChannelSource source = channels_.config(ch).source;
      int16_t value_cC;
      // A configured channel: Reading() cannot refuse it.
      if (hal::IsBoardSensor(source) && sensors->Take(ch, source, &value_cC))
        channels_.Reading(ch, value_cC, now_ms).IgnoreError();
    }
  }
  channels_.Supervise(now_ms);
  events.channels = channels_.TakeEvents();
  correction_.Update(channels_);
  uint8_t unused = 0;
  for (uint8_t ch = 0; ch < thermal::kMaxChannels; ++ch) {
    if (channels_.state(ch) == thermal::ChannelState::kUnused)
      unused = static_cast<uint8_t>(unused | 1u << ch);
  }
  const uint8_t unconfigured = correction_.model_channels() & unused;
  events.channels.faulted |= static_cast<uint8_t>(unconfigured & ~unconfigured_);
  events.channels.recovered |= static_cast<uint8_t>(unconfigured_ & ~unconfigured);
  unconfigured_ = unconfigured;
  uint8_t saturated = 0;
  for (uint8_t a = 0; a < axis_count_; ++a) {
    if (resolution_pm_[a] == 0) continue;
    if (!thermal::ToSteps(correction_, a, resolution_pm_[a], &terms_[a]))
      saturated = static_cast<uint8_t>(saturated | 1u << a);
  }
  events.saturated = static_cast<uint8_t>(saturated & ~saturated_);
  events.unsaturated = static_cast<uint8_t>(saturated_ & ~saturated);
  saturated_ = saturated;
  compensator_->PublishThermal(terms_, table::kMaxAxes);
  return events;
}

}  // namespace volcomp::firmware
