#include "volcomp/thermal/thermal_term.hpp"

namespace volcomp::thermal {
namespace {

// Rounds v to the nearest integer within [-limit, limit]; *fits false when it had to saturate.
int32_t Saturate(float v, float limit, bool* fits) {
  if (!(v <= limit)) {  // also NaN
    *fits = false;
    return static_cast<int32_t>(limit);
  }
  if (v < -limit) {
    *fits = false;
    return -static_cast<int32_t>(limit);
  }
  return static_cast<int32_t>(v < 0.0f ? v - 0.5f : v + 0.5f);
}

}  // namespace

bool ToSteps(const ThermalCorrection& correction,
             uint8_t a,
             uint32_t resolution_pm,
             ThermalTermSteps* out) {
  bool fits = resolution_pm > 0;
  const float steps_per_um = fits ? 1.0e6f / static_cast<float>(resolution_pm) : 0.0f;
  // um -> steps -> Q24.8; um/mm = 1e-3 steps per step (both lengths in steps) -> Q0.32; mm ->
  // steps.
  out->offset_q8 = Saturate(correction.applied_offset_um(a) * steps_per_um * 256.0f,
                            static_cast<float>(kMaxThermalOffset_q8), &fits);
  out->slope_q32 = Saturate(correction.applied_slope_um_per_mm(a) * 1.0e-3f * 4294967296.0f,
                            static_cast<float>(kMaxThermalSlope_q32), &fits);
  out->p0_steps = Saturate(correction.applied_p0_mm(a) * 1000.0f * steps_per_um,
                           static_cast<float>(kMaxThermalP0_steps), &fits);
  return fits;
}

}  // namespace volcomp::thermal
