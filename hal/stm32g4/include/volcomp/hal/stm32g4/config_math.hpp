// Pure computations behind the STM32G474 drivers (no register access, host-tested in
// tests/hal/stm32g4/): PLL and flash wait states, FDCAN bit timing and instances, the tick timer's
// period, the step I/O timer setup for a board configuration, the flash layout, and the timer
// settings that execute one PulsePlan. The drivers program exactly what these return, so the
// configuration path (settings in force -> register values) is checked on the host.
#pragma once

#include <cstdint>

#include "volcomp/base/status.hpp"
#include "volcomp/config/board_config.hpp"
#include "volcomp/hal/stm32g4/registers.hpp"
#include "volcomp/output/step_generator.hpp"

namespace volcomp::stm32g4 {

/// SYSCLK = HCLK = PCLK1 = PCLK2: the clock of every timer and of FDCAN (ConfigureSystemClock).
inline constexpr uint32_t kSysclkHz = 170000000u;

// ---- System clock (RM0440 §7.2.4 PLL, §3.3.3 Table 9 wait states)
// --------------------------------
struct PllConfig {
  uint32_t m = 1;  // input divider 1..16: f_in / m must be 2.66..16 MHz
  uint32_t n = 8;  // multiplier 8..127: VCO = f_in / m * n must be 96..344 MHz
  uint32_t r = 2;  // SYSCLK divider 2, 4, 6 or 8
  uint32_t q = 2;  // FDCAN/USB divider (PLLQ) 2, 4, 6 or 8
  uint32_t sysclk_hz = 0;
};

/// Finds M, N, R giving exactly `target_hz` from `input_hz` (HSI16 or HSE), preferring the
/// lowest VCO input divider; kConfigInvalid when no exact combination exists.
Result<PllConfig> ComputePll(uint32_t input_hz, uint32_t target_hz);

/// Flash wait states for HCLK (Table 9: Range 1 boost mode, 34 MHz per wait state up to 170 MHz;
/// Range 1 normal mode 30 MHz per wait state up to 150 MHz).
uint32_t FlashWaitStates(uint32_t hclk_hz, bool boost_mode);

// ---- FDCAN nominal bit timing (RM0440 §44.3.5; classic CAN)
// ----------------------------------------
struct CanBitTiming {
  uint32_t prescaler = 1;  // NBRP + 1 (1..512)
  uint32_t tseg1 = 1;      // NTSEG1 + 1 (2..256): propagation + phase segment 1, in tq
  uint32_t tseg2 = 1;      // NTSEG2 + 1 (1..128), in tq
  uint32_t sjw = 1;        // NSJW + 1 (1..128)
  uint32_t nbtp() const {
    return ((sjw - 1u) << 25) | ((prescaler - 1u) << 16) | ((tseg1 - 1u) << 8) | (tseg2 - 1u);
  }
};

/// The sample point StmFdcan asks for (CiA 301 recommends 87.5 %).
inline constexpr uint32_t kCanSamplePointPermille = 875;

/// Exact bit rate from `kernel_hz` with the sample point closest to `sample_permille` (e.g. 875),
/// 8..25 time quanta per bit; kConfigInvalid when the rate is not reachable exactly.
Result<CanBitTiming> ComputeCanBitTiming(uint32_t kernel_hz,
                                         uint32_t bitrate,
                                         uint32_t sample_permille);

// ---- FDCAN instances (RM0440 §2.2.2 memory map, §44.3.3 message RAM) ----------------------------
/// The FDCAN instances the reference board uses: FDCAN1 on the controller's bus (the board's
/// CANopen node; in gateway mode also the CNC side), FDCAN2 on the drives' bus (gateway mode).
enum class FdcanInstance : uint8_t { kFdcan1 = 0, kFdcan2 = 1 };

/// Where an instance lives and which pins carry it.
struct FdcanLayout {
  uintptr_t registers = 0;    // register block
  uintptr_t message_ram = 0;  // its part of the shared message RAM (fdcan::kRamInstanceSize bytes)
  uint8_t rx_port = 0, rx_pin = 0;  // port 0 = A, 1 = B, ...
  uint8_t tx_port = 0, tx_pin = 0;
  uint8_t af = 0;  // alternate function of both pins
};

/// FDCAN1: registers 0x40006400, message RAM 0x4000A400, PA11 RX / PA12 TX (AF9). FDCAN2:
/// registers 0x40006800, message RAM 0x4000A750 (the second 212-word part), PB5 RX / PB6 TX (AF9,
/// STM32G474 datasheet alternate-function table; PB12/PB13 are taken by home inputs).
constexpr FdcanLayout FdcanLayoutOf(FdcanInstance instance) {
  const uint32_t n = static_cast<uint32_t>(instance);
  const bool first = instance == FdcanInstance::kFdcan1;
  return {kFdcan1Base + 0x400u * n,
          kSramCanBase + fdcan::kRamInstanceSize * n,
          static_cast<uint8_t>(first ? 0 : 1),
          static_cast<uint8_t>(first ? 11 : 5),
          static_cast<uint8_t>(first ? 0 : 1),
          static_cast<uint8_t>(first ? 12 : 6),
          9};
}

// ---- Tick timer (TIM6, a basic timer with 16-bit PSC and ARR; RM0440 §29) ----------------------
struct TickTimerSettings {
  uint32_t psc = 0;  // prescaler register: divider - 1
  uint32_t arr = 0;  // auto-reload register: period - 1, in prescaled clocks
  /// Timer clocks per tick: (psc + 1) * (arr + 1).
  uint32_t clocks() const { return (psc + 1u) * (arr + 1u); }
};

/// PSC and ARR giving exactly `tick_hz` update events per second from `timer_clock_hz`: the
/// smallest prescaler (finest period resolution) whose ARR fits 16 bits. kConfigInvalid when no
/// exact pair exists (the timer clock is not a whole multiple of the rate, or the period needs
/// more than 16 + 16 bits).
Result<TickTimerSettings> ComputeTickTimer(uint32_t timer_clock_hz, uint32_t tick_hz);

// ---- Step input and output timers of the reference board (pin table: docs/mcu-target.md) -------
inline constexpr uint8_t kStepAxes = 3;
/// Width of each axis's input counter as wired: TIM2 (X) and TIM5 (Y) 32-bit, TIM3 (Z) 16-bit.
inline constexpr uint8_t kInputCounterBits[kStepAxes] = {32, 32, 16};
/// Counter width of the output timers TIM1, TIM8, TIM15.
inline constexpr uint32_t kOutputTimerBits = 16;

/// The reference board's factory configuration: DefaultBoardConfig() with the output timers'
/// clock (SYSCLK) as pulse clock and the counter widths as wired.
BoardConfig ReferenceBoardConfig();

/// What StepIo::Configure programs for a board configuration.
struct StepIoSetup {
  uint8_t axes = 0;
  uint32_t tick_clocks = 0;  // output timer clocks per tick (the PulsePlan time base)
  PulseFormat input_format[kStepAxes] = {};
  bool invert_input_dir[kStepAxes] = {};
  bool cw_ccw_output[kStepAxes] = {};
};

/// Checks that the board can do what `config` asks and returns the setup. kConfigInvalid when:
/// more than kStepAxes axes; an axis's input_counter_bits differs from its timer's width;
/// quadrature output (not wired on this board); pulse_clock_hz != timer_clock_hz (the output
/// timers count at SYSCLK); the tick is not a whole number of timer clocks; or a tick's pulse
/// plans may not fit the 16-bit output timers (tick + pulse width above 65536 clocks: below about
/// 2.6 kHz at 170 MHz); or a pulse without a high or a low time of at least one timer clock (pulse
/// width 0, or step space and rate leaving no low time). What it accepts, every plan fits
/// (PlanToTimerFitted()).
Result<StepIoSetup> PlanStepIo(const BoardConfig& config, uint32_t timer_clock_hz);

// ---- Flash layout of the reference board (RM0440 §3.3.1: dual-bank mode, 2 KB pages) ------------
namespace layout {
inline constexpr uint32_t kPageBytes = 2048;
inline constexpr uint32_t kBankBytes = 256u * 1024u;  // flash bank 1 at 0x08000000, bank 2 above
inline constexpr uint32_t kAppOffset = 0;
inline constexpr uint32_t kAppBytes = 76u * 1024u;
inline constexpr uint32_t kConfigOffset = kAppOffset + kAppBytes;  // settings store, 2 pages
inline constexpr uint32_t kConfigBytes = 2u * kPageBytes;
/// Table store: bank A fills the rest of flash bank 1, bank B the start of flash bank 2, so
/// staging (erasing, programming) one never stalls the tick reading the other: the flash banks
/// read while the other writes (RM0440 §3.3.1). 176 KB holds a 31 x 31 x 31 int16 grid.
inline constexpr uint32_t kTableBankBytes = 88u * kPageBytes;
inline constexpr uint32_t kTableOffset = kConfigOffset + kConfigBytes;
inline constexpr uint32_t kTableBankBOffset = kBankBytes;
/// The table store region (what the firmware's dual-bank store sees): bank A, then bank B.
/// Bank B starts the second flash bank, so the region includes no gap: A ends where bank 2 begins.
inline constexpr uint32_t kTableBytes = 2u * kTableBankBytes;
inline constexpr uint32_t kReservedOffset = kTableBankBOffset + kTableBankBytes;
inline constexpr uint32_t kFlashBytes = 512u * 1024u;
static_assert(kTableOffset + kTableBankBytes == kBankBytes, "bank A must end with flash bank 1");
static_assert(kTableOffset + kTableBankBytes == kTableBankBOffset, "the banks must be contiguous");
static_assert(kReservedOffset <= kFlashBytes, "layout exceeds the flash");
}  // namespace layout

/// Flash bank (0 or 1) and page number within it of a flash offset (dual-bank mode).
struct FlashPage {
  uint32_t bank = 0;
  uint32_t page = 0;
};
inline FlashPage PageOf(uint32_t flash_offset) {
  return {flash_offset / layout::kBankBytes,
          (flash_offset % layout::kBankBytes) / layout::kPageBytes};
}

// ---- Pulse output timer settings for one PulsePlan ----------------------------------------------
/// How a timer in PWM mode 2 with one-pulse mode and a repetition counter produces a plan: the
/// counter starts at the tick boundary (slave trigger from the tick timer); the first period is
/// ARR = first_rise + width - 1 with CCR = first_rise (rise at first_rise, fall at the update),
/// the following periods ARR = period - 1, CCR = period - width (loaded from the preload registers
/// at the first update); RCR = count - 1 stops the counter after `count` pulses. The direction
/// line is a second channel set/cleared on match at dir_edge (repeated matches keep its level).
struct PulseTimerSettings {
  bool run = false;        // false: no pulse and no direction change this tick
  bool pulse = false;      // false: only the direction edge (pulse channel disabled)
  uint32_t first_arr = 0;  // first period
  uint32_t first_ccr = 0;
  uint32_t arr = 0;  // following periods
  uint32_t ccr = 0;
  uint32_t rcr = 0;      // repetitions - 1
  uint32_t dir_ccr = 0;  // direction edge compare value
  bool dir_change = false;
  bool negative = false;
};

/// Timer settings for `plan` with a `counter_bits`-wide counter (16 for TIM1/8/15); `tick` is the
/// tick length in timer clocks. kConfigInvalid if the plan does not fit the timer.
Result<PulseTimerSettings> PlanToTimer(const PulsePlan& plan, uint32_t tick, uint32_t counter_bits);

/// The timer settings of `plan` without checks, for the tick (StepIo::Apply): a plan of a step
/// generator whose drive timing PlanStepIo() accepted always fits (a pulse width of at least one
/// clock, a low time of at least one clock, at most StepGenerator::kMaxPulsesPerTick pulses, tick +
/// width within the counter), so the tick spends no branch on a case that cannot occur
/// (tests/hal/stm32g4/config_math_test.cpp checks it against PlanToTimer() over generated plans).
/// Fields other than `run` are meaningful only when `run` is set. Always inlined: the settings
/// stay in registers.
__attribute__((always_inline)) inline void PlanToTimerFitted(const PulsePlan& plan,
                                                             PulseTimerSettings* s) {
  const bool pulse = plan.count != 0;
  s->negative = plan.negative;
  s->dir_change = plan.dir_change;
  s->dir_ccr = plan.dir_edge;
  s->run = pulse || plan.dir_change;
  s->pulse = pulse;
  // Without a pulse: one period covering the direction edge.
  s->first_ccr = pulse ? plan.first_rise : 0u;
  s->first_arr = pulse ? plan.first_rise + plan.width - 1u : plan.dir_edge + 1u;
  s->arr = pulse ? plan.period - 1u : s->first_arr;
  s->ccr = pulse ? plan.period - plan.width : 0u;
  s->rcr = pulse ? plan.count - 1u : 0u;
}

/// PlanToTimer() without the Result: writes every field of `*s` and returns true, or returns
/// false (`*s` then unspecified) where PlanToTimer() returns kConfigInvalid (a plan the timer
/// cannot execute). Always inlined.
__attribute__((always_inline)) inline bool PlanToTimerInto(const PulsePlan& plan,
                                                           uint32_t tick,
                                                           uint32_t counter_bits,
                                                           PulseTimerSettings* s) {
  const uint32_t max = counter_bits >= 32 ? 0xFFFFFFFFu : (1u << counter_bits) - 1u;
  PlanToTimerFitted(plan, s);
  if (!s->run) {
    s->dir_ccr = s->first_arr = s->arr = 0;  // nothing this tick
    return true;
  }
  if (!s->pulse) return s->first_arr <= max && s->first_arr <= tick;
  if (plan.width == 0 || plan.period <= plan.width || plan.count > 256u) return false;
  return s->first_arr <= max && s->arr <= max;
}

}  // namespace volcomp::stm32g4
