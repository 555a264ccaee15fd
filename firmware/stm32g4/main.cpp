// STM32G474 reference board: the board application on the register-level HAL.
//   tick    TIM6 update interrupt at BoardConfig::tick_hz (highest priority): BoardApp::StepTick()
//           (counters, targets, step pulses); pends the compensation interrupt when it is due
//   compensation  TIM7_DAC's vector as a software interrupt one level below the tick, every
//           ControlTick::compensation_divider() ticks: BoardApp::CompensationTick()
//   main    the temperature inputs' ADC scan (every 10 ms: TemperatureAdc, AdcTemperatureInputs),
//           BoardApp::Poll() (slow lines, thermal, CANopen) in a loop, watchdog refresh
// main() only creates the devices: BoardApp::Start applies the configuration in force (stored
// settings, else the factory defaults below) to the step I/O timers, TIM6 and FDCAN, and does so
// again at every NMT reset node.
// The tick path and the application object run from CCM SRAM (stm32g474re.ld).
#include <cstdint>

#include "cm4_runtime.hpp"
#include "volcomp/firmware/adc_temperature_inputs.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/firmware/stm32g4/tick_isr.hpp"
#include "volcomp/hal/stm32g4/drivers.hpp"
#include "volcomp/hal/stm32g4/temperature_adc.hpp"

namespace {

using volcomp::stm32g4::StepIo;
using TickIo = volcomp::firmware::StepDirIo<StepIo>;
using App = volcomp::firmware::BoardApp<TickIo>;

// The reference board: X, Y on 32-bit input timers (TIM2, TIM5), Z on a 16-bit one (TIM3);
// output timers count at SYSCLK.
volcomp::BoardSettings BoardDefaults() {
  volcomp::BoardSettings s;
  s.board = volcomp::stm32g4::ReferenceBoardConfig();
  return s;
}

StepIo g_step_io;
volcomp::stm32g4::StmSlowIo g_io;
volcomp::stm32g4::StmFlash g_tables(volcomp::stm32g4::layout::kTableOffset,
                                    volcomp::stm32g4::layout::kTableBytes);
volcomp::stm32g4::StmFlash g_settings(volcomp::stm32g4::layout::kConfigOffset,
                                      volcomp::stm32g4::layout::kConfigBytes);
volcomp::stm32g4::StmFdcan g_can;
volcomp::stm32g4::CycleClock g_clock;
volcomp::stm32g4::StmTickTimer g_tick(/*irq_priority=*/0);
volcomp::stm32g4::TemperatureAdc<volcomp::stm32g4::MmioBus> g_adc;
volcomp::firmware::AdcTemperatureInputs g_temperatures;
static_assert(volcomp::firmware::kAdcSensorInputs == volcomp::stm32g4::kTemperatureInputs,
              "one averager per ADC input");

// The application and the step output stage (the tick's data) in CCM SRAM next to the tick code.
__attribute__((section(".ccm_bss"))) TickIo g_tick_io(&g_step_io);
__attribute__((section(".ccm_bss")))
App g_app({&g_tick_io, &g_io, &g_tables, &g_settings, &g_can, &g_clock, &g_tick, &g_temperatures});

}  // namespace

// The control tick (vector TIM6_DAC) and the compensation run (vector TIM7_DAC), placed in CCM
// SRAM through their section names.
extern "C" __attribute__((section(".volcomp_hot.tick_isr"))) void volcomp_tick_isr() {
  volcomp::firmware::stm32g4::RunTickIsr(g_app);
}
extern "C" __attribute__((section(".volcomp_hot.compensation_isr"))) void
volcomp_compensation_isr() {
  volcomp::firmware::stm32g4::RunCompensationIsr(g_app);
}

int main() {
  if (!volcomp::stm32g4::ConfigureSystemClock().ok()) volcomp_runtime_panic();
  g_clock.Init();
  g_io.Init();
  g_adc.Start();  // after the cycle counter: it paces the scans
  volcomp::firmware::AppOptions options;
  options.table_bank_size = volcomp::stm32g4::layout::kTableBankBytes;
  // Stored settings the hardware refuses give way to the defaults (FAULT line, EMCY); defaults it
  // refuses leave the board stopped with FAULT set.
  g_app.Start(BoardDefaults(), options).IgnoreError();  // reported on the FAULT line and EMCY
  volcomp::stm32g4::Iwdg::Start(100);
  for (;;) {
    uint16_t counts[volcomp::firmware::kAdcSensorInputs];
    if (g_adc.Poll(counts)) g_temperatures.AddScan(counts);
    g_app.Poll();
    volcomp::stm32g4::Iwdg::Refresh();
  }
}
