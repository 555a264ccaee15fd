// Step I/O: the hardware end of the per-tick data path, a static interface (a template parameter
// of the board application: no virtual call on the tick path). A StepIo type provides
//   Status Configure(const BoardConfig&)  main loop, tick stopped; kConfigInvalid if the hardware
//                                         cannot (it may then be partly changed)
//   void ReadCounters(uint32_t*)          tick (and main loop while stopped): latch the counters
//   void Apply(const PulsePlan*)          tick: program the output timers, one plan per axis
// and optionally ApplyAxis(axis, plan) (HasApplyAxis: Apply() for one axis). Rules and units:
// docs/control-path.md, "Step I/O".
#pragma once

#include <cstdint>
#include <type_traits>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
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
