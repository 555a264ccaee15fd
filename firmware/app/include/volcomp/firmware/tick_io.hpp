// The two ends of the control tick as one static type: BoardApp's template parameter (no virtual
// call on the tick path). A tick I/O type provides
//
//   static constexpr OutputStage kOutputStage;
//       What drives the axes (board_settings.hpp): the settings rules the board keeps
//       (ValidateSettings() with it: at a start, in the settings check 0x2123 and at a store).
//   Status Configure(const BoardConfig& config);
//       Start() (main loop, tick stopped, at power-on and every node reset): sets up the input
//       and output hardware (step I/O) and then the output stage for `config`, which
//       ValidateSettings() accepted, before ControlTick is configured. An error (kConfigInvalid:
//       the hardware cannot do what `config` asks) is a refusal of canopen::ConfigPart::kTickIo:
//       BoardApp falls back to the factory defaults, or stays in pass-through with kFault.
//   void ReadCounters(uint32_t* counters);
//       The input stage, from the tick (and once at Start()): the raw input counter of every
//       configured axis, wrapping at AxisConfig::input_counter_bits (the hardware step counters,
//       or the commanded positions of the controller's target PDOs).
//   void Output(const ControlTick& tick);
//       The output stage, from the tick right after ControlTick::Run(): takes the tick's targets
//       (and the corrections in them) to the drives (step/dir pulses, or corrected CAN setpoints).
//   OutputStatus output_status() const;
//       Main loop: the output stage's counters (diagnostic objects).
//
// The two implementations: StepDirIo<StepIo> (step_dir_io.hpp: hardware counters in, StepOutput
// pulse plans out through the HAL's StepIo) and CspIo (csp_io.hpp: the CSP gateway's commanded
// positions in, corrections into the forwarded target PDOs out). IsTickIo<T> checks the shape.
#pragma once

#include <cstdint>
#include <type_traits>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/config/board_settings.hpp"
#include "volcomp/control/control_tick.hpp"
#include "volcomp/table/table_format.hpp"

namespace volcomp::firmware {

/// The output stage's counters, per axis where it applies.
struct OutputStatus {
  /// Output position in machine steps: step/dir, after every pulse planned so far; CSP, the
  /// target that forwarded setpoints carry (commanded + correction).
  int32_t position_steps[table::kMaxAxes] = {};
  /// Largest number of steps owed to the drive after a tick (step/dir; 0 for CSP).
  uint32_t max_backlog_steps[table::kMaxAxes] = {};
  /// Ticks whose owed steps exceeded one tick's pulse capacity (step/dir; 0 for CSP).
  uint32_t overruns = 0;
};

template <typename T, typename = void>
struct IsTickIo : std::false_type {};

template <typename T>
struct IsTickIo<
    T,
    std::void_t<decltype(OutputStage(T::kOutputStage)),
                decltype(Status(std::declval<T&>().Configure(std::declval<const BoardConfig&>()))),
                decltype(std::declval<T&>().ReadCounters(static_cast<uint32_t*>(nullptr))),
                decltype(std::declval<T&>().Output(std::declval<const ControlTick&>())),
                decltype(OutputStatus(std::declval<const T&>().output_status()))>>
    : std::true_type {};

}  // namespace volcomp::firmware
