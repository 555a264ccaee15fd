// STM32G474 backends of the volcomp HAL, register level (registers.hpp, RM0440): StepIo (the
// static step I/O: timer input counters, one-pulse timer outputs started by the tick's TRGO),
// StmTickTimer (TIM6), StmSlowIo (GPIO), StmFlash (main flash region), StmFdcan (FDCAN1/2, classic
// CAN), CycleClock (DWT), Iwdg. Main loop only, except StepIo::ReadCounters/Apply/ApplyAxis,
// TickTimerAcknowledge and PendCompensation (the tick ISR; in CCM SRAM). What each programs:
// docs/mcu-target.md, "Drivers".
#pragma once

#include <cstdint>

#include "volcomp/config/board_config.hpp"
#include "volcomp/hal/can.hpp"
#include "volcomp/hal/clock.hpp"
#include "volcomp/hal/flash.hpp"
#include "volcomp/hal/slow_io.hpp"
#include "volcomp/hal/stm32g4/config_math.hpp"
#include "volcomp/hal/stm32g4/registers.hpp"
#include "volcomp/hal/tick_timer.hpp"
#include "volcomp/output/step_generator.hpp"

namespace volcomp::stm32g4 {

/// HSI16 -> PLL (M=4, N=85, R=2) -> 170 MHz SYSCLK, Range 1 boost mode, 4 flash wait states with
/// prefetch and caches, APB1 = APB2 = 170 MHz (RM0440 §7.2.7 clock switching sequence above
/// 80 MHz: AHB /2 for the switch, then /1).
Status ConfigureSystemClock();

/// A pin: port (0 = A, 1 = B, ...) and number.
struct Pin {
  uint8_t port;
  uint8_t pin;
};
/// Alternate-function pin, very high speed, no pull.
void ConfigureAfPin(Pin p, uint32_t af);
void ConfigureInputPin(Pin p, bool pull_up);
void ConfigureOutputPin(Pin p, bool level);

/// The control tick: TIM6 update interrupt (vector TIM6_DAC) at the programmed rate, TRGO =
/// update (it starts the output timers). The ISR calls TickTimerAcknowledge() first. SetRate()
/// programs PSC/ARR from ComputeTickTimer(kSysclkHz, tick_hz): kConfigInvalid for a rate SYSCLK
/// cannot produce exactly.
class StmTickTimer final : public hal::TickTimer {
 public:
  explicit StmTickTimer(uint32_t irq_priority) : irq_priority_(irq_priority) {}

 private:
  Status DoSetRate(uint32_t tick_hz) override;
  Status DoStart() override;
  void DoStop() override;
  uint32_t DoRateHz() const override { return rate_hz_; }

  uint32_t irq_priority_;
  uint32_t rate_hz_ = 0;
  bool running_ = false;
};
void TickTimerAcknowledge();
/// The compensation interrupt (BoardApp::CompensationTick()): TIM7_DAC's vector (IRQ 55; TIM7 and
/// the DACs are unused on this board) taken as a software interrupt one priority level below the
/// tick's. StmTickTimer enables it with the tick and clears it when the tick stops; the tick ISR
/// pends it when a compensation run is due.
inline constexpr uint32_t kCompensationIrq = 55;
void PendCompensation();

/// Step inputs and outputs of up to three axes (X, Y, Z; see docs/mcu-target.md for pins).
class StepIo {
 public:
  static constexpr uint8_t kAxes = kStepAxes;
  /// Configures input and output timers for `config` as PlanStepIo(config, kSysclkHz) describes
  /// (formats, counter widths; the output timers count at SYSCLK). kConfigInvalid, with nothing
  /// changed, for what this board cannot do (see PlanStepIo).
  Status Configure(const BoardConfig& config);
  void ReadCounters(uint32_t* counters);
  void Apply(const PulsePlan* plans);
  /// Apply() for axis `a` alone (a < the configured axes): the step output stage calls it as it
  /// makes each axis's plan (StepDirIo::Output()), so the plan goes from registers to the timer.
  /// Always inlined.
  inline void ApplyAxis(uint32_t a, const PulsePlan& plan);

 private:
  uint8_t axes_ = 0;
  uint32_t tick_clocks_ = 0;
  bool cw_ccw_[kAxes] = {};
  uintptr_t output_base_[kAxes] = {};  // the axes' output timers (Configure())
};

__attribute__((always_inline)) inline void StepIo::ApplyAxis(uint32_t a, const PulsePlan& plan) {
  // Configure() accepted only drive timing whose every plan fits the timer (PlanStepIo).
  PulseTimerSettings settings;
  PlanToTimerFitted(plan, &settings);
  const PulseTimerSettings* const s = &settings;
  if (!s->run) return;
  const uintptr_t t = output_base_[a];
  // First period into the active registers (UG while stopped), the rest into the preloads;
  // the slave trigger (next tick boundary) starts the counter.
  Reg(t, tim::kArr) = s->first_arr;
  Reg(t, tim::kCcr1) = s->pulse ? s->first_ccr : 0xFFFFu;
  Reg(t, tim::kCcr2) = s->dir_ccr;
  Reg(t, tim::kRcr) = s->rcr;
  // CH2 (direction): set or cleared on the match at dir_ccr when the direction changes, else
  // frozen (mode 0). Selects, no branch.
  const uint32_t dir_mode = s->negative ? tim::kOcmActiveOnMatch : tim::kOcmInactiveOnMatch;
  Reg(t, tim::kCcmr1) =
      tim::Ocm(0, tim::kOcmPwm2) | tim::OcPreload(0) | tim::Ocm(1, s->dir_change ? dir_mode : 0u);
  Reg(t, tim::kCnt) = 0;
  Reg(t, tim::kEgr) = tim::kEgrUg;
  Reg(t, tim::kSr) = 0;
  Reg(t, tim::kArr) = s->arr;
  Reg(t, tim::kCcr1) = s->pulse ? s->ccr : 0xFFFFu;
  // CW/CCW: the pulse goes to CH1 (CW) or CH2 (CCW); the other channel stays idle.
  if (__builtin_expect(cw_ccw_[a], 0)) Reg(t, tim::kCcer) = s->negative ? tim::CcE(2) : tim::CcE(1);
}

class StmSlowIo final : public hal::SlowIo {
 public:
  void Init();

 private:
  bool DoRead(hal::InputLine line) override;
  void DoWrite(hal::OutputLine line, bool level) override;
};

/// `size` bytes of main flash from `offset` (page aligned), e.g. layout::kTableOffset.
class StmFlash final : public hal::Flash {
 public:
  StmFlash(uint32_t offset, uint32_t size) : offset_(offset), size_(size) {}

 private:
  uint32_t DoSize() const override { return size_; }
  uint32_t DoSectorSize() const override { return layout::kPageBytes; }
  uint32_t DoProgramUnit() const override { return 8; }
  Status DoErase(uint32_t offset) override;
  Status DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) override;
  const uint8_t* DoMap(uint32_t offset) const override;

  uint32_t offset_;
  uint32_t size_;
};

class StmFdcan final : public hal::CanPort {
 public:
  /// The instance's registers, message RAM part and pins: FdcanLayoutOf() (config_math.hpp).
  explicit StmFdcan(FdcanInstance instance = FdcanInstance::kFdcan1)
      : layout_(FdcanLayoutOf(instance)) {}
  /// The instance on its pins (FDCAN1: PA11 RX / PA12 TX; FDCAN2: PB5 / PB6), kernel clock PCLK1
  /// (shared by all instances), classic CAN at `bitrate` with the bit timing of
  /// ComputeCanBitTiming(kSysclkHz, bitrate, kCanSamplePointPermille); every frame is accepted
  /// into Rx FIFO 0 (filtering is the protocol's job). kConfigInvalid, with nothing changed, if
  /// the bit rate is not reachable exactly. SetBitrate() is Init() (it re-initialises the
  /// controller). Polled: Rx FIFO 0 holds 3 frames, so the caller must receive at least every 3
  /// frame times.
  Status Init(uint32_t bitrate);
  bool bus_off() const;

 private:
  Status DoSend(const hal::CanFrame& frame) override;
  bool DoReceive(hal::CanFrame* frame) override;
  Status DoSetBitrate(uint32_t bitrate_bps) override { return Init(bitrate_bps); }
  volatile uint32_t* RamWords(uint32_t byte_offset) const;

  FdcanLayout layout_;
};

class CycleClock final : public hal::Clock {
 public:
  void Init();

 private:
  uint64_t DoNowNs() override;
  uint32_t last_ = 0;
  uint64_t high_ = 0;
};

class Iwdg {
 public:
  /// Starts the watchdog (LSI 32 kHz / 32): reset after `timeout_ms` (1..4095) without Refresh().
  static void Start(uint32_t timeout_ms);
  static void Refresh();
};

}  // namespace volcomp::stm32g4
