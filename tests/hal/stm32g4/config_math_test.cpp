// STM32G474 driver computations: PLL, flash wait states, FDCAN bit timing, flash layout and the
// timer settings that execute a pulse plan (checked against the plan's own timing).
#include "volcomp/hal/stm32g4/config_math.hpp"

#include <gtest/gtest.h>

#include <random>

#include "volcomp/config/board_config.hpp"

namespace volcomp::stm32g4 {
namespace {

TEST(Stm32g4Clock, Pll170MHzFromHsi16) {
  const Result<PllConfig> p = ComputePll(16000000u, 170000000u);
  ASSERT_TRUE(p.ok());
  const uint64_t vco = uint64_t{16000000u} / p->m * p->n;
  EXPECT_EQ(vco / p->r, 170000000u);
  EXPECT_GE(16000000u / p->m, 2660000u);
  EXPECT_LE(16000000u / p->m, 16000000u);
  EXPECT_GE(vco, 96000000u);
  EXPECT_LE(vco, 344000000u);
  // The lowest input divider that gives exactly 170 MHz: 4 MHz reference, VCO 340 MHz.
  EXPECT_EQ(p->m, 4u);
  EXPECT_EQ(p->n, 85u);
  EXPECT_EQ(p->r, 2u);
}

TEST(Stm32g4Clock, PllFromHseAndUnreachable) {
  const Result<PllConfig> p = ComputePll(8000000u, 170000000u);
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(uint64_t{8000000u} / p->m * p->n / p->r, 170000000u);
  EXPECT_FALSE(ComputePll(16000000u, 170000001u).ok());
}

TEST(Stm32g4Clock, FlashWaitStatesPerRm0440Table9) {
  EXPECT_EQ(FlashWaitStates(170000000u, true), 4u);  // 136 < HCLK <= 170 MHz: 4 WS (boost)
  EXPECT_EQ(FlashWaitStates(136000000u, true), 3u);
  EXPECT_EQ(FlashWaitStates(34000000u, true), 0u);
  EXPECT_EQ(FlashWaitStates(150000000u, false), 4u);
  EXPECT_EQ(FlashWaitStates(16000000u, false), 0u);
}

TEST(Stm32g4Can, BitTimingExactWithSamplePoint) {
  for (uint32_t rate : {125000u, 250000u, 500000u, 1000000u}) {
    const Result<CanBitTiming> t = ComputeCanBitTiming(170000000u, rate, 875);
    ASSERT_TRUE(t.ok()) << rate;
    const uint32_t tq = 1 + t->tseg1 + t->tseg2;
    EXPECT_EQ(uint64_t{rate} * tq * t->prescaler, 170000000u) << rate;
    const uint32_t sp = 1000 * (1 + t->tseg1) / tq;
    EXPECT_NEAR(sp, 875, 60) << rate;
    EXPECT_GE(t->tseg2, 1u);
    EXPECT_LE(t->sjw, t->tseg2);
    // NBTP fields hold value - 1.
    EXPECT_EQ((t->nbtp() >> 16) & 0x1FF, t->prescaler - 1);
    EXPECT_EQ((t->nbtp() >> 8) & 0xFF, t->tseg1 - 1);
    EXPECT_EQ(t->nbtp() & 0x7F, t->tseg2 - 1);
  }
  EXPECT_FALSE(ComputeCanBitTiming(170000000u, 0, 875).ok());
}

TEST(Stm32g4Can, InstancesFromTheMemoryMap) {
  // RM0440 Table 4 (memory map): FDCAN1 0x4000 6400, FDCAN2 0x4000 6800, FDCAN message RAM
  // (SRAMCAN) from 0x4000 A400; §44.3.3: 212 words per instance, FDCAN1's part first.
  const FdcanLayout c1 = FdcanLayoutOf(FdcanInstance::kFdcan1);
  const FdcanLayout c2 = FdcanLayoutOf(FdcanInstance::kFdcan2);
  EXPECT_EQ(c1.registers, 0x40006400u);
  EXPECT_EQ(c2.registers, 0x40006800u);
  EXPECT_EQ(c1.message_ram, 0x4000A400u);
  EXPECT_EQ(c2.message_ram, 0x4000A400u + 212u * 4u);  // 0x4000A750
  // The element layout fills exactly one part: 28 standard filters (1 word), 8 extended filters
  // (2 words), 2 Rx FIFOs x 3 elements x 18 words, Tx event FIFO 3 x 2 words, 3 Tx buffers x 18
  // words.
  EXPECT_EQ(28u + 8u * 2u + 2u * 3u * 18u + 3u * 2u + 3u * 18u, 212u);
  EXPECT_EQ(fdcan::kRamExtFilter, 28u * 4u);
  EXPECT_EQ(fdcan::kRamRxFifo0, fdcan::kRamExtFilter + 8u * 2u * 4u);
  EXPECT_EQ(fdcan::kRamRxFifo1, fdcan::kRamRxFifo0 + 3u * fdcan::kRamElementBytes);
  EXPECT_EQ(fdcan::kRamTxEvent, fdcan::kRamRxFifo1 + 3u * fdcan::kRamElementBytes);
  EXPECT_EQ(fdcan::kRamTxBuffer, fdcan::kRamTxEvent + 3u * 2u * 4u);
  EXPECT_EQ(fdcan::kRamTxBuffer + 3u * fdcan::kRamElementBytes, fdcan::kRamInstanceSize);
  EXPECT_EQ(fdcan::kRamInstanceSize, 212u * 4u);
  // The two parts do not overlap and lie in the 1 KB x 3 of SRAMCAN (0x4000 A400 - 0x4000 AFFF).
  EXPECT_GE(c2.message_ram, c1.message_ram + fdcan::kRamInstanceSize);
  EXPECT_LE(c2.message_ram + fdcan::kRamInstanceSize, 0x4000B000u);
  // Pins (AF9): FDCAN1 PA11 RX / PA12 TX, FDCAN2 PB5 RX / PB6 TX, none shared with each other.
  EXPECT_EQ(c1.rx_port, 0u);
  EXPECT_EQ(c1.rx_pin, 11u);
  EXPECT_EQ(c1.tx_port, 0u);
  EXPECT_EQ(c1.tx_pin, 12u);
  EXPECT_EQ(c2.rx_port, 1u);
  EXPECT_EQ(c2.rx_pin, 5u);
  EXPECT_EQ(c2.tx_port, 1u);
  EXPECT_EQ(c2.tx_pin, 6u);
  EXPECT_EQ(c1.af, 9u);
  EXPECT_EQ(c2.af, 9u);
}

TEST(Stm32g4Flash, LayoutAndPages) {
  using namespace layout;
  EXPECT_EQ(kTableOffset % kPageBytes, 0u);
  EXPECT_EQ(kConfigOffset % kPageBytes, 0u);
  EXPECT_EQ(kTableOffset + kTableBankBytes, kBankBytes);  // bank A in flash bank 1 only
  const FlashPage a_first = PageOf(kTableOffset);
  const FlashPage b_first = PageOf(kTableOffset + kTableBankBytes);
  EXPECT_EQ(a_first.bank, 0u);
  EXPECT_EQ(b_first.bank, 1u);
  EXPECT_EQ(b_first.page, 0u);
  EXPECT_EQ(PageOf(kTableOffset + kTableBankBytes - 1).bank, 0u);
  EXPECT_EQ(PageOf(kTableOffset + kTableBankBytes - 1).page, 127u);
  // A 31 x 31 x 31 int16 grid image fits a bank with the store's 64-byte records.
  const uint32_t image = 24 + 8 + 28 + 8 + 44 + 31 * 31 * 31 * 3 * 2 + 2 + 4;
  EXPECT_LE(image + 64, kTableBankBytes);
}

// Expands timer settings into rising/falling edge times (what PWM mode 2 + OPM + RCR produce)
// and compares them with the plan.
TEST(Stm32g4PulseTimer, SettingsReproduceThePlan) {
  BoardConfig cfg = DefaultBoardConfig();
  cfg.pulse_clock_hz = 170000000u;
  StepGenerator gen;
  ASSERT_TRUE(gen.Configure(cfg.axis[0], cfg.tick_hz, cfg.pulse_clock_hz).ok());
  int32_t target = 0;
  int checked = 0;
  for (int tick = 0; tick < 2000; ++tick) {
    target += (tick / 100) % 2 == 0 ? 17 : -9;
    const PulsePlan plan = gen.Plan(target);
    const Result<PulseTimerSettings> s = PlanToTimer(plan, gen.tick_length(), 16);
    ASSERT_TRUE(s.ok());
    ASSERT_EQ(s->run, plan.count > 0 || plan.dir_change);
    // The tick's unchecked conversion (StepIo::Apply) programs the same values.
    PulseTimerSettings f;
    PlanToTimerFitted(plan, &f);
    ASSERT_EQ(f.run, s->run);
    if (s->run) {
      EXPECT_EQ(f.pulse, s->pulse);
      EXPECT_EQ(f.first_arr, s->first_arr);
      EXPECT_EQ(f.first_ccr, s->first_ccr);
      EXPECT_EQ(f.arr, s->arr);
      EXPECT_EQ(f.ccr, s->ccr);
      EXPECT_EQ(f.rcr, s->rcr);
      EXPECT_EQ(f.dir_ccr, s->dir_ccr);
      EXPECT_EQ(f.dir_change, s->dir_change);
      EXPECT_EQ(f.negative, s->negative);
    }
    if (plan.dir_change) {
      EXPECT_EQ(s->dir_ccr, plan.dir_edge);
    }
    if (plan.count == 0) continue;
    uint32_t start = 0;
    for (uint32_t k = 0; k <= s->rcr; ++k) {
      const uint32_t arr = k == 0 ? s->first_arr : s->arr;
      const uint32_t ccr = k == 0 ? s->first_ccr : s->ccr;
      const uint32_t rise = start + ccr, fall = start + arr + 1;
      EXPECT_EQ(rise, plan.first_rise + k * plan.period);
      EXPECT_EQ(fall - rise, plan.width);
      start += arr + 1;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

// What PlanStepIo() accepts, the timer can execute: every plan of such a generator passes
// PlanToTimer()'s checks (so StepIo::Apply converts without them), over random drive timings,
// tick rates and targets (forward, backward, reversing, beyond a tick's capacity).
TEST(Stm32g4PulseTimer, EveryPlanOfAnAcceptedConfigurationFits) {
  std::mt19937 rng(20261124);
  auto pick = [&](uint32_t lo, uint32_t hi) {
    return std::uniform_int_distribution<uint32_t>(lo, hi)(rng);
  };
  const uint32_t kTicks[] = {5000, 10000, 20000, 25000, 50000, 85000, 100000, 170000};
  int accepted = 0, plans = 0;
  for (int n = 0; n < 300; ++n) {
    BoardConfig cfg = ReferenceBoardConfig();
    cfg.tick_hz = kTicks[pick(0, 7)];
    AxisConfig& ax = cfg.axis[0];
    ax.drive.pulse_width_ns = pick(0, 3) == 0 ? pick(0, 20) : pick(0, 20000);
    ax.drive.step_space_ns = pick(0, 3) == 0 ? pick(0, 20) : pick(0, 20000);
    ax.drive.dir_setup_ns = pick(0, 20000);
    ax.drive.dir_hold_ns = pick(0, 20000);
    ax.drive.max_rate_hz = pick(1000, 10000000);
    ax.max_input_rate_hz = 1000;
    ax.max_correction_rate_steps_s = 100;
    if (!PlanStepIo(cfg, cfg.pulse_clock_hz).ok()) continue;
    ++accepted;
    StepGenerator gen;
    ASSERT_TRUE(gen.Configure(ax, cfg.tick_hz, cfg.pulse_clock_hz).ok());
    int32_t target = 0;
    for (int t = 0; t < 400; ++t) {
      target += static_cast<int32_t>(pick(0, 600)) - 300;
      const PulsePlan plan = gen.Plan(target);
      ASSERT_TRUE(PlanToTimer(plan, gen.tick_length(), 16).ok())
          << "width " << ax.drive.pulse_width_ns << " ns, space " << ax.drive.step_space_ns
          << " ns, rate " << ax.drive.max_rate_hz << " Hz, tick " << cfg.tick_hz << " Hz";
      ++plans;
    }
  }
  EXPECT_GT(accepted, 50);
  EXPECT_GT(plans, 20000);
}

TEST(Stm32g4PulseTimer, RejectsWhatTheTimerCannotDo) {
  PulsePlan p;
  p.count = 3;
  p.period = 100000;  // beyond a 16-bit counter
  p.width = 10;
  EXPECT_FALSE(PlanToTimer(p, 200000, 16).ok());
  p.period = 10;
  p.width = 10;  // no low time
  EXPECT_FALSE(PlanToTimer(p, 3400, 16).ok());
  PulsePlan idle;
  const Result<PulseTimerSettings> s = PlanToTimer(idle, 3400, 16);
  ASSERT_TRUE(s.ok());
  EXPECT_FALSE(s->run);
}

}  // namespace
}  // namespace volcomp::stm32g4
