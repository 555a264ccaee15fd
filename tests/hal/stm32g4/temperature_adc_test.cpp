// The STM32G474 temperature ADC driver (hal/stm32g4 temperature_adc.hpp) on a recorded register
// bus: the register values against RM0440's field layout (§21.7: JSQR, SMPR1/2, CFGR2; §21.8:
// CCR), worked out by hand here; the bring-up order against RM0440's rules (§21.4.6: DEEPPWD off
// before ADVREGEN, t_ADCVREG_STUP before calibration; §21.4.8: calibration with ADEN = 0,
// single-ended; §21.4.9: ADEN, then ADRDY; JSQR written once enabled, LL driver's note), and the
// main loop's scan: every 10 ms, collected only once it has ended.
#include "volcomp/hal/stm32g4/temperature_adc.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <vector>

namespace volcomp::stm32g4 {
namespace {

constexpr uintptr_t kAdc2 = 0x50000100u;
constexpr uintptr_t kCr = kAdc2 + 0x08, kIsr = kAdc2 + 0x00, kJsqr = kAdc2 + 0x4C;
constexpr uintptr_t kCcr = 0x50000300u + 0x08;
constexpr uint32_t kAden = 1u << 0, kJadstart = 1u << 3, kAdvregen = 1u << 28, kDeeppwd = 1u << 29,
                   kAdcaldif = 1u << 30, kAdcal = 1u << 31;
constexpr uint32_t kAdrdy = 1u << 0, kJeos = 1u << 6;
// CR bits software can only set (RM0440 §21.7.3 "rs"): ADEN, ADDIS, ADSTART, JADSTART, ADSTP,
// JADSTP, ADCAL.
constexpr uint32_t kSetOnly = 0x3Fu | kAdcal;

struct Write {
  uintptr_t address;
  uint32_t value;
  uint32_t cycle;  // the cycle counter when written
};

// A register file with the ADC's behaviour the driver relies on: ADCAL clears once read back,
// ADEN raises ADRDY, ISR bits are cleared by writing 1, every read advances the clock a little.
struct FakeState {
  std::map<uintptr_t, uint32_t> reg;
  std::vector<Write> writes;
  uint32_t cycles = 1000;
};

struct FakeBus {
  FakeState* s;
  uint32_t Read(uintptr_t a) const {
    s->cycles += 4;
    uint32_t& v = s->reg[a];
    const uint32_t out = v;
    if (a == kCr) v &= ~kAdcal;  // calibration ends
    return out;
  }
  void Write(uintptr_t a, uint32_t v) const {
    s->writes.push_back({a, v, s->cycles});
    s->cycles += 2;
    if (a == kIsr) {
      s->reg[a] &= ~v;
      return;
    }
    if (a == kCr) {  // set-only bits ignore a 0; the others take the value
      s->reg[a] = (s->reg[a] & kSetOnly) | v;
      if ((v & kAden) != 0) s->reg[kIsr] |= kAdrdy;
      return;
    }
    s->reg[a] = v;
  }
  uint32_t Cycles() const { return s->cycles += 1; }
};

TEST(TemperatureAdcRegisters, ValuesFollowRm0440Fields) {
  // JSQR: JL = 3 (4 ranks), JEXTEN = 00 (software), JSQ1..4 = IN17, IN5, IN11, IN13 at bits 9,
  // 15, 21, 27.
  EXPECT_EQ(TemperatureAdcJsqr(), 3u | 17u << 9 | 5u << 15 | 11u << 21 | 13u << 27);
  EXPECT_EQ(TemperatureAdcJsqr(), 0x6962A203u);
  // SMP = 110 (247.5 cycles): channel 5 in SMPR1 bits 17:15; channels 11, 13, 17 in SMPR2 bits
  // 5:3, 11:9, 23:21.
  EXPECT_EQ(TemperatureAdcSmpr(false), 6u << 15);
  EXPECT_EQ(TemperatureAdcSmpr(true), 6u << 3 | 6u << 9 | 6u << 21);
  // CFGR2: JOVSE (bit 1), OVSR = 111 (x256, bits 4:2), OVSS = 0100 (>> 4, bits 8:5).
  EXPECT_EQ(kTemperatureAdcCfgr2, 0x2u | 0x1Cu | 0x80u);
  // A scan: 4 x 256 x 260 ADC clocks at 42.5 MHz = 6.26 ms, within the 10 ms period.
  EXPECT_EQ(kTemperatureAdcClockHz, 42500000u);
  EXPECT_NEAR(kTemperatureScanAdcClocks / 42.5e6, 6.264e-3, 1e-6);
  EXPECT_EQ(kTemperatureScanPeriodCycles, 1700000u);
}

TEST(TemperatureAdcDriver, BringUpFollowsTheReferenceManualsOrder) {
  FakeState s;
  s.reg[kCr] = kDeeppwd;  // reset value: deep power-down
  TemperatureAdc<FakeBus> adc(FakeBus{&s});
  adc.Start();

  auto first = [&s](uintptr_t a, uint32_t mask, bool set) -> int {
    for (size_t i = 0; i < s.writes.size(); ++i) {
      if (s.writes[i].address == a && ((s.writes[i].value & mask) != 0) == set)
        return static_cast<int>(i);
    }
    return -1;
  };
  const int deeppwd_off = first(kCr, kDeeppwd, false);
  const int regulator = first(kCr, kAdvregen, true);
  const int calibrate = first(kCr, kAdcal, true);
  const int enable = first(kCr, kAden, true);
  const int jsqr = first(kJsqr, 0xFFFFFFFFu, true);
  const int start = first(kCr, kJadstart, true);
  ASSERT_GE(deeppwd_off, 0);
  EXPECT_LT(deeppwd_off, regulator);
  EXPECT_LT(regulator, calibrate);
  EXPECT_LT(calibrate, enable);
  EXPECT_LT(enable, jsqr);
  EXPECT_LT(jsqr, start);
  // 20 us (3400 cycles at 170 MHz) between the regulator and the calibration.
  EXPECT_GE(s.writes[calibrate].cycle - s.writes[regulator].cycle, 3400u);
  // Calibration: ADEN = 0, single-ended; the regulator stays on, never in deep power-down again.
  EXPECT_EQ(s.writes[calibrate].value & (kAden | kAdcaldif), 0u);
  for (const Write& w : s.writes) {
    if (w.address != kCr) continue;
    EXPECT_EQ(w.value & kDeeppwd, 0u);
    if (&w - s.writes.data() > regulator) {
      EXPECT_NE(w.value & kAdvregen, 0u);
    }
  }
  // ADEN is set once, with no other set-only bit (RM0440 §21.4.9); calibration never again.
  for (size_t i = static_cast<size_t>(enable) + 1; i < s.writes.size(); ++i) {
    if (s.writes[i].address == kCr) {
      EXPECT_EQ(s.writes[i].value & (kAden | kAdcal), 0u) << i;
    }
  }
  // The clock (CKMODE = HCLK/4) is set before the ADC is powered; the ADC12 bus clock first.
  EXPECT_LT(first(kCcr, 3u << 16, true), regulator);
  EXPECT_EQ(s.reg[kCcr] & (3u << 16), 3u << 16);
  EXPECT_NE(s.reg[0x40021000u + 0x4C] & (1u << 13), 0u);
  // The pins stay as the reset left them (analog): no GPIO register is written.
  for (const Write& w : s.writes) EXPECT_FALSE(w.address >= 0x48000000u && w.address < 0x48002000u);
  // Configuration as computed, the first scan started.
  EXPECT_EQ(s.reg[kJsqr], TemperatureAdcJsqr());
  EXPECT_EQ(s.reg[kAdc2 + 0x10], kTemperatureAdcCfgr2);
  EXPECT_EQ(s.reg[kAdc2 + 0x14], TemperatureAdcSmpr(false));
  EXPECT_EQ(s.reg[kAdc2 + 0x18], TemperatureAdcSmpr(true));
  EXPECT_NE(s.reg[kCr] & kJadstart, 0u);
}

TEST(TemperatureAdcDriver, ScansEveryTenMillisecondsAndOnlyWhenEnded) {
  FakeState s;
  TemperatureAdc<FakeBus> adc(FakeBus{&s});
  adc.Start();
  const uint32_t started = s.writes.back().cycle;
  uint16_t counts[kTemperatureInputs] = {};
  for (uint32_t i = 0; i < 4; ++i) s.reg[kAdc2 + 0x80 + 4 * i] = 1000u * (i + 1);
  s.reg[kIsr] |= kJeos;  // the scan ended (6.3 ms in)

  // Before the period is over: nothing read, nothing written.
  s.cycles = started + kTemperatureScanPeriodCycles - 100;
  const size_t writes = s.writes.size();
  EXPECT_FALSE(adc.Poll(counts));
  EXPECT_EQ(s.writes.size(), writes);

  // Over: the four results, JEOS cleared, the next scan started.
  s.cycles = started + kTemperatureScanPeriodCycles + 10;
  s.reg[kCr] &= ~kJadstart;  // hardware clears it at the end of the sequence
  ASSERT_TRUE(adc.Poll(counts));
  EXPECT_EQ(counts[0], 1000);
  EXPECT_EQ(counts[3], 4000);
  EXPECT_EQ(s.reg[kIsr] & kJeos, 0u);
  EXPECT_NE(s.reg[kCr] & kJadstart, 0u);

  // A scan that has not ended when its period is over is waited for, never read half done.
  s.cycles += kTemperatureScanPeriodCycles;
  EXPECT_FALSE(adc.Poll(counts));
  s.reg[kIsr] |= kJeos;
  EXPECT_TRUE(adc.Poll(counts));
}

}  // namespace
}  // namespace volcomp::stm32g4
