// Board-local temperature sensors on ADC inputs (issue 23, docs/thermal.md "Board-local
// sensors"): an NTC thermistor or a PT1000 in a ratiometric divider, its ADC counts averaged and
// converted to a channel reading (centi-degrees C, temperature_channels.hpp).
//
// The divider: a reference resistor from the ADC's reference voltage (VREF+ / VDDA) to the input
// pin, the sensor from the pin to ground. The ADC measures against the same reference, so the
// reading does not depend on it: counts / full_scale = R_sensor / (R_ref + R_sensor), hence
// R_sensor = R_ref * counts / (full_scale - counts).
//
// Open and short circuit: an open sensor pulls the pin to the reference (counts near full scale),
// a short to ground (counts near 0); within kRailMarginPermille of either end the conversion gives
// kNoReading_cC, which the channel takes as out of range. So does a temperature outside int16 cC.
//
// Conversions (no libm: the core links without a C library):
//   NTC, beta model:  1/T = 1/T0 + ln(R/R0)/B       (T in kelvin; R0 at T0, usually 25 C)
//   PT1000, IEC 60751 (Callendar-Van Dusen):  R = R0 (1 + A t + B t^2 + C (t - 100) t^3),
//     C = 0 for t >= 0; A = 3.9083e-3, B = -5.775e-7, C = -4.183e-12; inverted by Newton's method.
// Main-loop code (a reading per second or so): float arithmetic and divisions are fine here, never
// on the tick path.
#pragma once

#include <cstdint>

#include "volcomp/thermal/temperature_channels.hpp"

namespace volcomp::thermal {

/// Counts this close to 0 or to full scale (per mille of full scale) are an open or short circuit.
inline constexpr uint32_t kRailMarginPermille = 5;

struct DividerInput {
  uint32_t full_scale_counts = 65536;  // the averaged ADC's full scale (16-bit oversampled)
  float reference_ohm = 10000.0f;      // R_ref, from the reference voltage to the pin
};

struct NtcParams {
  float r0_ohm = 10000.0f;  // resistance at t0_c
  float beta_k = 3950.0f;   // B constant, kelvin
  float t0_c = 25.0f;
};

struct Pt1000Params {
  float r0_ohm = 1000.0f;  // resistance at 0 C (1000 for a PT1000, 100 for a PT100)
};

/// The sensor's resistance from averaged counts; a negative value on an open or short circuit
/// (within kRailMarginPermille of either end, or counts >= full scale).
float SensorOhms(uint32_t counts, const DividerInput& divider);

/// Natural logarithm of x > 0 to about 1e-7 relative (float), without libm; x <= 0 gives a
/// large negative number.
float Ln(float x);

/// Temperature of an NTC of resistance `ohms`, cC (rounded); kNoReading_cC for ohms <= 0 or a
/// result outside int16.
int16_t NtcCelsius_cC(float ohms, const NtcParams& ntc);
/// Temperature of a platinum sensor of resistance `ohms`, cC (rounded) over -200..+850 C (IEC
/// 60751's range); kNoReading_cC for ohms <= 0 or outside it.
int16_t PlatinumCelsius_cC(float ohms, const Pt1000Params& pt);

/// Averages raw ADC samples into one reading every `samples` samples (a boxcar: noise drops by
/// sqrt(samples), a 50 Hz mains hum averages out when the window spans whole periods).
class AdcAverager {
 public:
  /// samples: 1..65535; 0 is taken as 1.
  explicit AdcAverager(uint16_t samples = 100) : samples_(samples == 0 ? 1 : samples) {}
  /// Adds one sample; true when a window is complete: *mean_counts is its mean (rounded).
  bool Add(uint32_t counts, uint32_t* mean_counts);

 private:
  uint16_t samples_;
  uint16_t count_ = 0;
  uint64_t sum_ = 0;
};

}  // namespace volcomp::thermal
