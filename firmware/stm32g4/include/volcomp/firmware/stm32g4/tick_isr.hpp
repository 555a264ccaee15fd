// The bodies of the STM32G474 images' two control interrupts (docs/mcu-target.md, "Two rates"):
//   tick          TIM6 update, highest priority: acknowledge the timer, BoardApp::StepTick()
//                 (counters, targets, output); pend the compensation interrupt when a run is due.
//   compensation  TIM7_DAC's vector as a software interrupt one level below:
//                 BoardApp::CompensationTick() (requests from the main loop, the compensator).
// main.cpp's vectors call them; the cycle bench (tests/target/bench) calls the same code on the
// same drivers with their registers in RAM and prices each as a whole interrupt (rows
// tick_isr_3axes and compensation_isr_3axes).
#pragma once

#include "volcomp/hal/stm32g4/drivers.hpp"

namespace volcomp::firmware::stm32g4 {

template <class App>
__attribute__((always_inline)) inline void RunTickIsr(App& app) {
  volcomp::stm32g4::TickTimerAcknowledge();
  if (app.StepTick()) volcomp::stm32g4::PendCompensation();
}

/// The gateway image's tick: both parts in the one interrupt (BoardApp::Tick(); at its 1 kHz
/// tick the compensation runs every tick).
template <class App>
__attribute__((always_inline)) inline void RunWholeTickIsr(App& app) {
  volcomp::stm32g4::TickTimerAcknowledge();
  app.Tick();
}

template <class App>
__attribute__((always_inline)) inline void RunCompensationIsr(App& app) {
  app.CompensationTick();
}

}  // namespace volcomp::firmware::stm32g4
