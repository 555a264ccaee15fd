// The body of the STM32G474 images' tick interrupt (TIM6 update, highest priority): acknowledge
// the timer, run the board application's tick. main.cpp's vector calls it; the cycle bench
// (tests/target/bench) calls the same code on the same drivers with their registers in RAM and
// prices it as the whole interrupt (row tick_isr_3axes, docs/mcu-target.md).
#pragma once

#include "volcomp/hal/stm32g4/drivers.hpp"

namespace volcomp::firmware::stm32g4 {

template <class App>
__attribute__((always_inline)) inline void RunTickIsr(App& app) {
  volcomp::stm32g4::TickTimerAcknowledge();
  app.Tick();
}

}  // namespace volcomp::firmware::stm32g4
