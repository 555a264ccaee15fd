// The temperature channels' board-local sensors on ADC inputs (docs/thermal.md, "Board-local
// sensors"): the averaging of the ADC's scans and the conversion to a reading, between an ADC
// driver that delivers oversampled counts (the STM32G474's: hal/stm32g4 temperature_adc.hpp) and
// BoardThermal, which takes the readings (hal::TemperatureInputs).
//
// Channel n (0-based) reads input n, n < kAdcSensorInputs; a channel's source says which sensor
// hangs on the input: kBoardNtc or kBoardPt1000 (for kLinuxFile, and channels beyond the inputs,
// there is nothing: those channels go stale). Every input is averaged, whatever its channel's
// source, over kAdcScansPerReading scans (a boxcar; at 100 scans per second a window of 0.5 s:
// 25 periods of 50 Hz hum, 30 of 60 Hz, both average out), so a reading per input every 0.5 s.
// The inputs' windows are staggered by a quarter window (input i joins at scan 12.5 i), so their
// readings come 120 ms or more apart and a thermal period (100 ms) converts one of them, not four
// (two after a main-loop stall).
//
// The hardware parameters are compile-time constants of the reference board here (namespace
// sensor_board): one reference resistor per input, the NTC and the platinum sensor they are
// sized for. Configurable parameters would be objects of their own.
//
// Main loop only (AddScan() and Take() in one context); no allocation.
#pragma once

#include <cstdint>

#include "volcomp/hal/temperature_inputs.hpp"
#include "volcomp/thermal/sensor_conversion.hpp"

namespace volcomp::firmware {

/// ADC inputs of the board (docs/mcu-target.md: PA4, PC4, PC5, PA5 on ADC2).
inline constexpr uint8_t kAdcSensorInputs = 4;
/// Scans averaged into one reading (at the driver's 100 scans per second: 2 readings per second).
inline constexpr uint16_t kAdcScansPerReading = 50;

namespace sensor_board {
/// The counts' full scale: 12-bit conversions, 256 summed by the ADC's oversampler and shifted
/// right by 4, i.e. the mean code x 16 (16-bit).
inline constexpr uint32_t kFullScaleCounts = 65536;
/// R_ref from VREF+ (= VDDA) to the pin, 10 kOhm 0.1 % 25 ppm/K: the NTC's R25 (mid-scale at
/// 25 C), and 0.3 mA (0.09 mW) through a PT1000.
inline constexpr float kReferenceOhm = 10000.0f;
/// NTC: 10 kOhm at 25 C, B25/50 = 3380 K (Murata NCP18XH103F03RB and its many equivalents); the
/// beta model with B25/50 is within 0.15 K of the maker's R-T table from 20 to 50 C, 0.4 K at
/// 10 C (AdcTemperatureInputs test).
inline constexpr thermal::NtcParams kNtc{10000.0f, 3380.0f, 25.0f};
/// PT1000 (IEC 60751 class A or B).
inline constexpr thermal::Pt1000Params kPt1000{1000.0f};
}  // namespace sensor_board

class AdcTemperatureInputs final : public hal::TemperatureInputs {
 public:
  /// One scan of every input: counts[i] of input i (full scale sensor_board::kFullScaleCounts).
  void AddScan(const uint16_t counts[kAdcSensorInputs]);

  /// The mean counts of input i's last complete window (0 before the first).
  uint32_t mean_counts(uint8_t input) const { return mean_[input]; }

  /// The reading for counts `mean` of a sensor of kind `source` (kBoardNtc or kBoardPt1000):
  /// centi-degrees C, kNoReading_cC for an open or shorted input or another source.
  static int16_t Convert(uint32_t mean, thermal::ChannelSource source);

 private:
  bool DoTake(uint8_t channel, thermal::ChannelSource source, int16_t* value_cC) override;

  static_assert(kAdcSensorInputs == 4, "one averager per input below");
  thermal::AdcAverager averager_[kAdcSensorInputs] = {
      thermal::AdcAverager(kAdcScansPerReading), thermal::AdcAverager(kAdcScansPerReading),
      thermal::AdcAverager(kAdcScansPerReading), thermal::AdcAverager(kAdcScansPerReading)};
  uint32_t mean_[kAdcSensorInputs] = {};
  uint8_t fresh_ = 0;  // bit i: input i completed a window since its channel's last Take()
  uint8_t scans_ = 0;  // scans since the start, up to kAdcScansPerReading (the stagger)
};

}  // namespace volcomp::firmware
