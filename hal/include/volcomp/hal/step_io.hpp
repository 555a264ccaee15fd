// Step I/O: the hardware end of the per-tick data path. A static interface (no virtual calls on
// the tick path): the board application is a template over a StepIo type that provides
//
//   void ReadCounters(uint32_t* counters);
//       Latch the input step counters of all configured axes (hardware: timers in encoder or
//       clock+direction mode; counters wrap at their width, see AxisConfig::input_counter_bits).
//   void Apply(const volcomp::PulsePlan* plans);
//       Program the output pulse timers with this tick's plans (one per axis); times in the plan
//       are pulse-clock units from the start of the tick being planned.
//
// Both are called from the control tick only. IsStepIo<T> checks the shape at compile time.
#pragma once

#include <cstdint>
#include <type_traits>

#include "volcomp/step_generator.hpp"

namespace volcomp::hal {

template <typename T, typename = void>
struct IsStepIo : std::false_type {};

template <typename T>
struct IsStepIo<
    T,
    std::void_t<decltype(std::declval<T&>().ReadCounters(static_cast<uint32_t*>(nullptr))),
                decltype(std::declval<T&>().Apply(static_cast<const PulsePlan*>(nullptr)))>>
    : std::true_type {};

}  // namespace volcomp::hal
