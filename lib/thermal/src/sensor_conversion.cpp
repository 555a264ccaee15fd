// ADC counts to temperatures: divider, NTC beta model, IEC 60751 platinum sensors.
#include "volcomp/thermal/sensor_conversion.hpp"

namespace volcomp::thermal {
namespace {

constexpr float kKelvinAtZeroC = 273.15f;
// IEC 60751 coefficients.
constexpr float kPtA = 3.9083e-3f;
constexpr float kPtB = -5.775e-7f;
constexpr float kPtC = -4.183e-12f;

int16_t Rounded_cC(float celsius) {
  const float v = celsius * 100.0f;
  if (!(v > -32767.5f && v < 32767.5f)) return kNoReading_cC;  // also NaN
  return static_cast<int16_t>(v >= 0.0f ? v + 0.5f : v - 0.5f);
}

}  // namespace

float SensorOhms(uint32_t counts, const DividerInput& divider) {
  const uint32_t full = divider.full_scale_counts;
  const uint64_t margin = uint64_t{full} * kRailMarginPermille / 1000;
  if (counts <= margin || uint64_t{counts} + margin >= full) return -1.0f;
  return divider.reference_ohm * static_cast<float>(counts) / static_cast<float>(full - counts);
}

float Ln(float x) {
  if (!(x > 0.0f)) return -1.0e30f;
  uint32_t bits;
  __builtin_memcpy(&bits, &x, sizeof bits);
  int32_t e = static_cast<int32_t>((bits >> 23) & 0xFFu) - 127;
  bits = (bits & 0x007FFFFFu) | 0x3F800000u;  // mantissa m in [1, 2)
  float m;
  __builtin_memcpy(&m, &bits, sizeof m);
  if (m > 1.41421356f) {  // m in [0.707, 1.414]: |s| <= 0.172 below
    m *= 0.5f;
    ++e;
  }
  // ln m = 2 atanh(s), s = (m - 1) / (m + 1): the series to s^9 leaves < 1e-9.
  const float s = (m - 1.0f) / (m + 1.0f);
  const float s2 = s * s;
  const float series =
      s * (1.0f + s2 * (1.0f / 3 + s2 * (1.0f / 5 + s2 * (1.0f / 7 + s2 * (1.0f / 9)))));
  return static_cast<float>(e) * 0.69314718f + 2.0f * series;
}

int16_t NtcCelsius_cC(float ohms, const NtcParams& ntc) {
  if (!(ohms > 0.0f) || !(ntc.r0_ohm > 0.0f) || !(ntc.beta_k > 0.0f)) return kNoReading_cC;
  const float inv_t = 1.0f / (ntc.t0_c + kKelvinAtZeroC) + Ln(ohms / ntc.r0_ohm) / ntc.beta_k;
  if (!(inv_t > 0.0f)) return kNoReading_cC;
  return Rounded_cC(1.0f / inv_t - kKelvinAtZeroC);
}

int16_t PlatinumCelsius_cC(float ohms, const Pt1000Params& pt) {
  if (!(ohms > 0.0f) || !(pt.r0_ohm > 0.0f)) return kNoReading_cC;
  const float ratio = ohms / pt.r0_ohm;
  if (!(ratio >= 0.18f && ratio <= 3.91f)) return kNoReading_cC;  // -200 .. +850 C
  // Newton's method on ratio(t) from the linear guess; four steps reach float precision.
  float t = (ratio - 1.0f) / kPtA;
  for (int i = 0; i < 4; ++i) {
    const float c = t < 0.0f ? kPtC : 0.0f;
    const float f = 1.0f + t * (kPtA + t * kPtB) + c * (t - 100.0f) * t * t * t - ratio;
    const float df = kPtA + 2.0f * kPtB * t + c * (4.0f * t - 300.0f) * t * t;
    t -= f / df;
  }
  if (!(t >= -200.0f && t <= 850.0f)) return kNoReading_cC;
  return Rounded_cC(t);
}

bool AdcAverager::Add(uint32_t counts, uint32_t* mean_counts) {
  sum_ += counts;
  if (++count_ < samples_) return false;
  *mean_counts = static_cast<uint32_t>((sum_ + samples_ / 2) / samples_);
  sum_ = 0;
  count_ = 0;
  return true;
}

}  // namespace volcomp::thermal
