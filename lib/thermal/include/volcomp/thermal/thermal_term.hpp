// The thermal correction of one axis in the compensation run's units: the main loop converts the
// applied terms of ThermalCorrection (um, um/mm, mm) with the axis's resolution, and the run adds
//   offset_q8 + (slope_q32 * (position_steps - p0_steps)) >> 24          [Q24.8 steps]
// to the axis's table target before the clamp (docs/thermal.md, "In the compensation run").
// No division and no float in the run: the conversion (float, one division per axis) is done here,
// in the main loop, once per ThermalCorrection period.
#pragma once

#include <cstdint>

#include "volcomp/thermal/thermal_model.hpp"

namespace volcomp::thermal {

struct ThermalTermSteps {
  int32_t offset_q8 = 0;  // the correction at p0, Q24.8 steps
  int32_t slope_q32 = 0;  // the correction's change per step of travel, Q0.32 (steps per step)
  int32_t p0_steps = 0;   // where the slope term is zero, machine coordinates in steps
};

/// Bounds ToSteps() writes within, so that the run's term fits int32 without a 64-bit sum:
/// |offset_q8| <= 2^29 (2 097 152 steps, far beyond any board's maximum correction);
/// |slope_q32| <= 2^23 (2^-9 steps per step: 1953 um/m, six times the ISO 1 case of 11.5 um/(K m)
/// over 30 K); |p0_steps| <= 2^30. The run takes position - p0 modulo 2^32: the axis's positions
/// must stay within +-2^30 steps too (+-1.07 m at 1 nm per step), which every board axis does
/// that a step/dir drive can follow. Then |slope * (position - p0)| <= 2^22 steps.
inline constexpr int32_t kMaxThermalOffset_q8 = int32_t{1} << 29;
inline constexpr int32_t kMaxThermalSlope_q32 = int32_t{1} << 23;
inline constexpr int32_t kMaxThermalP0_steps = int32_t{1} << 30;

/// Axis `a`'s applied terms of `correction` for an axis of `resolution_pm` picometres per step
/// (> 0). Returns false, with the terms saturated at the bounds above, when a value does not fit
/// (or the resolution is 0); true otherwise. ValidateThermalModel() accepts coefficients up to
/// 1000 um/K and um/(K m), so a model can ask for more than fits: false means the board must not
/// apply it as it stands (the caller raises its fault and shows the saturated terms).
[[nodiscard]] bool ToSteps(const ThermalCorrection& correction,
                           uint8_t a,
                           uint32_t resolution_pm,
                           ThermalTermSteps* out);

}  // namespace volcomp::thermal
