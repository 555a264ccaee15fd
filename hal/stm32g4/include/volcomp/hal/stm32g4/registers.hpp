// STM32G474 peripheral registers used by volcomp, defined from the reference manual RM0440 rev 8
// (no vendor headers). Only what the drivers touch is here; section numbers refer to RM0440.
// Access is through Reg(): a volatile 32-bit word at base + offset.
#pragma once

#include <cstdint>

namespace volcomp::stm32g4 {

inline volatile uint32_t& Reg(uintptr_t base, uint32_t offset) {
  return *reinterpret_cast<volatile uint32_t*>(base + offset);
}

// ---- Memory map (RM0440 §2.2.2, Table 4) -------------------------------------------------------
// VOLCOMP_STM32G4_REGISTER_WINDOW (the cycle bench's QEMU image only, tests/target): the APB/AHB1
// peripherals from 0x40000000 and the GPIO ports from 0x48000000 are moved into RAM at that
// address (+ 0x30000 for GPIO), so the tick's driver code runs unchanged on a machine without
// these peripherals: only the address constants differ. Never defined for a board image.
#if defined(VOLCOMP_STM32G4_REGISTER_WINDOW)
inline constexpr uintptr_t kPeriphBase = VOLCOMP_STM32G4_REGISTER_WINDOW;
inline constexpr uintptr_t kGpioPortsBase = VOLCOMP_STM32G4_REGISTER_WINDOW + 0x30000u;
#else
inline constexpr uintptr_t kPeriphBase = 0x40000000u;
inline constexpr uintptr_t kGpioPortsBase = 0x48000000u;
#endif
inline constexpr uintptr_t kFlashBase = 0x08000000u;    // 512 KB main flash
inline constexpr uintptr_t kCcmSramBase = 0x10000000u;  // 32 KB CCM SRAM (I-bus alias)
inline constexpr uintptr_t kTim2Base = kPeriphBase + 0x0000u;
inline constexpr uintptr_t kTim3Base = kPeriphBase + 0x0400u;
inline constexpr uintptr_t kTim4Base = kPeriphBase + 0x0800u;
inline constexpr uintptr_t kTim5Base = kPeriphBase + 0x0C00u;
inline constexpr uintptr_t kTim6Base = kPeriphBase + 0x1000u;
inline constexpr uintptr_t kIwdgBase = kPeriphBase + 0x3000u;
inline constexpr uintptr_t kFdcan1Base = kPeriphBase + 0x6400u;  // FDCAN2 +0x400, FDCAN3 +0x800
inline constexpr uintptr_t kFdcan2Base = kPeriphBase + 0x6800u;
inline constexpr uintptr_t kPwrBase = kPeriphBase + 0x7000u;
inline constexpr uintptr_t kSramCanBase = kPeriphBase + 0xA400u;  // FDCAN message RAM, shared
inline constexpr uintptr_t kTim1Base = kPeriphBase + 0x12C00u;
inline constexpr uintptr_t kTim8Base = kPeriphBase + 0x13400u;
inline constexpr uintptr_t kTim15Base = kPeriphBase + 0x14000u;
inline constexpr uintptr_t kRccBase = kPeriphBase + 0x21000u;
inline constexpr uintptr_t kFlashRegBase = kPeriphBase + 0x22000u;
inline constexpr uintptr_t kGpioABase = kGpioPortsBase;  // GPIOx = A + 0x400 * x
// ADC1/ADC2 on AHB2 (not moved by the register window: the cycle bench has no ADC driver).
inline constexpr uintptr_t kAdc1Base = 0x50000000u;
inline constexpr uintptr_t kAdc2Base = 0x50000100u;
inline constexpr uintptr_t kAdc12CommonBase = 0x50000300u;

// ---- RCC (§7.4)
// -----------------------------------------------------------------------------------
namespace rcc {
inline constexpr uint32_t kCr = 0x00, kCfgr = 0x08, kPllCfgr = 0x0C, kAhb2Enr = 0x4C,
                          kApb1Enr1 = 0x58, kApb2Enr = 0x60, kCcipr = 0x88, kCsr = 0x94;
inline constexpr uint32_t kCrHsiOn = 1u << 8, kCrHsiRdy = 1u << 10, kCrHseOn = 1u << 16,
                          kCrHseRdy = 1u << 17, kCrPllOn = 1u << 24, kCrPllRdy = 1u << 25;
inline constexpr uint32_t kCfgrSwPll = 3u, kCfgrSwsMask = 3u << 2, kCfgrSwsPll = 3u << 2;
inline constexpr uint32_t kCfgrHpreMask = 0xFu << 4, kCfgrHpreDiv2 = 0x8u << 4;
inline constexpr uint32_t kPllSrcHsi16 = 2u, kPllSrcHse = 3u;
inline constexpr uint32_t kPllRen = 1u << 24, kPllQen = 1u << 20;
// APB1ENR1 bits
inline constexpr uint32_t kTim2En = 1u << 0, kTim3En = 1u << 1, kTim4En = 1u << 2,
                          kTim5En = 1u << 3, kTim6En = 1u << 4, kFdcanEn = 1u << 25,
                          kPwrEn = 1u << 28;
// APB2ENR bits
inline constexpr uint32_t kSyscfgEn = 1u << 0, kTim1En = 1u << 11, kTim8En = 1u << 13,
                          kTim15En = 1u << 16;
// AHB2ENR bits: GPIOA..GPIOG are bits 0..6
inline constexpr uint32_t kAdc12En = 1u << 13;
// CCIPR: FDCANSEL[25:24] = 10 -> PCLK1
inline constexpr uint32_t kFdcanSelMask = 3u << 24, kFdcanSelPclk1 = 2u << 24;
}  // namespace rcc

// ---- PWR (§6.4): CR5.R1MODE = 0 selects Range 1 boost mode, needed above 150 MHz ---------------
namespace pwr {
inline constexpr uint32_t kCr5 = 0x80, kCr5R1Mode = 1u << 8;
}

// ---- FLASH (§3.7)
// ---------------------------------------------------------------------------------
namespace flash {
inline constexpr uint32_t kAcr = 0x00, kKeyr = 0x08, kSr = 0x10, kCr = 0x14, kOptr = 0x20;
inline constexpr uint32_t kAcrLatencyMask = 0xFu, kAcrPrften = 1u << 8, kAcrIcen = 1u << 9,
                          kAcrDcen = 1u << 10;
inline constexpr uint32_t kKey1 = 0x45670123u, kKey2 = 0xCDEF89ABu;
inline constexpr uint32_t kCrPg = 1u << 0, kCrPer = 1u << 1, kCrPnbShift = 3,
                          kCrPnbMask = 0x7Fu << 3, kCrBker = 1u << 11, kCrStrt = 1u << 16,
                          kCrLock = 1u << 31;
inline constexpr uint32_t kSrEop = 1u << 0, kSrOperr = 1u << 1, kSrProgerr = 1u << 3,
                          kSrWrperr = 1u << 4, kSrPgaerr = 1u << 5, kSrSizerr = 1u << 6,
                          kSrPgserr = 1u << 7, kSrMiserr = 1u << 8, kSrFasterr = 1u << 9,
                          kSrRderr = 1u << 14, kSrOptverr = 1u << 15, kSrBsy = 1u << 16;
inline constexpr uint32_t kSrAllErrors = kSrOperr | kSrProgerr | kSrWrperr | kSrPgaerr | kSrSizerr |
                                         kSrPgserr | kSrMiserr | kSrFasterr | kSrRderr | kSrOptverr;
inline constexpr uint32_t kOptrDbank = 1u << 22;  // 1 = dual bank, 2 KB pages (factory default)
}  // namespace flash

// ---- GPIO (§9.4)
// ----------------------------------------------------------------------------------
namespace gpio {
inline constexpr uint32_t kModer = 0x00, kOtyper = 0x04, kOspeedr = 0x08, kPupdr = 0x0C,
                          kIdr = 0x10, kOdr = 0x14, kBsrr = 0x18, kAfrl = 0x20, kAfrh = 0x24;
inline constexpr uint32_t kModeInput = 0, kModeOutput = 1, kModeAf = 2, kModeAnalog = 3;
inline constexpr uintptr_t PortBase(uint32_t port) { return kGpioABase + 0x400u * port; }
}  // namespace gpio

// ---- General-purpose / advanced timers (§28 TIM1/8/20, §29 TIM2-5, §30 TIM15-17, §31 TIM6/7) ---
namespace tim {
inline constexpr uint32_t kCr1 = 0x00, kCr2 = 0x04, kSmcr = 0x08, kDier = 0x0C, kSr = 0x10,
                          kEgr = 0x14, kCcmr1 = 0x18, kCcmr2 = 0x1C, kCcer = 0x20, kCnt = 0x24,
                          kPsc = 0x28, kArr = 0x2C, kRcr = 0x30, kCcr1 = 0x34, kCcr2 = 0x38,
                          kCcr3 = 0x3C, kCcr4 = 0x40, kBdtr = 0x44;
inline constexpr uint32_t kCr1Cen = 1u << 0, kCr1Urs = 1u << 2, kCr1Opm = 1u << 3,
                          kCr1Arpe = 1u << 7;
inline constexpr uint32_t kCr2MmsUpdate = 2u << 4;  // TRGO = update event
inline constexpr uint32_t kDierUie = 1u << 0;
inline constexpr uint32_t kSrUif = 1u << 0;
inline constexpr uint32_t kEgrUg = 1u << 0;
inline constexpr uint32_t kBdtrMoe = 1u << 15;
/// SMCR slave mode SMS[3:0]: bit 16 holds SMS[3], bits 2:0 SMS[2:0] (§28.6.3).
inline constexpr uint32_t Sms(uint32_t mode) { return ((mode & 8u) << 13) | (mode & 7u); }
inline constexpr uint32_t kSmsQuadratureX4 = 0x3;        // encoder mode 3: both edges of TI1, TI2
inline constexpr uint32_t kSmsTrigger = 0x6;             // counter starts on trigger rising edge
inline constexpr uint32_t kSmsClockDirectionX1 = 0xB;    // clock (TI2) plus direction (TI1), x1
inline constexpr uint32_t kSmsDirectionalClockX1 = 0xD;  // up clock TI2, down clock TI1, x1
/// SMCR TS[4:0]: bits 21:20 hold TS[4:3], bits 6:4 TS[2:0].
inline constexpr uint32_t Ts(uint32_t itr) { return ((itr & 0x18u) << 17) | ((itr & 7u) << 4); }
/// CCMRx output compare mode OCxM[3:0] for channel slot 0 or 1 of the register.
inline constexpr uint32_t Ocm(uint32_t slot, uint32_t mode) {
  return (((mode & 8u) << 13) | ((mode & 7u) << 4)) << (8u * slot);
}
inline constexpr uint32_t kOcmActiveOnMatch = 0x1, kOcmInactiveOnMatch = 0x2, kOcmPwm2 = 0x7;
inline constexpr uint32_t OcPreload(uint32_t slot) { return (1u << 3) << (8u * slot); }
/// CCMRx input capture: CCxS = 01 (TIx mapped on its own input), filter ICxF.
inline constexpr uint32_t IcDirect(uint32_t slot, uint32_t filter) {
  return (1u | (filter << 4)) << (8u * slot);
}
inline constexpr uint32_t CcE(uint32_t channel) { return 1u << (4u * (channel - 1u)); }
inline constexpr uint32_t CcP(uint32_t channel) { return 2u << (4u * (channel - 1u)); }
}  // namespace tim

// ---- IWDG (§42.4)
// --------------------------------------------------------------------------------
namespace iwdg {
inline constexpr uint32_t kKr = 0x00, kPr = 0x04, kRlr = 0x08, kSr = 0x0C, kWinr = 0x10;
inline constexpr uint32_t kKeyStart = 0xCCCC, kKeyRefresh = 0xAAAA, kKeyAccess = 0x5555;
}  // namespace iwdg

// ---- FDCAN (§44.4; one register block per instance, 0x400 apart; the message RAM is shared,
// one 0x350-byte part per instance in instance order, §44.3.3)
// -------------------------------------------------------------------------------
namespace fdcan {
inline constexpr uint32_t kCccr = 0x018, kNbtp = 0x01C, kEcr = 0x040, kPsr = 0x044, kIr = 0x050,
                          kIe = 0x054, kIls = 0x058, kIle = 0x05C, kRxgfc = 0x080, kRxf0s = 0x090,
                          kRxf0a = 0x094, kTxbc = 0x0C0, kTxfqs = 0x0C4, kTxbar = 0x0CC;
inline constexpr uint32_t kCccrInit = 1u << 0, kCccrCce = 1u << 1, kCccrFdoe = 1u << 8;
inline constexpr uint32_t kPsrBo = 1u << 7;
inline constexpr uint32_t kTxfqsTfqf = 1u << 21;
/// Message RAM per instance (§44.3.3, fixed layout, word offsets from the instance's start):
/// 28 standard filters, 8 extended filters, Rx FIFO 0 and 1 (3 x 18 words), Tx event FIFO
/// (3 x 2 words), 3 Tx buffers (3 x 18 words); 212 words (0x350 bytes) per instance.
inline constexpr uint32_t kRamStdFilter = 0x000, kRamExtFilter = 0x070, kRamRxFifo0 = 0x0B0,
                          kRamRxFifo1 = 0x188, kRamTxEvent = 0x260, kRamTxBuffer = 0x278,
                          kRamInstanceSize = 0x350, kRamElementBytes = 18 * 4;
}  // namespace fdcan

// ---- ADC (§21.7 registers of one ADC, §21.8 the common registers of ADC1/ADC2)
// ------------------------------------------------------------------------------------------------
namespace adc {
inline constexpr uint32_t kIsr = 0x00, kCr = 0x08, kCfgr = 0x0C, kCfgr2 = 0x10, kSmpr1 = 0x14,
                          kSmpr2 = 0x18, kJsqr = 0x4C, kJdr1 = 0x80;  // JDRn = JDR1 + 4 (n - 1)
inline constexpr uint32_t kCommonCcr = 0x08;                          // from kAdc12CommonBase
inline constexpr uint32_t kIsrAdrdy = 1u << 0, kIsrJeos = 1u << 6;    // write 1 to clear
inline constexpr uint32_t kCrAden = 1u << 0, kCrAdstart = 1u << 2, kCrJadstart = 1u << 3,
                          kCrAdvregen = 1u << 28, kCrDeeppwd = 1u << 29, kCrAdcaldif = 1u << 30,
                          kCrAdcal = 1u << 31;
/// CFGR2: JOVSE (oversampling of the injected group), OVSR[4:2] ratio 2^(OVSR + 1), OVSS[8:5]
/// right shift.
inline constexpr uint32_t kCfgr2Jovse = 1u << 1;
inline constexpr uint32_t Ovsr(uint32_t log2_ratio) { return (log2_ratio - 1u) << 2; }
inline constexpr uint32_t Ovss(uint32_t shift) { return shift << 5; }
/// JSQR: JL[1:0] = ranks - 1, JEXTEN[8:7] = 00 (software start), JSQn[4:0] at 9 + 6 (n - 1).
inline constexpr uint32_t JsqrRank(uint32_t rank, uint32_t channel) {
  return channel << (9u + 6u * (rank - 1u));
}
/// SMPR1 (channels 0..9) / SMPR2 (10..18): SMPx[2:0] at 3 x (x mod 10).
inline constexpr uint32_t SmpShift(uint32_t channel) { return 3u * (channel % 10u); }
/// SMP code 6: 247.5 ADC clock cycles.
inline constexpr uint32_t kSmp247 = 6;
/// CCR CKMODE[17:16] = 11: synchronous clock HCLK / 4.
inline constexpr uint32_t kCcrCkmodeHclkDiv4 = 3u << 16, kCcrCkmodeMask = 3u << 16;
}  // namespace adc

// ---- Cortex-M4 system control (ARMv7-M ARM B3.2, Cortex-M4 Generic User Guide §4)
// ----------------
namespace scb {
inline constexpr uintptr_t kNvicIser = 0xE000E100u, kNvicIspr = 0xE000E200u,
                           kNvicIcpr = 0xE000E280u, kNvicIpr = 0xE000E400u;
inline constexpr uintptr_t kScbVtor = 0xE000ED08u, kScbAircr = 0xE000ED0Cu;
}  // namespace scb

}  // namespace volcomp::stm32g4
