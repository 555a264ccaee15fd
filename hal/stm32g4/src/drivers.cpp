// STM32G474 HAL backends, register level from RM0440 (see drivers.hpp and registers.hpp).
#include "volcomp/hal/stm32g4/drivers.hpp"

#include "volcomp/hal/stm32g4/registers.hpp"

namespace volcomp::stm32g4 {
namespace {

void SpinUntil(uintptr_t base, uint32_t offset, uint32_t mask, uint32_t value) {
  while ((Reg(base, offset) & mask) != value) {
  }
}

// ---- Timer assignment of the reference board (docs/mcu-target.md, pin table) ------------------
struct InputTimer {
  uintptr_t base;
  Pin ti1;  // direction (step/dir), CCW (cw/ccw) or A (quadrature)
  Pin ti2;  // step (step/dir), CW (cw/ccw) or B (quadrature)
  uint8_t af;
};
// The input timer table is read by the tick (StepIo::ReadCounters): tick data in CCM SRAM (zero
// wait states; from flash a read may wait 4 cycles on an ART data-cache miss); the output timers'
// addresses are copied into the StepIo (Configure()). Counter widths: kInputCounterBits
// (config_math.hpp).
__attribute__((section(".ccm_data.step_io_input"))) constexpr InputTimer kInput[StepIo::kAxes] = {
    {kTim2Base, {0, 15}, {1, 3}, 1},  // X: TIM2 CH1 PA15, CH2 PB3 (AF1), 32-bit
    {kTim5Base, {0, 0}, {0, 1}, 2},   // Y: TIM5 CH1 PA0, CH2 PA1 (AF2), 32-bit
    {kTim3Base, {0, 6}, {0, 7}, 2},   // Z: TIM3 CH1 PA6, CH2 PA7 (AF2), 16-bit
};

struct OutputTimer {
  uintptr_t base;
  Pin step;  // CH1: STEP (step/dir) or CW
  Pin dir;   // CH2: DIR (step/dir) or CCW
  uint8_t af;
  uint8_t trigger_itr;  // ITR input carrying TIM6 TRGO (RM0440 "internal trigger connection")
};
constexpr OutputTimer kOutput[StepIo::kAxes] = {
    {kTim1Base, {0, 8}, {0, 9}, 6, 0},     // X: TIM1 CH1 PA8, CH2 PA9 (AF6)
    {kTim8Base, {2, 6}, {2, 7}, 4, 0},     // Y: TIM8 CH1 PC6, CH2 PC7 (AF4)
    {kTim15Base, {1, 14}, {1, 15}, 1, 0},  // Z: TIM15 CH1 PB14, CH2 PB15 (AF1)
};
// TIM6 TRGO reaches TIM1/8/15 through their ITR multiplexer; RM0440 Table "TIMx internal trigger
// connection" gives the TS value. Board bring-up item: confirm it with a scope
// (docs/mcu-target.md).
constexpr uint32_t kTickTriggerTs = 0x7;

// Slow lines of the reference board.
constexpr Pin kInputPins[static_cast<int>(hal::InputLine::kCount)] = {
    {1, 0}, {1, 1}, {1, 2}, {1, 10}, {1, 11}, {1, 12},  // HOME0..HOME5: PB0, PB1, PB2, PB10-12
    {2, 0},                                             // ENABLE: PC0
    {2, 1},                                             // ESTOP: PC1
    {2, 2},                                             // DRIVE_ALARM: PC2
    {2, 3},                                             // WRITE_PROTECT: PC3
};
constexpr Pin kOutputPins[static_cast<int>(hal::OutputLine::kCount)] = {
    {2, 10},  // READY: PC10
    {2, 11},  // COMPENSATING: PC11
    {2, 12},  // FAULT: PC12
};

void EnableGpioClocks() { Reg(kRccBase, rcc::kAhb2Enr) |= 0x7Fu; }  // GPIOA..GPIOG

void SetPinBits(Pin p, uint32_t offset, uint32_t width, uint32_t value) {
  const uintptr_t base = gpio::PortBase(p.port);
  const uint32_t shift = p.pin * width;
  const uint32_t mask = ((1u << width) - 1u) << shift;
  Reg(base, offset) = (Reg(base, offset) & ~mask) | (value << shift);
}

}  // namespace

// ---- Clocks
// ---------------------------------------------------------------------------------------
Status ConfigureSystemClock() {
  const Result<PllConfig> pll = ComputePll(16000000u, kSysclkHz);
  if (!pll.ok()) return pll.status();
  Reg(kRccBase, rcc::kApb1Enr1) |= rcc::kPwrEn;
  Reg(kPwrBase, pwr::kCr5) &= ~pwr::kCr5R1Mode;  // Range 1 boost (above 150 MHz)
  const uint32_t ws = FlashWaitStates(kSysclkHz, true);
  Reg(kFlashRegBase, flash::kAcr) = (Reg(kFlashRegBase, flash::kAcr) & ~flash::kAcrLatencyMask) |
                                    ws | flash::kAcrPrften | flash::kAcrIcen | flash::kAcrDcen;
  SpinUntil(kFlashRegBase, flash::kAcr, flash::kAcrLatencyMask, ws);
  Reg(kRccBase, rcc::kCr) |= rcc::kCrHsiOn;
  SpinUntil(kRccBase, rcc::kCr, rcc::kCrHsiRdy, rcc::kCrHsiRdy);
  Reg(kRccBase, rcc::kCr) &= ~rcc::kCrPllOn;
  SpinUntil(kRccBase, rcc::kCr, rcc::kCrPllRdy, 0);
  const uint32_t r_bits = (pll->r / 2u - 1u) << 25, q_bits = (pll->q / 2u - 1u) << 21;
  Reg(kRccBase, rcc::kPllCfgr) = rcc::kPllSrcHsi16 | ((pll->m - 1u) << 4) | (pll->n << 8) | r_bits |
                                 rcc::kPllRen | q_bits | rcc::kPllQen;
  Reg(kRccBase, rcc::kCr) |= rcc::kCrPllOn;
  SpinUntil(kRccBase, rcc::kCr, rcc::kCrPllRdy, rcc::kCrPllRdy);
  // Above 80 MHz: switch with AHB /2, wait at least 1 us, then AHB /1 (RM0440 §7.2.7).
  Reg(kRccBase, rcc::kCfgr) =
      (Reg(kRccBase, rcc::kCfgr) & ~rcc::kCfgrHpreMask) | rcc::kCfgrHpreDiv2;
  Reg(kRccBase, rcc::kCfgr) = (Reg(kRccBase, rcc::kCfgr) & ~3u) | rcc::kCfgrSwPll;
  SpinUntil(kRccBase, rcc::kCfgr, rcc::kCfgrSwsMask, rcc::kCfgrSwsPll);
  for (volatile uint32_t i = 0; i < 200; ++i) {
  }
  Reg(kRccBase, rcc::kCfgr) &= ~rcc::kCfgrHpreMask;
  return Status::Ok();
}

// ---- GPIO
// -----------------------------------------------------------------------------------------
void ConfigureAfPin(Pin p, uint32_t af) {
  SetPinBits(p, gpio::kOspeedr, 2, 3);
  SetPinBits(p, gpio::kPupdr, 2, 0);
  // 4 bits per pin: pins 0-7 in AFRL, 8-15 in AFRH.
  const Pin slot{p.port, static_cast<uint8_t>(p.pin & 7u)};
  SetPinBits(slot, p.pin < 8 ? gpio::kAfrl : gpio::kAfrh, 4, af);
  SetPinBits(p, gpio::kModer, 2, gpio::kModeAf);
}

void ConfigureInputPin(Pin p, bool pull_up) {
  SetPinBits(p, gpio::kPupdr, 2, pull_up ? 1 : 0);
  SetPinBits(p, gpio::kModer, 2, gpio::kModeInput);
}

void ConfigureOutputPin(Pin p, bool level) {
  Reg(gpio::PortBase(p.port), gpio::kBsrr) = level ? (1u << p.pin) : (1u << (p.pin + 16));
  SetPinBits(p, gpio::kOtyper, 1, 0);
  SetPinBits(p, gpio::kModer, 2, gpio::kModeOutput);
}

// ---- Tick timer
// -------------------------------------------------------------------------------------
namespace {
constexpr uint32_t kTim6Irq = 54;  // TIM6_DAC (RM0440 Table 97, vector table)
}  // namespace

Status StmTickTimer::DoSetRate(uint32_t tick_hz) {
  if (running_) return Error::kBusy;
  const Result<TickTimerSettings> t = ComputeTickTimer(kSysclkHz, tick_hz);
  if (!t.ok()) return t.status();
  Reg(kRccBase, rcc::kApb1Enr1) |= rcc::kTim6En;
  Reg(kTim6Base, tim::kCr1) = 0;
  Reg(kTim6Base, tim::kPsc) = t->psc;
  Reg(kTim6Base, tim::kArr) = t->arr;
  Reg(kTim6Base, tim::kCr2) = tim::kCr2MmsUpdate;
  rate_hz_ = tick_hz;
  return Status::Ok();
}

Status StmTickTimer::DoStart() {
  if (rate_hz_ == 0) return Error::kNotReady;
  // UG loads PSC/ARR; its update flag is cleared before the interrupt is enabled.
  Reg(kTim6Base, tim::kEgr) = tim::kEgrUg;
  Reg(kTim6Base, tim::kSr) = 0;
  Reg(kTim6Base, tim::kDier) = tim::kDierUie;
  auto* ipr = reinterpret_cast<volatile uint8_t*>(scb::kNvicIpr);
  ipr[kTim6Irq] = static_cast<uint8_t>(irq_priority_ << 4);
  ipr[kCompensationIrq] = static_cast<uint8_t>((irq_priority_ + 1u) << 4);
  Reg(scb::kNvicIcpr, 4u * (kCompensationIrq / 32u)) = 1u << (kCompensationIrq % 32u);
  Reg(scb::kNvicIser, 4u * (kCompensationIrq / 32u)) = 1u << (kCompensationIrq % 32u);
  Reg(scb::kNvicIser, 4u * (kTim6Irq / 32u)) = 1u << (kTim6Irq % 32u);
  Reg(kTim6Base, tim::kCr1) = tim::kCr1Cen;
  running_ = true;
  return Status::Ok();
}

void StmTickTimer::DoStop() {
  Reg(kTim6Base, tim::kCr1) = 0;
  Reg(kTim6Base, tim::kDier) = 0;
  Reg(kTim6Base, tim::kSr) = 0;
  Reg(scb::kNvicIcpr, 4u * (kTim6Irq / 32u)) = 1u << (kTim6Irq % 32u);  // drop a pending tick
  // ... and a pending compensation run (the main loop calls this: a pended run has either
  // completed before it or is dropped here).
  Reg(scb::kNvicIcpr, 4u * (kCompensationIrq / 32u)) = 1u << (kCompensationIrq % 32u);
  __asm volatile("dsb\n isb" ::: "memory");  // no tick ISR begins after this returns
  running_ = false;
}

void TickTimerAcknowledge() { Reg(kTim6Base, tim::kSr) = ~tim::kSrUif; }

void PendCompensation() {
  Reg(scb::kNvicIspr, 4u * (kCompensationIrq / 32u)) = 1u << (kCompensationIrq % 32u);
}

// ---- Step I/O
// -------------------------------------------------------------------------------------
Status StepIo::Configure(const BoardConfig& config) {
  const Result<StepIoSetup> setup = PlanStepIo(config, kSysclkHz);
  if (!setup.ok()) return setup.status();
  axes_ = setup->axes;
  tick_clocks_ = setup->tick_clocks;
  Reg(kRccBase, rcc::kApb1Enr1) |= rcc::kTim2En | rcc::kTim3En | rcc::kTim5En;
  Reg(kRccBase, rcc::kApb2Enr) |= rcc::kTim1En | rcc::kTim8En | rcc::kTim15En;
  EnableGpioClocks();
  for (uint8_t a = 0; a < axes_; ++a) {
    const InputTimer& in = kInput[a];
    uint32_t sms = tim::kSmsClockDirectionX1;
    if (setup->input_format[a] == PulseFormat::kCwCcw) sms = tim::kSmsDirectionalClockX1;
    if (setup->input_format[a] == PulseFormat::kQuadrature) sms = tim::kSmsQuadratureX4;
    Reg(in.base, tim::kCr1) = 0;
    Reg(in.base, tim::kCcmr1) = tim::IcDirect(0, 3) | tim::IcDirect(1, 3);  // filter: 8 clocks
    // Clock on the rising STEP edge; the direction polarity selects which level counts up.
    Reg(in.base, tim::kCcer) = setup->invert_input_dir[a] ? tim::CcP(1) : 0u;
    Reg(in.base, tim::kArr) = kInputCounterBits[a] == 32 ? 0xFFFFFFFFu : 0xFFFFu;
    Reg(in.base, tim::kSmcr) = tim::Sms(sms);
    Reg(in.base, tim::kCnt) = 0;
    Reg(in.base, tim::kCr1) = tim::kCr1Cen;
    ConfigureAfPin(in.ti1, in.af);
    ConfigureAfPin(in.ti2, in.af);

    const OutputTimer& out = kOutput[a];
    cw_ccw_[a] = setup->cw_ccw_output[a];
    output_base_[a] = out.base;
    Reg(out.base, tim::kCr1) = tim::kCr1Opm | tim::kCr1Arpe;
    Reg(out.base, tim::kPsc) = 0;
    Reg(out.base, tim::kRcr) = 0;
    // CH1 pulse channel: PWM mode 2 with preload; CH2 direction: set/reset on match.
    Reg(out.base, tim::kCcmr1) =
        tim::Ocm(0, tim::kOcmPwm2) | tim::OcPreload(0) | tim::Ocm(1, tim::kOcmInactiveOnMatch);
    Reg(out.base, tim::kCcer) = tim::CcE(1) | tim::CcE(2);
    Reg(out.base, tim::kBdtr) = tim::kBdtrMoe;  // main output enable (advanced timers)
    Reg(out.base, tim::kSmcr) = tim::Ts(kTickTriggerTs) | tim::Sms(tim::kSmsTrigger);
    ConfigureAfPin(out.step, out.af);
    ConfigureAfPin(out.dir, out.af);
  }
  return Status::Ok();
}

void StepIo::ReadCounters(uint32_t* counters) {
  for (uint8_t a = 0; a < axes_; ++a) counters[a] = Reg(kInput[a].base, tim::kCnt);
}

void StepIo::Apply(const PulsePlan* plans) {
  for (uint8_t a = 0; a < axes_; ++a) ApplyAxis(a, plans[a]);
}

// ---- Slow lines
// -----------------------------------------------------------------------------------
void StmSlowIo::Init() {
  EnableGpioClocks();
  for (const Pin& p : kInputPins) ConfigureInputPin(p, false);
  for (const Pin& p : kOutputPins) ConfigureOutputPin(p, false);
}

bool StmSlowIo::DoRead(hal::InputLine line) {
  const auto i = static_cast<uint32_t>(line);
  if (i >= static_cast<uint32_t>(hal::InputLine::kCount)) return false;
  const Pin p = kInputPins[i];
  return (Reg(gpio::PortBase(p.port), gpio::kIdr) & (1u << p.pin)) != 0;
}

void StmSlowIo::DoWrite(hal::OutputLine line, bool level) {
  const auto i = static_cast<uint32_t>(line);
  if (i >= static_cast<uint32_t>(hal::OutputLine::kCount)) return;
  const Pin p = kOutputPins[i];
  Reg(gpio::PortBase(p.port), gpio::kBsrr) = level ? (1u << p.pin) : (1u << (p.pin + 16));
}

// ---- Flash (RM0440 §3.3.7 programming, §3.3.8 erase)
// ----------------------------------------------
namespace {

bool FlashUnlock() {
  if ((Reg(kFlashRegBase, flash::kCr) & flash::kCrLock) != 0) {
    Reg(kFlashRegBase, flash::kKeyr) = flash::kKey1;
    Reg(kFlashRegBase, flash::kKeyr) = flash::kKey2;
  }
  return (Reg(kFlashRegBase, flash::kCr) & flash::kCrLock) == 0;
}

void FlashLock() { Reg(kFlashRegBase, flash::kCr) |= flash::kCrLock; }

Status FlashWaitAndCheck() {
  SpinUntil(kFlashRegBase, flash::kSr, flash::kSrBsy, 0);
  const uint32_t sr = Reg(kFlashRegBase, flash::kSr);
  Reg(kFlashRegBase, flash::kSr) = sr & (flash::kSrAllErrors | flash::kSrEop);  // write 1 clears
  return (sr & flash::kSrAllErrors) != 0 ? Status(Error::kIoError) : Status::Ok();
}

}  // namespace

Status StmFlash::DoErase(uint32_t offset) {
  if (!FlashUnlock()) return Error::kIoError;
  Status s = FlashWaitAndCheck();  // clears stale error flags
  const FlashPage pg = PageOf(offset_ + offset);
  Reg(kFlashRegBase, flash::kCr) = flash::kCrPer | (pg.bank != 0 ? flash::kCrBker : 0u) |
                                   ((pg.page << flash::kCrPnbShift) & flash::kCrPnbMask);
  Reg(kFlashRegBase, flash::kCr) |= flash::kCrStrt;
  s = FlashWaitAndCheck();
  Reg(kFlashRegBase, flash::kCr) &= ~(flash::kCrPer | flash::kCrBker | flash::kCrPnbMask);
  FlashLock();
  return s;
}

Status StmFlash::DoProgram(uint32_t offset, const uint8_t* data, uint32_t bytes) {
  if (!FlashUnlock()) return Error::kIoError;
  Status s = FlashWaitAndCheck();
  Reg(kFlashRegBase, flash::kCr) |= flash::kCrPg;
  for (uint32_t i = 0; i < bytes && s.ok(); i += 8) {
    uint32_t w[2];
    __builtin_memcpy(w, data + i, 8);
    auto* dst = reinterpret_cast<volatile uint32_t*>(kFlashBase + offset_ + offset + i);
    dst[0] = w[0];  // a double word: first word, then second word starts the programming
    dst[1] = w[1];
    s = FlashWaitAndCheck();
  }
  Reg(kFlashRegBase, flash::kCr) &= ~flash::kCrPg;
  FlashLock();
  return s;
}

const uint8_t* StmFlash::DoMap(uint32_t offset) const {
  return reinterpret_cast<const uint8_t*>(kFlashBase + offset_ + offset);
}

// ---- FDCAN (RM0440 §44.3)
// --------------------------------------------------------------------------
volatile uint32_t* StmFdcan::RamWords(uint32_t byte_offset) const {
  return reinterpret_cast<volatile uint32_t*>(layout_.message_ram + byte_offset);
}

Status StmFdcan::Init(uint32_t bitrate) {
  const Result<CanBitTiming> bt = ComputeCanBitTiming(kSysclkHz, bitrate, kCanSamplePointPermille);
  if (!bt.ok()) return bt.status();
  const uintptr_t base = layout_.registers;
  // Kernel clock selection and bus clock enable are common to all instances (CCIPR, APB1ENR1).
  Reg(kRccBase, rcc::kCcipr) =
      (Reg(kRccBase, rcc::kCcipr) & ~rcc::kFdcanSelMask) | rcc::kFdcanSelPclk1;
  Reg(kRccBase, rcc::kApb1Enr1) |= rcc::kFdcanEn;
  EnableGpioClocks();
  ConfigureAfPin({layout_.rx_port, layout_.rx_pin}, layout_.af);
  ConfigureAfPin({layout_.tx_port, layout_.tx_pin}, layout_.af);
  Reg(base, fdcan::kCccr) |= fdcan::kCccrInit;
  SpinUntil(base, fdcan::kCccr, fdcan::kCccrInit, fdcan::kCccrInit);
  Reg(base, fdcan::kCccr) |= fdcan::kCccrCce;
  Reg(base, fdcan::kCccr) &= ~fdcan::kCccrFdoe;  // classic CAN frames only
  Reg(base, fdcan::kNbtp) = bt->nbtp();
  // No filter elements; non-matching standard and extended frames go to Rx FIFO 0 (ANFS = ANFE =
  // 00), remote frames are accepted too (RRFS = RRFE = 0).
  Reg(base, fdcan::kRxgfc) = 0;
  Reg(base, fdcan::kTxbc) = 0;  // Tx FIFO mode
  for (uint32_t i = 0; i < fdcan::kRamInstanceSize / 4u; ++i) RamWords(0)[i] = 0;
  Reg(base, fdcan::kCccr) &= ~(fdcan::kCccrCce | fdcan::kCccrInit);
  SpinUntil(base, fdcan::kCccr, fdcan::kCccrInit, 0);
  return Status::Ok();
}

bool StmFdcan::bus_off() const {
  return (Reg(layout_.registers, fdcan::kPsr) & fdcan::kPsrBo) != 0;
}

Status StmFdcan::DoSend(const hal::CanFrame& f) {
  const uint32_t txfqs = Reg(layout_.registers, fdcan::kTxfqs);
  if ((txfqs & fdcan::kTxfqsTfqf) != 0) return Error::kFull;
  const uint32_t put = (txfqs >> 16) & 3u;  // TFQPI
  volatile uint32_t* e = RamWords(fdcan::kRamTxBuffer + put * fdcan::kRamElementBytes);
  e[0] = (f.extended ? (1u << 30) | (f.id & 0x1FFFFFFFu) : (f.id & 0x7FFu) << 18) |
         (f.rtr ? 1u << 29 : 0u);
  e[1] = static_cast<uint32_t>(f.dlc) << 16;
  uint32_t d[2];
  __builtin_memcpy(d, f.data, 8);
  e[2] = d[0];
  e[3] = d[1];
  Reg(layout_.registers, fdcan::kTxbar) = 1u << put;
  return Status::Ok();
}

bool StmFdcan::DoReceive(hal::CanFrame* f) {
  const uint32_t rxf0s = Reg(layout_.registers, fdcan::kRxf0s);
  if ((rxf0s & 0xFu) == 0) return false;   // F0FL: fill level
  const uint32_t get = (rxf0s >> 8) & 3u;  // F0GI
  const volatile uint32_t* e = RamWords(fdcan::kRamRxFifo0 + get * fdcan::kRamElementBytes);
  const uint32_t r0 = e[0], r1 = e[1];
  f->extended = (r0 & (1u << 30)) != 0;
  f->rtr = (r0 & (1u << 29)) != 0;
  f->id = f->extended ? (r0 & 0x1FFFFFFFu) : ((r0 >> 18) & 0x7FFu);
  const uint32_t dlc = (r1 >> 16) & 0xFu;
  f->dlc = static_cast<uint8_t>(dlc > 8 ? 8 : dlc);
  const uint32_t d[2] = {e[2], e[3]};
  __builtin_memcpy(f->data, d, 8);
  Reg(layout_.registers, fdcan::kRxf0a) = get;
  return true;
}

// ---- Clock and watchdog
// -----------------------------------------------------------------------------
void CycleClock::Init() {
  Reg(0xE000EDFCu, 0) |= 1u << 24;  // DEMCR.TRCENA
  Reg(0xE0001004u, 0) = 0;          // DWT_CYCCNT
  Reg(0xE0001000u, 0) |= 1u;        // DWT_CTRL.CYCCNTENA
}

uint64_t CycleClock::DoNowNs() {
  const uint32_t now = Reg(0xE0001004u, 0);
  if (now < last_) high_ += uint64_t{1} << 32;
  last_ = now;
  const uint64_t cycles = high_ | now;
  return cycles * 1000u / (kSysclkHz / 1000000u);  // 170 cycles per microsecond
}

void Iwdg::Start(uint32_t timeout_ms) {
  const uint32_t reload = timeout_ms == 0 ? 1u : (timeout_ms > 4095u ? 4095u : timeout_ms);
  Reg(kIwdgBase, iwdg::kKr) = iwdg::kKeyStart;
  Reg(kIwdgBase, iwdg::kKr) = iwdg::kKeyAccess;
  Reg(kIwdgBase, iwdg::kPr) = 3;  // /32: 1 kHz from the 32 kHz LSI
  Reg(kIwdgBase, iwdg::kRlr) = reload;
  SpinUntil(kIwdgBase, iwdg::kSr, 0x7u, 0);
  Reg(kIwdgBase, iwdg::kKr) = iwdg::kKeyRefresh;
}

void Iwdg::Refresh() { Reg(kIwdgBase, iwdg::kKr) = iwdg::kKeyRefresh; }

}  // namespace volcomp::stm32g4
