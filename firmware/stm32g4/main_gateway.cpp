// STM32G474 reference board as a CiA 402 CSP gateway (docs/mcu-target.md, "Gateway image"): the
// freestanding GatewayApp between the controller's bus on FDCAN1 and the drives' bus on FDCAN2.
//   tick    TIM6 update interrupt at BoardConfig::tick_hz (highest priority): GatewayApp::Tick()
//           (ControlTick to the corrections, which the CSP output stage hands to the gateway)
//   main    frames of both buses (forwarded with corrected target / actual positions), the
//           temperature inputs' ADC scan (every 10 ms), then GatewayApp::Poll() (slow lines,
//           thermal, the CANopen node), watchdog refresh
// No step inputs or outputs: the commanded positions come from the controller's target PDOs.
// main() only creates the devices: BoardApp::Start applies the configuration in force (stored
// settings, else the factory defaults below) to TIM6 and to FDCAN1 (the node's bit rate), and does
// so again at every NMT reset node. The drives' bus rate is not a board setting (the drives are
// configured for it): FDCAN2 runs at kDriveBitrate. The tick path and the application object run
// from CCM SRAM (stm32g474re.ld), as in the step/dir image.
#include <cstdint>

#include "cm4_runtime.hpp"
#include "volcomp/firmware/adc_temperature_inputs.hpp"
#include "volcomp/firmware/gateway_app.hpp"
#include "volcomp/firmware/stm32g4/tick_isr.hpp"
#include "volcomp/gateway/csp_gateway.hpp"
#include "volcomp/hal/stm32g4/drivers.hpp"
#include "volcomp/hal/stm32g4/temperature_adc.hpp"

namespace {

namespace stm32g4 = volcomp::stm32g4;
namespace gateway = volcomp::gateway;

// Three linear axes; the drives are CiA 402 nodes 1..3 with the usual CSP PDO mapping: RPDO1
// 0x200 + n = controlword + target position 0x607A at byte 2, TPDO1 0x180 + n = statusword +
// position actual value 0x6064 at byte 2. The mapping is part of the image (the Linux board reads
// it from its configuration file).
volcomp::BoardSettings BoardDefaults() {
  volcomp::BoardSettings s;
  s.board = volcomp::DefaultBoardConfig();
  s.board.pulse_clock_hz = stm32g4::kSysclkHz;
  return s;
}

// The drives' bus (FDCAN2).
constexpr uint32_t kDriveBitrate = 1000000u;

gateway::GatewayConfig DriveMapping(uint8_t axes) {
  gateway::GatewayConfig c;
  for (uint8_t a = 0; a < axes; ++a) {
    c.map[c.map_count++] = {static_cast<uint16_t>(0x201u + a), gateway::PdoField::kTargetPosition,
                            2, a};
    c.map[c.map_count++] = {static_cast<uint16_t>(0x181u + a), gateway::PdoField::kActualPosition,
                            2, a};
  }
  return c;
}

stm32g4::StmSlowIo g_io;
stm32g4::StmFlash g_tables(stm32g4::layout::kTableOffset, stm32g4::layout::kTableBytes);
stm32g4::StmFlash g_settings(stm32g4::layout::kConfigOffset, stm32g4::layout::kConfigBytes);
stm32g4::StmFdcan g_controller(stm32g4::FdcanInstance::kFdcan1);
stm32g4::StmFdcan g_drives(stm32g4::FdcanInstance::kFdcan2);
stm32g4::CycleClock g_clock;
stm32g4::StmTickTimer g_tick(/*irq_priority=*/0);
stm32g4::TemperatureAdc<stm32g4::MmioBus> g_adc;
volcomp::firmware::AdcTemperatureInputs g_temperatures;
static_assert(volcomp::firmware::kAdcSensorInputs == volcomp::stm32g4::kTemperatureInputs,
              "one averager per ADC input");

// The application (the tick's data) in CCM SRAM next to the tick code.
__attribute__((section(".ccm_bss")))
volcomp::firmware::GatewayApp g_app({&g_controller, &g_drives, &g_io, &g_tables, &g_settings,
                                     &g_clock, &g_tick, &g_temperatures});

}  // namespace

// The control tick (vector TIM6_DAC), placed in CCM SRAM through its section name.
extern "C" __attribute__((section(".volcomp_hot.tick_isr"))) void volcomp_tick_isr() {
  volcomp::firmware::stm32g4::RunWholeTickIsr(g_app);
}

int main() {
  if (!stm32g4::ConfigureSystemClock().ok()) volcomp_runtime_panic();
  g_clock.Init();
  g_io.Init();
  g_adc.Start();  // after the cycle counter: it paces the scans
  const volcomp::BoardSettings defaults = BoardDefaults();
  volcomp::firmware::AppOptions options;
  options.table_bank_size = stm32g4::layout::kTableBankBytes;
  // Stored settings the hardware refuses give way to the defaults (FAULT line, EMCY); defaults it
  // refuses leave the board stopped with FAULT set.
  if (g_drives.Init(kDriveBitrate).ok()) {
    g_app.Start(defaults, DriveMapping(defaults.board.axis_count), options).IgnoreError();
  }
  stm32g4::Iwdg::Start(100);
  for (;;) {
    g_app.PumpFrames();
    uint16_t counts[volcomp::firmware::kAdcSensorInputs];
    if (g_adc.Poll(counts)) g_temperatures.AddScan(counts);
    g_app.Poll();
    stm32g4::Iwdg::Refresh();
  }
}
