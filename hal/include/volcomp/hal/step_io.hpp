// Step I/O: the hardware end of the per-tick data path. A static interface (no virtual calls on
// the tick path): the board application is a template over a StepIo type that provides
//
//   volcomp::Status Configure(const volcomp::BoardConfig& config);
//       Set up the input counters and output timers for `config` (pulse formats, counter widths,
//       pulse clock, tick length). Main loop only, while the tick is stopped (the board
//       application calls it at start and at every node reset, before it configures the data
//       path). kConfigInvalid when the hardware cannot do what `config` asks (then the previous
//       setup may be partly changed: the board application does not tick until a Configure()
//       succeeds).
//   void ReadCounters(uint32_t* counters);
//       Latch the input step counters of all configured axes (hardware: timers in encoder or
//       clock+direction mode; counters wrap at their width, see AxisConfig::input_counter_bits).
//   void Apply(const volcomp::PulsePlan* plans);
//       Program the output pulse timers with this tick's plans (one per axis); times in the plan
//       are pulse-clock units from the start of the tick being planned.
//
// and optionally
//
//   void ApplyAxis(uint32_t axis, const volcomp::PulsePlan& plan);
//       Apply() for one axis; the output stage then hands over each plan as it is made
//       (HasApplyAxis<T>), and Apply() is the same as ApplyAxis() for every axis in order.
//
// ReadCounters and Apply are called from the control tick only (and ReadCounters from the main
// loop while the tick is stopped, to latch the counters at start). IsStepIo<T> checks the shape at
// compile time.
#pragma once

#include <cstdint>
#include <type_traits>

#include "volcomp/config/board_config.hpp"
#include "volcomp/base/status.hpp"
#include "volcomp/output/step_generator.hpp"

namespace volcomp::hal {

template <typename T, typename = void>
struct IsStepIo : std::false_type {};

template <typename T>
struct IsStepIo<
    T,
    std::void_t<decltype(std::declval<T&>().ReadCounters(static_cast<uint32_t*>(nullptr))),
                decltype(std::declval<T&>().Apply(static_cast<const PulsePlan*>(nullptr))),
                decltype(static_cast<Status>(std::declval<T&>().Configure(
                    std::declval<const BoardConfig&>())))>> : std::true_type {};

template <typename T, typename = void>
struct HasApplyAxis : std::false_type {};
template <typename T>
struct HasApplyAxis<T,
                    std::void_t<decltype(std::declval<T&>().ApplyAxis(
                        uint32_t{0}, std::declval<const PulsePlan&>()))>> : std::true_type {};

}  // namespace volcomp::hal
