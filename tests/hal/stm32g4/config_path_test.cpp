// The STM32G474 configuration path on the host: from the settings in force to the register
// values the drivers program, through the functions the drivers call (ComputeTickTimer for TIM6,
// PlanStepIo for the step timers, ComputeCanBitTiming for FDCAN). First the computations against
// their definitions (RM0440: update rate = f_clk / ((PSC + 1)(ARR + 1)), 16-bit PSC/ARR; CAN bit
// time = prescaler x quanta / f_clk); then BoardApp on host stand-ins of the three devices that
// compute exactly what StmTickTimer, StepIo and StmFdcan program (the step timers under the
// step/dir tick I/O, StepDirIo, as in the image): the tick rate and bit rate
// changed over CAN and a node reset leave TIM6, the output timers' tick length, FDCAN and the
// data path agreeing; settings the hardware cannot run are refused visibly.
#include <gtest/gtest.h>

#include <vector>

#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/hal/mock/mock_step_io.hpp"
#include "volcomp/hal/stm32g4/config_math.hpp"

namespace volcomp::stm32g4 {
namespace {

using hal::OutputLine;

TEST(Stm32g4TickTimer, ExactRateWith16BitRegisters) {
  // Every tick rate the board configuration allows (1 kHz .. 200 kHz).
  int exact = 0;
  for (uint32_t hz = 1000; hz <= 200000; ++hz) {
    const Result<TickTimerSettings> t = ComputeTickTimer(kSysclkHz, hz);
    if (kSysclkHz % hz != 0) {
      EXPECT_FALSE(t.ok()) << hz;  // not a whole number of clocks: refused, never approximated
      continue;
    }
    ASSERT_TRUE(t.ok()) << hz;
    ++exact;
    EXPECT_LE(t->psc, 0xFFFFu) << hz;
    EXPECT_LE(t->arr, 0xFFFFu) << hz;
    EXPECT_GE(t->arr, 1u) << hz;
    EXPECT_EQ(uint64_t{t->psc + 1} * (t->arr + 1) * hz, kSysclkHz) << hz;
    // The finest resolution: no smaller prescaler divides the period within 16 bits.
    for (uint32_t div = 1; div < t->psc + 1; ++div) {
      const uint32_t clocks = kSysclkHz / hz;
      EXPECT_FALSE(clocks % div == 0 && clocks / div <= 0x10000u) << hz << " div " << div;
    }
  }
  EXPECT_GT(exact, 50);
  // The default 50 kHz: 3400 clocks, no prescaler (docs/mcu-target.md: ARR = 3399).
  const Result<TickTimerSettings> t50 = ComputeTickTimer(kSysclkHz, 50000);
  ASSERT_TRUE(t50.ok());
  EXPECT_EQ(t50->psc, 0u);
  EXPECT_EQ(t50->arr, 3399u);
  // 1 kHz needs the prescaler: 170000 clocks do not fit 16 bits.
  const Result<TickTimerSettings> t1 = ComputeTickTimer(kSysclkHz, 1000);
  ASSERT_TRUE(t1.ok());
  EXPECT_EQ(t1->psc, 3u);
  EXPECT_EQ(t1->arr, 42499u);
  EXPECT_FALSE(ComputeTickTimer(kSysclkHz, 0).ok());
  EXPECT_FALSE(ComputeTickTimer(kSysclkHz, 30000).ok());  // 5666.67 clocks
}

TEST(Stm32g4StepIo, TheReferenceBoardAndWhatItCannotDo) {
  const BoardConfig ref = ReferenceBoardConfig();
  const Result<StepIoSetup> s = PlanStepIo(ref, kSysclkHz);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->axes, 3);
  EXPECT_EQ(s->tick_clocks, 3400u);  // the output timers' tick = TIM6's period
  EXPECT_EQ(s->tick_clocks, ComputeTickTimer(kSysclkHz, ref.tick_hz)->clocks());
  BoardConfig c = ref;
  c.axis[1].input_format = PulseFormat::kQuadrature;
  c.axis[2].output_format = PulseFormat::kCwCcw;
  c.axis[0].invert_input_dir = true;
  const Result<StepIoSetup> s2 = PlanStepIo(c, kSysclkHz);
  ASSERT_TRUE(s2.ok());
  EXPECT_EQ(s2->input_format[1], PulseFormat::kQuadrature);
  EXPECT_TRUE(s2->cw_ccw_output[2]);
  EXPECT_TRUE(s2->invert_input_dir[0]);
  struct Case {
    const char* what;
    BoardConfig config;
  };
  std::vector<Case> refused;
  c = ref;
  c.axis[0].output_format = PulseFormat::kQuadrature;
  refused.push_back({"quadrature output is not wired", c});
  c = ref;
  c.axis[2].input_counter_bits = 32;
  refused.push_back({"Z's input timer is 16-bit", c});
  c = ref;
  c.axis_count = 4;
  refused.push_back({"three step channels", c});
  c = ref;
  c.pulse_clock_hz = 1000000000;
  refused.push_back({"the output timers count at SYSCLK", c});
  c = ref;
  c.tick_hz = 30000;
  refused.push_back({"a tick of 5666.67 clocks", c});
  c = ref;
  c.tick_hz = 2000;  // 85000 clocks: a plan's first period does not fit 16 bits
  refused.push_back({"16-bit output timers", c});
  c = ref;
  c.axis[1].drive.pulse_width_ns = 0;
  refused.push_back({"a pulse needs a high time", c});
  c = ref;
  c.axis[1].drive.step_space_ns = 0;
  c.axis[1].drive.max_rate_hz = 170000000;  // the rate leaves no low time either
  refused.push_back({"a pulse needs a low time", c});
  for (const Case& r : refused) EXPECT_FALSE(PlanStepIo(r.config, kSysclkHz).ok()) << r.what;
  c = ref;
  c.tick_hz = 5000;  // 34000 clocks + the pulse width: fits
  EXPECT_TRUE(PlanStepIo(c, kSysclkHz).ok());
}

// Host stand-ins of the STM32 devices: they compute what the drivers program.
class Tim6 final : public hal::TickTimer {
 public:
  TickTimerSettings programmed;
  bool running = false;

 private:
  Status DoSetRate(uint32_t tick_hz) override {
    if (running) return Error::kBusy;
    const Result<TickTimerSettings> t = ComputeTickTimer(kSysclkHz, tick_hz);
    if (!t.ok()) return t.status();
    programmed = *t;
    rate_ = tick_hz;
    return Status::Ok();
  }
  Status DoStart() override {
    running = true;
    return Status::Ok();
  }
  void DoStop() override { running = false; }
  uint32_t DoRateHz() const override { return rate_; }
  uint32_t rate_ = 0;
};

class StepTimers {
 public:
  explicit StepTimers(hal::mock::MockStepIo* lines) : lines_(lines) {}
  Status Configure(const BoardConfig& config) {
    const Result<StepIoSetup> s = PlanStepIo(config, kSysclkHz);
    if (!s.ok()) return s.status();
    setup = *s;
    return lines_->Configure(config);
  }
  void ReadCounters(uint32_t* counters) { lines_->ReadCounters(counters); }
  void Apply(const PulsePlan* plans) { lines_->Apply(plans); }
  StepIoSetup setup;

 private:
  hal::mock::MockStepIo* lines_;
};

class Fdcan final : public hal::mock::MockCan {
 public:
  using MockCan::MockCan;
  CanBitTiming timing;
  uint32_t bitrate = 0;

 private:
  Status DoSetBitrate(uint32_t bitrate_bps) override {
    const Result<CanBitTiming> t =
        ComputeCanBitTiming(kSysclkHz, bitrate_bps, kCanSamplePointPermille);
    if (!t.ok()) return t.status();
    timing = *t;
    bitrate = bitrate_bps;
    return Status::Ok();
  }
};

// An expedited SDO download to node 0x10 (CiA 301: 0x23 = 4 data bytes, 0x2B = 2).
CanFrame Download(uint16_t index, uint8_t sub, uint32_t value, uint8_t bytes = 4) {
  CanFrame f;
  f.id = 0x610;
  f.dlc = 8;
  f.data[0] = bytes == 2 ? 0x2B : 0x23;
  f.data[1] = static_cast<uint8_t>(index);
  f.data[2] = static_cast<uint8_t>(index >> 8);
  f.data[3] = sub;
  for (int i = 0; i < 4; ++i) f.data[4 + i] = static_cast<uint8_t>(value >> (8 * i));
  return f;
}

class Stm32ConfigPathTest : public ::testing::Test {
 protected:
  Stm32ConfigPathTest()
      : io_(&clock_, nullptr),
        tables_(64 * 1024, 2048, 8, &clock_, nullptr),
        settings_(4096, 2048, 8, &clock_, nullptr),
        can_(&clock_, nullptr, 256),
        lines_(ReferenceBoardConfig(), nullptr),
        step_(&lines_),
        tick_io_(&step_),
        app_({&tick_io_, &io_, &tables_, &settings_, &can_, &clock_, &tim6_}) {
    defaults_.board = ReferenceBoardConfig();
    io_.SetInput(hal::InputLine::kWriteEnable, true);
  }

  // Stores the tick rate and bit rate over CAN and resets the node.
  void StoreAndReset(uint32_t tick_hz, uint32_t bitrate_kbit) {
    for (const CanFrame& f : {Download(0x2000, 3, tick_hz), Download(0x2000, 2, bitrate_kbit, 2),
                              Download(0x1010, 1, 0x65766173)}) {  // "save"
      can_.Inject(f);
      app_.Poll();
    }
    CanFrame nmt;
    nmt.id = 0;
    nmt.dlc = 2;
    nmt.data[0] = 0x81;  // reset node
    nmt.data[1] = 0x10;
    can_.Inject(nmt);
    app_.Poll();
  }
  // TIM6, the output timers' tick and the data path agree on the tick.
  void ExpectTickAgrees(uint32_t tick_hz) {
    EXPECT_EQ(app_.settings().board.tick_hz, tick_hz);
    EXPECT_TRUE(tim6_.running);
    EXPECT_EQ(uint64_t{tim6_.programmed.clocks()} * tick_hz, kSysclkHz);
    EXPECT_EQ(step_.setup.tick_clocks, tim6_.programmed.clocks());
    EXPECT_EQ(uint64_t{app_.settings().board.pulse_clock_hz} / tick_hz, step_.setup.tick_clocks);
  }
  void ExpectBitRate(uint32_t bitrate) {
    EXPECT_EQ(can_.bitrate, bitrate);
    const CanBitTiming& t = can_.timing;
    EXPECT_EQ(uint64_t{t.prescaler} * (1 + t.tseg1 + t.tseg2) * bitrate, kSysclkHz);
  }

  BoardSettings defaults_;
  hal::mock::MockClock clock_;
  hal::mock::MockSlowIo io_;
  hal::mock::MockFlash tables_, settings_;
  Fdcan can_;
  Tim6 tim6_;
  hal::mock::MockStepIo lines_;
  StepTimers step_;
  firmware::StepDirIo<StepTimers> tick_io_;
  firmware::BoardApp<firmware::StepDirIo<StepTimers>> app_;
};

TEST_F(Stm32ConfigPathTest, TheRatesInForceReachTim6TheStepTimersAndFdcan) {
  ASSERT_TRUE(app_.Start(defaults_).ok());
  ExpectTickAgrees(50000);
  EXPECT_EQ(tim6_.programmed.arr, 3399u);
  ExpectBitRate(1000000);
  EXPECT_EQ(can_.timing.prescaler, 10u);  // docs/mcu-target.md: 1 Mbit/s, 17 tq

  StoreAndReset(25000, 500);
  ExpectTickAgrees(25000);
  EXPECT_EQ(tim6_.programmed.psc, 0u);
  EXPECT_EQ(tim6_.programmed.arr, 6799u);
  ExpectBitRate(500000);
  EXPECT_TRUE(app_.config_status().ok());
  EXPECT_FALSE(io_.output(OutputLine::kFault));
}

TEST_F(Stm32ConfigPathTest, RatesTheHardwareCannotProduceAreRefusedVisibly) {
  ASSERT_TRUE(app_.Start(defaults_).ok());
  StoreAndReset(25000, 500);
  // 30 kHz is a valid setting, but 170 MHz / 30 kHz is no whole number of timer clocks: the step
  // timers (which share the tick) refuse it; the board runs the factory defaults and says so.
  StoreAndReset(30000, 500);
  EXPECT_EQ(app_.config_status().error(), Error::kConfigInvalid);
  EXPECT_EQ(app_.config_refused_by(), canopen::ConfigPart::kTickIo);
  ExpectTickAgrees(50000);
  ExpectBitRate(1000000);
  EXPECT_TRUE(io_.output(OutputLine::kFault));
  // 10 kbit/s needs a prescaler above 512 at 170 MHz: FDCAN refuses it.
  StoreAndReset(25000, 10);
  EXPECT_EQ(app_.config_refused_by(), canopen::ConfigPart::kCanBitrate);
  ExpectTickAgrees(50000);
  ExpectBitRate(1000000);
  // Settings it can run clear the refusal at the next reset.
  StoreAndReset(10000, 250);
  EXPECT_TRUE(app_.config_status().ok());
  ExpectTickAgrees(10000);
  ExpectBitRate(250000);
  EXPECT_FALSE(io_.output(OutputLine::kFault));
}

}  // namespace
}  // namespace volcomp::stm32g4
