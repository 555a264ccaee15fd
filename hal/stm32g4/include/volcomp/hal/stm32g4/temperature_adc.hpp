// The STM32G474 reference board's temperature inputs (docs/mcu-target.md pin table, docs/thermal.md
// "Board-local sensors"): ADC2's injected group scans four inputs, each oversampled 256 times in
// hardware, every 10 ms, started from the main loop; the four results wait in JDR1..JDR4 (no
// DMA, no interrupt), and the next pass that finds the period over collects them and starts the
// next scan.
//
//   input  pin  ADC2 channel          the divider: R_ref (10 k 0.1 %) from VREF+ to the node,
//     0    PA4  IN17                  the sensor from the node to GND; node -> 1 k -> pin,
//     1    PC4  IN5                   100 nF from the pin to GND (the ADC's charge reservoir and
//     2    PC5  IN11                  an RC filter); the counts do not depend on VREF+
//     3    PA5  IN13                  (ratiometric). Nucleo-G474RE: LD2 sits on PA5.
//
// ADC clock HCLK / 4 = 42.5 MHz (CKMODE = 11, synchronous, no RCC kernel clock); 12-bit
// conversions with a 247.5-cycle sample time (SMP = 110): 260 ADC clocks = 6.12 us each; the
// oversampler sums 256 of them per channel (OVSR = 111) and shifts by 4 (OVSS = 0100): a 16-bit
// result, the mean code x 16. A scan is 4 x 256 x 260 = 266 240 ADC clocks = 6.26 ms, within the
// 10 ms period (kScanPeriodCycles).
//
// Bring-up (RM0440 §21.4.6 regulator, §21.4.8 calibration, §21.4.9 enable): DEEPPWD off,
// ADVREGEN on, wait t_ADCVREG_STUP (20 us, the DS12288 maximum), single-ended calibration with
// ADEN = 0, 4 ADC clocks, ADEN and wait for ADRDY; then, enabled and idle, the sample times, the
// oversampler and the injected sequence (JSQR is written with ADEN = 1), and the first scan.
// JQDIS = 1 (its reset value): the injected sequence stays programmed, JADSTART restarts it.
//
// TemperatureAdc<Bus> is the driver over a register bus: MmioBus on the board; tests record the
// bus (tests/hal/stm32g4/temperature_adc_test.cpp). Main loop only.
#pragma once

#include <cstdint>

#include "volcomp/hal/stm32g4/config_math.hpp"
#include "volcomp/hal/stm32g4/registers.hpp"

namespace volcomp::stm32g4 {

inline constexpr uint32_t kTemperatureInputs = 4;

struct AdcInputPin {
  uint8_t port;     // 0 = A, 2 = C
  uint8_t pin;      // 0..15
  uint8_t channel;  // ADC2_INx
};
/// Input n of the board (its temperature channel n).
inline constexpr AdcInputPin kTemperatureInputPins[kTemperatureInputs] = {
    {0, 4, 17}, {2, 4, 5}, {2, 5, 11}, {0, 5, 13}};

/// The ADC clock: HCLK / 4.
inline constexpr uint32_t kTemperatureAdcClockHz = kSysclkHz / 4u;
/// ADC clocks of one scan: 4 inputs x 256 conversions x (247.5 sample + 12.5 conversion).
inline constexpr uint32_t kTemperatureScanAdcClocks = kTemperatureInputs * 256u * 260u;
/// A scan starts every 10 ms (CPU cycles of the DWT counter).
inline constexpr uint32_t kTemperatureScanPeriodCycles = kSysclkHz / 100u;
static_assert(uint64_t{kTemperatureScanAdcClocks} * 4u < kTemperatureScanPeriodCycles,
              "a scan must end within its period");

/// The register values the driver programs (host-tested against RM0440's field layout).
constexpr uint32_t TemperatureAdcJsqr() {
  uint32_t v = kTemperatureInputs - 1u;  // JL; JEXTEN = 00: software start
  for (uint32_t i = 0; i < kTemperatureInputs; ++i)
    v |= adc::JsqrRank(i + 1u, kTemperatureInputPins[i].channel);
  return v;
}
/// SMPR1 (low) or SMPR2 (high): 247.5 cycles for the inputs' channels, the rest at reset (0).
constexpr uint32_t TemperatureAdcSmpr(bool high) {
  uint32_t v = 0;
  for (const AdcInputPin& p : kTemperatureInputPins) {
    if ((p.channel >= 10) == high) v |= adc::kSmp247 << adc::SmpShift(p.channel);
  }
  return v;
}
inline constexpr uint32_t kTemperatureAdcCfgr2 = adc::kCfgr2Jovse | adc::Ovsr(8) | adc::Ovss(4);

/// Register access of the board: volatile words, the DWT cycle counter (CycleClock::Init()
/// enables it).
struct MmioBus {
  static uint32_t Read(uintptr_t address) { return *reinterpret_cast<volatile uint32_t*>(address); }
  static void Write(uintptr_t address, uint32_t value) {
    *reinterpret_cast<volatile uint32_t*>(address) = value;
  }
  static uint32_t Cycles() { return Read(0xE0001004u); }  // DWT_CYCCNT
};

template <class Bus>
class TemperatureAdc {
 public:
  explicit TemperatureAdc(Bus bus = Bus()) : bus_(bus) {}

  /// Powers ADC2 up, calibrates and enables it, programs the scan and starts the first (about
  /// 25 us of busy waiting: start-up only).
  void Start() {
    // The pins: analog mode is their reset state (GPIOx_MODER, RM0440 §9.4.1) and no driver
    // changes them.
    bus_.Write(kRccBase + rcc::kAhb2Enr, bus_.Read(kRccBase + rcc::kAhb2Enr) | rcc::kAdc12En);
    const uintptr_t ccr = kAdc12CommonBase + adc::kCommonCcr;
    bus_.Write(ccr, (bus_.Read(ccr) & ~adc::kCcrCkmodeMask) | adc::kCcrCkmodeHclkDiv4);
    Cr(0);  // DEEPPWD off (reset: on)
    Cr(adc::kCrAdvregen);
    Wait(20u * (kSysclkHz / 1000000u));    // t_ADCVREG_STUP
    Cr(adc::kCrAdvregen | adc::kCrAdcal);  // ADCALDIF = 0: single-ended inputs
    while ((Reg(adc::kCr) & adc::kCrAdcal) != 0) {
    }
    Wait(16);  // 4 ADC clocks before ADEN
    Write(adc::kIsr, adc::kIsrAdrdy);
    Cr(adc::kCrAdvregen | adc::kCrAden);
    while ((Reg(adc::kIsr) & adc::kIsrAdrdy) == 0) {
    }
    Write(adc::kSmpr1, TemperatureAdcSmpr(false));
    Write(adc::kSmpr2, TemperatureAdcSmpr(true));
    Write(adc::kCfgr2, kTemperatureAdcCfgr2);
    Write(adc::kJsqr, TemperatureAdcJsqr());
    StartScan();
  }

  /// Every main-loop pass: once a period has passed since the last scan started and the scan has
  /// ended (JEOS), the inputs' counts into counts[0..3] (the mean code x 16), the next scan
  /// started; true. Otherwise false, and no register is touched but the cycle counter (and ISR
  /// when the period is over).
  bool Poll(uint16_t counts[kTemperatureInputs]) {
    if (bus_.Cycles() - started_ < kTemperatureScanPeriodCycles) return false;
    if ((Reg(adc::kIsr) & adc::kIsrJeos) == 0) return false;  // not ended: the next pass
    for (uint32_t i = 0; i < kTemperatureInputs; ++i)
      counts[i] = static_cast<uint16_t>(Reg(adc::kJdr1 + 4u * i));
    StartScan();
    return true;
  }

 private:
  uint32_t Reg(uint32_t offset) { return bus_.Read(kAdc2Base + offset); }
  void Write(uint32_t offset, uint32_t value) { bus_.Write(kAdc2Base + offset, value); }
  void Cr(uint32_t value) { Write(adc::kCr, value); }
  void Wait(uint32_t cycles) {
    const uint32_t t0 = bus_.Cycles();
    while (bus_.Cycles() - t0 < cycles) {
    }
  }
  void StartScan() {
    Write(adc::kIsr, adc::kIsrJeos);
    started_ = bus_.Cycles();
    // CR's set-only bits (ADEN, JADSTART, ADCAL, ...) ignore a 0, so only JADSTART is set; the
    // read-write ADVREGEN stays on, DEEPPWD off.
    Cr(adc::kCrAdvregen | adc::kCrJadstart);
  }

  Bus bus_;
  uint32_t started_ = 0;
};

}  // namespace volcomp::stm32g4
