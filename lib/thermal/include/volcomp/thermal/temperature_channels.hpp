// The board's temperature channels (issue 23, docs/thermal.md): up to kMaxChannels inputs, each
// fed by one source (a CANopen object the CNC's PLC or a temperature module writes, a board-local
// sensor, the simulator), supervised so that a thermal correction never rests on a reading it
// should not trust.
//
// Units: temperatures in centi-degrees Celsius (`_cC`, int16: -327.67..+327.67 C, 0.01 K: finer
// than a DS18B20's 0.0625 K or a MAX31865's 0.03125 K), times in milliseconds of the board's
// monotonic clock (uint32, wraps after 49 days; every comparison is a wrapping difference).
//
// A channel's state, what a user reads (docs/thermal.md, "Channel states"):
//   kUnused          no source configured; readings are refused
//   kWaiting         configured, no reading yet (for up to its timeout)
//   kValid           the last reading was accepted: value_cC() is that reading
//   kStale           no reading for longer than the timeout (a writer that stopped, a dead bus)
//   kOutOfRange      the last reading was outside [low_cC, high_cC] or the source's "no reading"
//                    value (kNoReading_cC: an open or short-circuited sensor)
//   kImplausibleRate the reading moved faster than max_rate_cC_s from the one before it
//   kStuck           stuck_samples readings in a row were exactly equal (a frozen converter;
//                    only for sources whose readings carry noise, 0 = off)
// In every fault state value_cC() holds the last accepted reading. A fault clears after
// kRecoveryReadings readings in a row that pass every check (so one spike never enters the value,
// and a real step of the temperature, e.g. a replaced sensor, is taken once it is steady); the
// first reading after kWaiting is taken at once when it is in range.
//
// Fault onsets and recoveries are reported once each through TakeEvents() (the board turns them
// into an EMCY and a status flag) and counted per channel (fault_count()).
//
// Threading: one context (the board's main loop); no allocation, no division, no floating point.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"

namespace volcomp::thermal {

inline constexpr uint8_t kMaxChannels = 8;
/// What a source writes when it has no reading (sensor open or shorted, converter fault): int16's
/// lowest value, 0x8000, never a temperature.
inline constexpr int16_t kNoReading_cC = INT16_MIN;
/// Readings in a row that must pass every check before a faulted channel is valid again.
inline constexpr uint8_t kRecoveryReadings = 3;
/// Allowance on top of the rate limit for a source's quantisation and noise (0.25 K), so that
/// two readings a few milliseconds apart one resolution step apart are not "implausible".
inline constexpr int32_t kRateSlack_cC = 25;

enum class ChannelSource : uint8_t {
  kNone = 0,         // channel unused
  kCanObject = 1,    // written over CANopen (SDO or RPDO) by the CNC's PLC or a module
  kBoardNtc = 2,     // an NTC thermistor on a board ADC input
  kBoardPt1000 = 3,  // a PT1000 on a board ADC input
  kLinuxFile = 4,    // a Linux board's hwmon / 1-Wire sysfs file
  kSimulated = 5,    // the host simulator's sensor model
};
inline constexpr uint8_t kLastChannelSource = 5;

enum class ChannelState : uint8_t {
  kUnused = 0,
  kWaiting = 1,
  kValid = 2,
  kStale = 3,
  kOutOfRange = 4,
  kImplausibleRate = 5,
  kStuck = 6,
};

/// Readable name of a state, e.g. "stale". Never null.
const char* ChannelStateName(ChannelState s);

/// True for the states in which the channel's value is not current (held).
constexpr bool IsFault(ChannelState s) {
  return s == ChannelState::kStale || s == ChannelState::kOutOfRange ||
         s == ChannelState::kImplausibleRate || s == ChannelState::kStuck;
}

struct ChannelConfig {
  ChannelSource source = ChannelSource::kNone;
  /// Stale after this long without a reading, 100..60000 ms. The default suits a source that
  /// reports at 1 Hz: a stopped source is detected within timeout + the supervision period
  /// (Supervise() at 10 Hz: 1.6 s).
  uint16_t timeout_ms = 1500;
  /// Plausible range; a reading outside it is an open or short circuit (an NTC or PT1000 divider
  /// reads far outside any machine temperature when either happens). low_cC < high_cC.
  int16_t low_cC = -2000;  // -20 C
  int16_t high_cC = 9000;  // +90 C
  /// Fastest plausible change, cC per second, >= 1 (a machine's structure changes by a few K per
  /// hour, a spindle housing by well under 1 K/s).
  uint16_t max_rate_cC_s = 100;  // 1 K/s
  /// Readings in a row exactly equal that mean a frozen source, 2..255; 0 = off (a PLC may write
  /// the same value for minutes: only for sources whose raw readings carry noise).
  uint8_t stuck_readings = 0;
};

/// kOk, or kInvalidArgument when a field is outside the ranges above (source kNone is valid: the
/// channel is unused and the other fields are not checked).
Status ValidateChannelConfig(const ChannelConfig& c);

/// What TakeEvents() returns: bit n = channel n.
struct ChannelEvents {
  uint8_t faulted = 0;    // entered a fault state (from kWaiting or kValid)
  uint8_t recovered = 0;  // became valid again after a fault
};

class TemperatureChannels {
 public:
  /// Sets channel `ch`'s source and limits and restarts it at `now_ms` (kWaiting, or kUnused for
  /// source kNone; its value 0 and its fault count 0). kInvalidArgument for ch >= kMaxChannels or
  /// a config ValidateChannelConfig() refuses (the channel is left as it was).
  Status Configure(uint8_t ch, const ChannelConfig& config, uint32_t now_ms);

  /// A reading of channel `ch` from its source at `now_ms` (kNoReading_cC when the source has
  /// none). kNotFound for ch >= kMaxChannels, kNotReady for an unused channel (the reading is
  /// dropped); otherwise kOk, whatever the checks decide (the state says).
  Status Reading(uint8_t ch, int16_t value_cC, uint32_t now_ms);

  /// Detects stale channels at `now_ms`; call it at least every 100 ms.
  void Supervise(uint32_t now_ms);

  /// Fault onsets and recoveries since the last call (each reported once).
  ChannelEvents TakeEvents();

  ChannelState state(uint8_t ch) const { return channel_[ch].state; }
  const ChannelConfig& config(uint8_t ch) const { return channel_[ch].config; }
  /// The last accepted reading (held through a fault; 0 before the first).
  int16_t value_cC(uint8_t ch) const { return channel_[ch].value_cC; }
  /// The last reading as the source sent it, accepted or not (kNoReading_cC before the first).
  int16_t last_reading_cC(uint8_t ch) const { return channel_[ch].prev_cC; }
  /// Fault onsets of the channel since Configure() (saturates at 65535).
  uint16_t fault_count(uint8_t ch) const { return channel_[ch].fault_count; }
  /// Bit n: channel n is kValid.
  uint8_t valid_mask() const;
  /// Bit n: channel n is in a fault state.
  uint8_t fault_mask() const;

 private:
  struct Channel {
    ChannelConfig config;
    ChannelState state = ChannelState::kUnused;
    int16_t value_cC = 0;
    int16_t prev_cC = kNoReading_cC;  // the previous reading (accepted or not)
    uint32_t prev_ms = 0;             // when it came (or Configure()'s time before the first)
    bool has_prev = false;
    uint8_t same_run = 0;  // readings in a row equal to the one before them
    uint8_t good_run = 0;  // readings in a row that passed every check, while faulted
    uint16_t fault_count = 0;
  };
  // The check a reading fails (kValid: none).
  ChannelState Check(const Channel& c, int16_t value_cC, uint32_t now_ms) const;
  void EnterFault(uint8_t ch, ChannelState fault);

  Channel channel_[kMaxChannels];
  ChannelEvents events_;
};

}  // namespace volcomp::thermal
