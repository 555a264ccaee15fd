// Board-local temperature sensors (issue 23, docs/thermal.md "Board-local sensors"): the readings
// of the board's own inputs for the temperature channels whose source is one of them (an NTC or a
// PT1000 on an STM32 ADC input, a hwmon / 1-Wire file on the Linux board).
//
// The board's main loop pulls: every thermal period (100 ms) BoardThermal asks for each channel
// whose source is a board sensor (thermal::ChannelSource kBoardNtc, kBoardPt1000, kLinuxFile) and
// hands what it gets to the channel as a reading. The sampling itself (an ADC scan, a file read)
// runs beside it in the driver, at its own rate (>= 1 Hz); the data flows one way, from the HAL
// to the channels. A virtual call per channel and period (<= 80 per second, main loop only): the
// tick path never sees this interface.
//
// Channel n reads the board's input n (0-based: the CAN sub-index 0x2150:n+1). A board without
// such an input, or with an input of another kind, answers "nothing new": the channel stays
// waiting, then stale, and is flagged, never valid.
#pragma once

#include <cstdint>

#include "volcomp/thermal/temperature_channels.hpp"

namespace volcomp::hal {

class TemperatureInputs {
 public:
  /// The reading of channel `channel`'s input for a sensor of kind `source`, when the input has
  /// completed one since the last call for that channel: true and *value_cC (centi-degrees C;
  /// thermal::kNoReading_cC when the input has none: an open or shorted sensor, a file that is
  /// missing, unreadable or not a temperature). False when nothing new is there, or the board has
  /// no such input for that kind (the caller then leaves the channel as it is).
  bool Take(uint8_t channel, thermal::ChannelSource source, int16_t* value_cC) {
    return DoTake(channel, source, value_cC);
  }

 protected:
  ~TemperatureInputs() = default;  // not deletable through the interface (no heap in firmware)

 private:
  virtual bool DoTake(uint8_t channel, thermal::ChannelSource source, int16_t* value_cC) = 0;
};

/// True for the sources a board reads itself through TemperatureInputs.
constexpr bool IsBoardSensor(thermal::ChannelSource s) {
  return s == thermal::ChannelSource::kBoardNtc || s == thermal::ChannelSource::kBoardPt1000 ||
         s == thermal::ChannelSource::kLinuxFile;
}

}  // namespace volcomp::hal
