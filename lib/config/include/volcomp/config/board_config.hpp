// The board configuration: what the installation is (axes, units per step, signal formats, drive
// timing, limits). It is set by the integrator, stored on the board, and never changed by a table:
// a table may only be activated if it was built for the same axes and units per step, and the
// limits here (maximum correction, rate, acceleration) bound whatever a table asks for.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/limiter/correction_limiter.hpp"
#include "volcomp/table/table_format.hpp"
#include "volcomp/table/table_image.hpp"

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
  // The AXIS1D direction follows the drive: it turns to reverse once the output (command +
  // correction) has moved back more than this many steps from the furthest point reached forward,
  // and back the same way. 1 step ignores the one-step dither of the output's rounding at rest; a
  // reversal of h steps or less is not recognised, so it leaves at most h steps of lost motion.
  uint16_t direction_hysteresis_steps = 1;
  // A switch between the AXIS1D forward and reverse tables (the lost motion to take up once the
  // drive has reversed) moves the correction at this acceleration and at the rate the drive has
  // left beyond the fastest input (drive max rate - max input rate) instead of at the
  // correction's own limits, until the correction has caught up (docs/control-path.md,
  // "Direction switch"). 10^8 steps/s^2 (100 m/s^2 at 1 um/step): a 20-step dead band is taken
  // up in 0.9 ms, while a CNC axis accelerating at 10 m/s^2 moves 4 steps.
  uint32_t direction_switch_accel_steps_s2 = 100000000;
};

/// Control tick rates ValidateBoardConfig accepts.
inline constexpr uint32_t kMinTickHz = 1000;
inline constexpr uint32_t kMaxTickHz = 200000;

/// The compensator (sensing, the target refresh, the correction limiters) runs every
/// CompensationDivider(tick_hz) ticks, at tick_hz / divider <= kMaxCompensationHz; the step path
/// (counters, targets = commanded + correction, output) runs every tick. On the STM32 step/dir
/// board the two are separate interrupts (docs/mcu-target.md, "Two rates"); elsewhere
/// BoardApp::Tick() runs both in sequence. The limiters' units are converted at the compensation
/// rate (CorrectionLimiter::MakeParams()).
inline constexpr uint32_t kMaxCompensationHz = 20000;
constexpr uint32_t CompensationDivider(uint32_t tick_hz) {
  return tick_hz <= kMaxCompensationHz ? 1u
                                       : (tick_hz + kMaxCompensationHz - 1u) / kMaxCompensationHz;
}

struct BoardConfig {
  uint32_t tick_hz = 50000;              // control tick rate
  uint32_t pulse_clock_hz = 1000000000;  // output pulse timer clock (ns resolution in the mock)
  uint8_t axis_count = 3;
  AxisConfig axis[table::kMaxAxes];
};

/// The rules a configuration must keep, one per check of ValidateBoardConfig() (and of the node
/// settings, firmware ValidateSettings()); kConfigRuleTexts says each in words. Values are stable
/// (they travel in 0x2123): append, never renumber.
enum class ConfigRule : uint8_t {
  kNone = 0,
  kTickRate = 1,             // tick_hz within kMinTickHz..kMaxTickHz
  kPulseClock = 2,           // pulse clock >= 100 x tick rate
  kAxisCount = 3,            // 1..kMaxAxes axes
  kAxisName = 4,             // one of XYZABCUVW, each once
  kResolution = 5,           // units per step not zero
  kAxisKind = 6,             // linear or rotary
  kPulseFormat = 7,          // input/output pulse format 0..2
  kCounterBits = 8,          // input counter 16 or 32 bits
  kMaxCorrection = 9,        // max correction 0..table::kMaxCorrectionSteps
  kRateNotZero = 10,         // max input rate and drive max rate not zero
  kCounterWrap = 11,         // a 16-bit counter does not wrap by half within a tick
  kDriveKeepsUp = 12,        // max input rate + max correction rate <= drive max rate
  kLimiter = 13,             // correction rate/accel representable at the tick rate
  kNodeId = 14,              // node-ID 1..127
  kBitrate = 15,             // bit rate 10..1000 kbit/s
  kDirectionSwitch = 16,     // direction switch acceleration >= the correction's
  kPulseTiming = 17,         // step outputs: pulse width + step space allow the drive max rate
  kTemperatureChannel = 18,  // a temperature channel's source and limits (thermal::
                             // ValidateChannelConfig); ConfigFinding::axis = the channel, 1..8
  kCount = 19,
};

inline constexpr const char* kConfigRuleTexts[] = {
    "none",
    "tick rate must be 1000..200000 Hz",
    "pulse clock must be at least 100 x the tick rate",
    "axis count must be 1..6",
    "axis name must be one of XYZABCUVW and used once",
    "units per step (0x2012) must not be zero",
    "axis kind (0x2011) must be 0 linear or 1 rotary",
    "pulse format (0x2013/0x2014) must be 0..2",
    "input counter must be 16 or 32 bits",
    "max correction (0x2015) must be 0..65536 steps",
    "max input rate (0x201E) and drive max rate (0x201D) must not be zero",
    "a 16-bit input counter must not wrap by half its range within one tick",
    "max input rate (0x201E) + max correction rate (0x2016) must not exceed the drive max rate "
    "(0x201D)",
    "max correction rate (0x2016) and acceleration (0x2017) must fit the tick rate f: "
    "acceleration from f^2/2^32 to below f^2 steps/s2, rate at least acceleration/f steps/s",
    "node-ID must be 1..127",
    "bit rate must be 10..1000 kbit/s",
    "direction switch acceleration (0x2020) must be at least the max correction accel (0x2017)",
    "on a step output, drive pulse width (0x2019) + step space (0x201A) must allow the drive max "
    "rate (0x201D): together at most 1e9 / rate ns",
    "temperature channel: source 0..5, timeout 100..60000 ms, low below high (and not -327.68 C), "
    "max rate at least 0.01 K/s, stuck readings 0 (off) or 2..255",
};
static_assert(sizeof(kConfigRuleTexts) / sizeof(kConfigRuleTexts[0]) ==
                  static_cast<size_t>(ConfigRule::kCount),
              "one text per rule");

constexpr const char* ConfigRuleText(ConfigRule r) {
  return r < ConfigRule::kCount ? kConfigRuleTexts[static_cast<int>(r)] : "?";
}

/// Which rule a configuration breaks first, and on which axis (1-based; 0: not an axis rule; for
/// kTemperatureChannel the channel, 1-based).
struct ConfigFinding {
  ConfigRule rule = ConfigRule::kNone;
  uint8_t axis = 0;
};

/// Checks ranges and consistency (rates versus tick, timing versus rate); kConfigInvalid if bad,
/// with the first broken rule and its axis in *finding (optional; kNone when ok).
Status ValidateBoardConfig(const BoardConfig& config, ConfigFinding* finding = nullptr);

/// The fastest step rate (Hz, rounded down) a step/dir or CW/CCW output can send with `axis`'s
/// pulse timing, one pulse width plus one step space per step; 0 where it sets no bound (a
/// quadrature output sends edges, no pulses; or both times 0).
uint32_t PulseTimingRateHz(const AxisConfig& axis);

/// The rules of a board that sends step pulses (the step/dir board, not the CAN gateway, whose
/// settings carry drive pulse timing it never uses): ValidateBoardConfig(), then per axis
/// kPulseTiming: drive.max_rate_hz at most PulseTimingRateHz() where that bounds it. Without it the
/// other rules (kDriveKeepsUp) would count on a rate the output cannot send: the step output
/// would fall behind its input at full speed. kConfigInvalid with the first broken rule and its
/// axis in *finding (optional; kNone when ok).
Status ValidateStepOutputConfig(const BoardConfig& config, ConfigFinding* finding = nullptr);

/// The correction limiter of `axis` stepped every `ticks_per_step` ticks of `tick_hz`; without it,
/// at the board's compensation rate (CompensationDivider()). kConfigInvalid as
/// CorrectionLimiter::MakeParams().
inline Result<LimiterParams> AxisLimiterParams(const AxisConfig& axis,
                                               uint32_t tick_hz,
                                               uint32_t ticks_per_step) {
  return CorrectionLimiter::MakeParams(tick_hz, axis.max_correction_rate_steps_s,
                                       axis.max_correction_accel_steps_s2, ticks_per_step);
}
inline Result<LimiterParams> AxisLimiterParams(const AxisConfig& axis, uint32_t tick_hz) {
  return AxisLimiterParams(axis, tick_hz, CompensationDivider(tick_hz));
}

/// What bounds the acceleration of a direction switch below direction_switch_accel_steps_s2.
enum class SwitchAccelBound : uint8_t {
  kNone,    // the configured value is in effect
  kPeriod,  // the most the limiter's period represents (below one step per period squared)
  kRate,    // the acceleration that reaches the drive's spare rate within one period
};

/// The acceleration (steps/s^2) an AXIS1D direction switch of `axis` is taken up with when the
/// limiter steps every `ticks_per_step` ticks of `tick_hz`, and what bounds it: the one definition
/// used by AxisSwitchLimiterParams() and by the PC tool, which reports a bound value (`config
/// show`, `config apply`). 0 with kRate where the drive has no rate to spare beyond the input.
struct SwitchAccelInEffect {
  uint32_t steps_s2 = 0;
  SwitchAccelBound bound = SwitchAccelBound::kNone;
};
SwitchAccelInEffect DirectionSwitchAccelInEffect(const AxisConfig& axis,
                                                 uint32_t tick_hz,
                                                 uint32_t ticks_per_step);

/// The limiter of `axis` while it takes up an AXIS1D direction switch, stepped every
/// `ticks_per_step` ticks of `tick_hz`: the rate the drive has left beyond the fastest input
/// (drive.max_rate_hz - max_input_rate_hz, at least the correction's rate on a valid
/// configuration) and direction_switch_accel_steps_s2, taken as at most what the limiter's period
/// represents: below one step per period squared, and no more than reaches that rate within one
/// period (a larger value would move the correction no faster). So the factory value holds at every
/// tick rate: at a 1 kHz compensation rate it is 10^6 steps/s^2 (docs/control-path.md). Fails
/// (kConfigInvalid) only where the correction's own limits do.
Result<LimiterParams> AxisSwitchLimiterParams(const AxisConfig& axis,
                                              uint32_t tick_hz,
                                              uint32_t ticks_per_step);

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
