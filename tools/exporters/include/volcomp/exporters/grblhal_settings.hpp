// grblHAL backlash compensation settings ($160 …) from positioning tests (hobby_common.hpp has the
// backlash and its derivation). grblHAL core has no skew or pitch table (shared reference
// data-formats.md §B12).
//
// Format (grblHAL/core @f80fc34d): Setting_AxisBacklash = Setting_AxisSettingsBase (100) +
// 6 × AXIS_SETTINGS_INCREMENT (10) = 160, plus the axis index X 0, Y 1, Z 2, A 3, B 4, C 5, U 6,
// V 7 (settings.h); so `$160=<X>`, `$161=<Y>`, … The unit is mm, deg on a rotary axis
// (settings.c), display format "#####0.000##"; the setting exists only in a build with
// ENABLE_BACKLASH_COMPENSATION (otherwise Status_SettingDisabled). mc_backlash_init
// (motion_control.c) rounds it to whole steps and adds it when the axis reverses. A line that
// starts with ';' is an empty block (gcode.c), so the notes are ';' lines; the `$` lines carry no
// comment (system_execute_line parses the whole line).
// Sign: b = −B̄ ≥ 0, the lost motion. grblHAL checks no range (no min/max in its settings table):
// ≥ 0 is inferred from its meaning; a negative b is refused.
// Values: 5 decimals (the display format's most). W is refused (grblHAL names 8 axes, XYZABCUV).
#pragma once

#include <string>
#include <vector>

#include "volcomp/exporters/hobby_common.hpp"
#include "volcomp/hosted/expected.hpp"

namespace volcomp::exporters {

inline constexpr int kGrblhalBacklashSetting = 160;  // $160 = X
inline constexpr const char* kGrblhalAxes = "XYZABCUV";

struct GrblhalSetting {
  char axis = 'X';
  int number = 0;    // $160 + axis index
  double value = 0;  // mm (deg)
};

struct GrblhalSettings {
  std::string text;
  std::vector<GrblhalSetting> settings;
};

/// kInvalidArgument naming the value and the limit: no axis, an axis outside XYZABCUV, b < 0.
Expected<GrblhalSettings> BuildGrblhalSettings(const std::vector<AxisBacklash>& backlash);

}  // namespace volcomp::exporters
