// Temperature channel supervision.
#include "volcomp/thermal/temperature_channels.hpp"

namespace volcomp::thermal {

const char* ChannelStateName(ChannelState s) {
  switch (s) {
    case ChannelState::kUnused:
      return "unused";
    case ChannelState::kWaiting:
      return "waiting";
    case ChannelState::kValid:
      return "valid";
    case ChannelState::kStale:
      return "stale";
    case ChannelState::kOutOfRange:
      return "out of range";
    case ChannelState::kImplausibleRate:
      return "implausible rate";
    case ChannelState::kStuck:
      return "stuck";
  }
  return "unknown";
}

Status ValidateChannelConfig(const ChannelConfig& c) {
  if (c.source == ChannelSource::kNone) return Status::Ok();
  const bool ok = static_cast<uint8_t>(c.source) <= kLastChannelSource && c.timeout_ms >= 100 &&
                  c.timeout_ms <= 60000 && c.low_cC != kNoReading_cC && c.low_cC < c.high_cC &&
                  c.max_rate_cC_s >= 1 && c.stuck_readings != 1;
  return ok ? Status::Ok() : Status(Error::kInvalidArgument);
}

Status TemperatureChannels::Configure(uint8_t ch, const ChannelConfig& config, uint32_t now_ms) {
  if (ch >= kMaxChannels) return Error::kInvalidArgument;
  VOLCOMP_TRY(ValidateChannelConfig(config));
  Channel& c = channel_[ch];
  c = Channel();
  c.config = config;
  c.state = config.source == ChannelSource::kNone ? ChannelState::kUnused : ChannelState::kWaiting;
  c.prev_ms = now_ms;
  const uint8_t bit = static_cast<uint8_t>(1u << ch);
  events_.faulted &= static_cast<uint8_t>(~bit);
  events_.recovered &= static_cast<uint8_t>(~bit);
  return Status::Ok();
}

ChannelState TemperatureChannels::Check(const Channel& c, int16_t value_cC, uint32_t now_ms) const {
  const ChannelConfig& k = c.config;
  if (value_cC == kNoReading_cC || value_cC < k.low_cC || value_cC > k.high_cC) {
    return ChannelState::kOutOfRange;
  }
  if (!c.has_prev) return ChannelState::kValid;
  // |change| <= rate * dt + slack, in cC * ms (64-bit: a reading after a long gap).
  const int32_t change = value_cC - c.prev_cC;
  const int64_t moved = static_cast<int64_t>(change < 0 ? -change : change) * 1000;
  const int64_t allowed =
      static_cast<int64_t>(k.max_rate_cC_s) * (now_ms - c.prev_ms) + int64_t{kRateSlack_cC} * 1000;
  if (moved > allowed) return ChannelState::kImplausibleRate;
  if (k.stuck_readings != 0 && change == 0 && c.same_run + 2 >= k.stuck_readings) {
    return ChannelState::kStuck;
  }
  return ChannelState::kValid;
}

void TemperatureChannels::EnterFault(uint8_t ch, ChannelState fault) {
  Channel& c = channel_[ch];
  if (!IsFault(c.state)) {
    events_.faulted |= static_cast<uint8_t>(1u << ch);
    if (c.fault_count != UINT16_MAX) ++c.fault_count;
  }
  c.state = fault;
  c.good_run = 0;
}

Status TemperatureChannels::Reading(uint8_t ch, int16_t value_cC, uint32_t now_ms) {
  if (ch >= kMaxChannels) return Error::kNotFound;
  Channel& c = channel_[ch];
  if (c.state == ChannelState::kUnused) return Error::kNotReady;
  const ChannelState verdict = Check(c, value_cC, now_ms);
  const bool in_range = verdict != ChannelState::kOutOfRange;
  c.same_run = in_range && c.has_prev && value_cC == c.prev_cC
                   ? static_cast<uint8_t>(c.same_run + (c.same_run < UINT8_MAX))
                   : 0;
  c.prev_cC = value_cC;
  c.prev_ms = now_ms;
  c.has_prev = in_range;
  if (verdict != ChannelState::kValid) {
    EnterFault(ch, verdict);
    return Status::Ok();
  }
  if (IsFault(c.state)) {
    if (++c.good_run < kRecoveryReadings) return Status::Ok();
    events_.recovered |= static_cast<uint8_t>(1u << ch);
  }
  c.state = ChannelState::kValid;
  c.good_run = 0;
  c.value_cC = value_cC;
  return Status::Ok();
}

void TemperatureChannels::Supervise(uint32_t now_ms) {
  for (uint8_t ch = 0; ch < kMaxChannels; ++ch) {
    Channel& c = channel_[ch];
    if (c.state == ChannelState::kUnused || c.state == ChannelState::kStale) continue;
    if (now_ms - c.prev_ms > c.config.timeout_ms) EnterFault(ch, ChannelState::kStale);
  }
}

ChannelEvents TemperatureChannels::TakeEvents() {
  const ChannelEvents e = events_;
  events_ = ChannelEvents();
  return e;
}

uint8_t TemperatureChannels::valid_mask() const {
  uint8_t m = 0;
  for (uint8_t ch = 0; ch < kMaxChannels; ++ch) {
    if (channel_[ch].state == ChannelState::kValid) m |= static_cast<uint8_t>(1u << ch);
  }
  return m;
}

uint8_t TemperatureChannels::fault_mask() const {
  uint8_t m = 0;
  for (uint8_t ch = 0; ch < kMaxChannels; ++ch) {
    if (IsFault(channel_[ch].state)) m |= static_cast<uint8_t>(1u << ch);
  }
  return m;
}

}  // namespace volcomp::thermal
