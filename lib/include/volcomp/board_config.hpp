// The board configuration: what the installation is (axes, units per step, signal formats, drive
// timing, limits). It is set by the integrator, stored on the board, and never changed by a table:
// a table may only be activated if it was built for the same axes and units per step, and the
// limits here (maximum correction, rate, acceleration) bound whatever a table asks for.
#pragma once

#include <cstdint>

#include "volcomp/status.hpp"
#include "volcomp/table_format.hpp"
#include "volcomp/table_image.hpp"

namespace volcomp {

/// Signal format of a step input or output.
enum class PulseFormat : uint8_t {
  kStepDir = 0,     // step pulse + direction level
  kCwCcw = 1,       // pulse on CW line = +1, pulse on CCW line = -1
  kQuadrature = 2,  // A/B quadrature, 4 counts per cycle (each edge is one step)
};

/// Timing the drive needs on its step/dir inputs (from its datasheet), in nanoseconds.
struct DriveTiming {
  uint32_t pulse_width_ns = 2500;  // minimum step high time
  uint32_t step_space_ns = 2500;   // minimum step low time
  uint32_t dir_setup_ns = 5000;    // direction change -> next step edge
  uint32_t dir_hold_ns = 10000;    // step edge -> direction change
  uint32_t max_rate_hz = 200000;   // maximum step rate the drive accepts
};

struct AxisConfig {
  char name = 'X';
  table::AxisKind kind = table::AxisKind::kLinear;
  uint32_t resolution_e9 = 1000000;  // units per step x 1e9 (pm/step or ndeg/step)
  PulseFormat input_format = PulseFormat::kStepDir;
  PulseFormat output_format = PulseFormat::kStepDir;
  bool invert_input_dir = false;
  uint8_t input_counter_bits = 32;  // width of the hardware input counter (16 or 32)
  DriveTiming drive;
  uint32_t max_input_rate_hz = 1000000;             // fastest input step rate to accept
  int32_t max_correction_steps = 1000;              // |applied correction| bound
  uint32_t max_correction_rate_steps_s = 2000;      // correction velocity limit
  uint32_t max_correction_accel_steps_s2 = 200000;  // correction acceleration limit
  int32_t home_position_steps = 0;  // machine position assigned at the home (reference) edge
};

/// Control tick rates ValidateBoardConfig accepts.
inline constexpr uint32_t kMinTickHz = 1000;
inline constexpr uint32_t kMaxTickHz = 200000;

struct BoardConfig {
  uint32_t tick_hz = 50000;              // control tick rate
  uint32_t pulse_clock_hz = 1000000000;  // output pulse timer clock (ns resolution in the mock)
  uint8_t axis_count = 3;
  AxisConfig axis[table::kMaxAxes];
};

/// Checks ranges and consistency (rates versus tick, timing versus rate); kConfigInvalid if bad.
Status ValidateBoardConfig(const BoardConfig& config);

/// Checks that an image was built for this board: axis count, names, kinds, units per step.
Status CheckImageMatchesBoard(const table::TableView& image, const BoardConfig& config);

/// The factory configuration: three linear axes X, Y, Z at 1 um/step, and on every axis drive
/// timing (200 ns pulses, 2 MHz) that keeps up with the 1 MHz input plus the correction rate. What
/// a board without stored settings runs with; od_entries.def takes the EDS defaults from it.
constexpr BoardConfig DefaultBoardConfig() {
  BoardConfig c;
  c.axis_count = 3;
  const char names[3] = {'X', 'Y', 'Z'};
  for (uint32_t i = 0; i < table::kMaxAxes; ++i) {
    c.axis[i] = AxisConfig();
    if (i < 3) c.axis[i].name = names[i];
    c.axis[i].drive.pulse_width_ns = 200;
    c.axis[i].drive.step_space_ns = 200;
    c.axis[i].drive.dir_setup_ns = 200;
    c.axis[i].drive.dir_hold_ns = 200;
    c.axis[i].drive.max_rate_hz = 2000000;
  }
  return c;
}

}  // namespace volcomp
