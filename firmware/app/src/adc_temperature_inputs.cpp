// Board-local sensors on ADC inputs: averaging and conversion.
#include "volcomp/firmware/adc_temperature_inputs.hpp"

namespace volcomp::firmware {

void AdcTemperatureInputs::AddScan(const uint16_t counts[kAdcSensorInputs]) {
  if (scans_ < kAdcScansPerReading) ++scans_;
  for (uint8_t i = 0; i < kAdcSensorInputs; ++i) {
    if (scans_ <= i * kAdcScansPerReading / kAdcSensorInputs) continue;  // not yet joined
    if (averager_[i].Add(counts[i], &mean_[i])) fresh_ = static_cast<uint8_t>(fresh_ | 1u << i);
  }
}

int16_t AdcTemperatureInputs::Convert(uint32_t mean, thermal::ChannelSource source) {
  thermal::DividerInput divider;
  divider.full_scale_counts = sensor_board::kFullScaleCounts;
  divider.reference_ohm = sensor_board::kReferenceOhm;
  const float ohms = thermal::SensorOhms(mean, divider);
  switch (source) {
    case thermal::ChannelSource::kBoardNtc:
      return thermal::NtcCelsius_cC(ohms, sensor_board::kNtc);
    case thermal::ChannelSource::kBoardPt1000:
      return thermal::PlatinumCelsius_cC(ohms, sensor_board::kPt1000);
    default:
      return thermal::kNoReading_cC;
  }
}

bool AdcTemperatureInputs::DoTake(uint8_t channel,
                                  thermal::ChannelSource source,
                                  int16_t* value_cC) {
  // No Linux file on this board, no input beyond the ADC's: nothing (the channel goes stale).
  if (channel >= kAdcSensorInputs || (source != thermal::ChannelSource::kBoardNtc &&
                                      source != thermal::ChannelSource::kBoardPt1000)) {
    return false;
  }
  const uint8_t bit = static_cast<uint8_t>(1u << channel);
  if ((fresh_ & bit) == 0) return false;
  fresh_ = static_cast<uint8_t>(fresh_ & ~bit);
  *value_cC = Convert(mean_[channel], source);
  return true;
}

}  // namespace volcomp::firmware
