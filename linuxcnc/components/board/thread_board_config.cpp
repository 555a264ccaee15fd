// The component's board configuration (see the header).
#include "board/thread_board_config.hpp"

namespace volcomp::linuxcnc {

BoardConfig ThreadBoardConfig(const ThreadBoardParams& params, uint32_t period_ns) {
  BoardConfig c;
  c.tick_hz = static_cast<uint32_t>(1000000000ull / (uint64_t{kPeriodsPerTick} * period_ns));
  c.pulse_clock_hz = 1000000000u;
  c.axis_count = 3;
  const char names[3] = {'X', 'Y', 'Z'};
  for (uint8_t a = 0; a < c.axis_count; ++a) {
    AxisConfig& x = c.axis[a];
    x = AxisConfig();
    x.name = names[a];
    x.resolution_e9 = params.resolution_nm * 1000u;
    x.invert_input_dir = params.invert_input_dir;
    x.drive.pulse_width_ns = period_ns;
    x.drive.step_space_ns = period_ns;
    x.drive.dir_setup_ns = period_ns;
    x.drive.dir_hold_ns = period_ns;
    x.drive.max_rate_hz = c.tick_hz;
    x.max_correction_steps = params.max_correction_steps;
    x.max_correction_rate_steps_s = params.correction_rate_steps_s;
    x.max_correction_accel_steps_s2 = params.correction_accel_steps_s2;
    // No input capacity left when the correction rate takes the whole tick rate: 0, which the
    // firmware refuses.
    x.max_input_rate_hz = c.tick_hz > params.correction_rate_steps_s
                              ? c.tick_hz - params.correction_rate_steps_s
                              : 0u;
    x.home_position_steps = params.home_position_steps[a];
  }
  return c;
}

}  // namespace volcomp::linuxcnc
