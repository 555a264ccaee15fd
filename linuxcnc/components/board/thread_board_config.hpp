// The configuration the `volcomp_board` component gives the firmware for LinuxCNC's base thread:
// three linear axes X, Y, Z with step/dir inputs and outputs; a control tick of
// kPeriodsPerTick base periods; drive timing (pulse width, step space, direction setup and hold)
// of one base period, the shortest the sampled output renders without losing a pulse
// (hal_step_io.hpp); output rate limit = tick rate (one whole pulse per tick); input rate limit =
// tick rate − correction rate (what the output can carry on top of the correction).
//
// The firmware validates it (ValidateSettings) and its devices check it against the thread
// (HalStepIo::Configure, ThreadTickTimer::SetRate): nothing here is clamped.
#pragma once

#include <cstdint>

#include "volcomp/config/board_config.hpp"

namespace volcomp::linuxcnc {

/// Base periods per control tick: a whole output pulse (high and low phase of one period each).
inline constexpr uint32_t kPeriodsPerTick = 2;

/// The component's load parameters that shape the configuration.
struct ThreadBoardParams {
  uint32_t resolution_nm = 1000;  // X, Y and Z, nm per step (must match the table)
  bool invert_input_dir = true;   // DIR input high = negative (LinuxCNC stepgen)
  int32_t max_correction_steps = 1000;
  uint32_t correction_rate_steps_s = 2000;
  uint32_t correction_accel_steps_s2 = 200000;
  int32_t home_position_steps[3] = {0, 0, 0};  // X, Y, Z: machine position at the home edge
};

/// The configuration for a base thread of `period_ns` (> 0). Its tick_hz is
/// 1e9 / (kPeriodsPerTick x period_ns) rounded down: a period for which that is not a whole
/// number is refused later by the tick timer, visibly.
BoardConfig ThreadBoardConfig(const ThreadBoardParams& params, uint32_t period_ns);

}  // namespace volcomp::linuxcnc
