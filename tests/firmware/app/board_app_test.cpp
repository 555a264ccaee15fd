// The board application on the mock HAL: stored table at boot, referencing by home switches,
// fault handling, refused images leave the active table untouched, recorded output timeline.
#include "volcomp/firmware/board_app.hpp"

#include <gtest/gtest.h>

#include "test_tables.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/firmware/table_store.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/hal/mock/mock_step_io.hpp"

namespace volcomp {
namespace {

using hal::InputLine;
using hal::OutputLine;
using hal::mock::EventKind;

testing::AlignedBytes UniformImage(double cx, double cy, double cz, uint32_t id) {
  testing::GridCase g;
  g.type = table::ElementType::kInt16;
  g.frac_bits = 8;
  for (auto& d : g.dim) d = {2, -100000, 200000};
  for (int i = 0; i < 8; ++i) {
    for (double c : {cx, cy, cz}) g.i16.push_back(static_cast<int16_t>(c * 256));
  }
  g.steps.assign(g.i16.size(), 0);
  return testing::WriteGridImage(g, id);
}

class BoardAppTest : public ::testing::Test {
 protected:
  BoardAppTest()
      : config_(DefaultBoardConfig()),
        io_(&clock_, &timeline_),
        flash_(64 * 1024, 4096, 8, &clock_, &timeline_),
        step_io_(config_, &timeline_),
        tick_io_(&step_io_),
        app_({&tick_io_, &io_, &flash_}) {}

  // Stores `img` as the active table, as a completed upload and activation would.
  void Store(const testing::AlignedBytes& img) {
    firmware::TableStore store;
    ASSERT_TRUE(store.Init(&flash_, flash_.size() / 2).ok());
    store.MountActive(config_).status().IgnoreError();
    ASSERT_TRUE(store.BeginUpload(static_cast<uint32_t>(img.size())).ok());
    ASSERT_TRUE(store.UploadData(img.data(), static_cast<uint32_t>(img.size())).ok());
    ASSERT_TRUE(store.FinishUpload().ok());
    ASSERT_TRUE(store.Verify(config_).ok());
    ASSERT_TRUE(store.Activate().ok());
  }
  // Runs `n` ticks of 20 us with a Poll() every 50 ticks.
  void Run(int n) {
    for (int i = 0; i < n; ++i) {
      step_io_.set_tick_start_ns(clock_.now());
      app_.Tick();
      if (i % 50 == 0) app_.Poll();
      clock_.Advance(20000);
    }
  }
  void Home() {
    for (uint8_t a = 0; a < 3; ++a) io_.SetInput(hal::HomeLine(a), true);
    app_.Poll();
    Run(1);
    for (uint8_t a = 0; a < 3; ++a) io_.SetInput(hal::HomeLine(a), false);
  }

  BoardConfig config_;
  hal::mock::Timeline timeline_;
  hal::mock::MockClock clock_;
  hal::mock::MockSlowIo io_;
  hal::mock::MockFlash flash_;
  hal::mock::MockStepIo step_io_;
  firmware::StepDirIo<hal::mock::MockStepIo> tick_io_;
  firmware::BoardApp<firmware::StepDirIo<hal::mock::MockStepIo>> app_;
};

TEST_F(BoardAppTest, EmptyFlashRunsPassThrough) {
  ASSERT_TRUE(app_.Start(config_).ok());
  EXPECT_EQ(app_.stored_table_status().error(), Error::kNotFound);
  io_.SetInput(InputLine::kEnable, true);
  Home();
  step_io_.add_steps(0, 1234);
  Run(100);
  EXPECT_EQ(step_io_.drive(0).position(), 1234);
  EXPECT_TRUE(io_.output(OutputLine::kReady));
  EXPECT_FALSE(io_.output(OutputLine::kCompensating));
}

TEST_F(BoardAppTest, StoredTableEngagesAfterHomingAndTimelineShowsIt) {
  Store(UniformImage(5, -3, 2, 77));
  ASSERT_TRUE(app_.Start(config_).ok());
  ASSERT_TRUE(app_.stored_table_status().ok()) << app_.stored_table_status().name();
  Run(1);  // the table is handed to the data path at the next tick
  EXPECT_EQ(app_.control_tick().compensator().table_id(), 77u);
  io_.SetInput(InputLine::kEnable, true);
  step_io_.add_steps(1, 500);
  Run(200);
  EXPECT_EQ(step_io_.drive(1).position(), 500);  // not referenced: pass-through
  EXPECT_FALSE(io_.output(OutputLine::kCompensating));
  const uint64_t homed_at = clock_.now();
  Home();
  Run(20000);
  EXPECT_TRUE(io_.output(OutputLine::kCompensating));
  EXPECT_EQ(step_io_.drive(0).position(), 5);
  EXPECT_EQ(step_io_.drive(1).position(), 500 - 3);
  EXPECT_EQ(step_io_.drive(2).position(), 2);
  EXPECT_EQ(app_.control_tick().machine_position(1), config_.axis[1].home_position_steps);
  // Timeline: Ready went high at start; Compensating rose after homing, before any fault.
  const auto outs = timeline_.Filter(EventKind::kOutputLine);
  ASSERT_GE(outs.size(), 2u);
  EXPECT_EQ(outs[0].channel, static_cast<uint8_t>(OutputLine::kReady));
  EXPECT_EQ(outs[0].value, 1);
  const auto comp =
      timeline_.Filter(EventKind::kOutputLine, static_cast<int>(OutputLine::kCompensating));
  ASSERT_EQ(comp.size(), 1u);
  EXPECT_GE(comp[0].time_ns, homed_at);
  // Every correction step went out as a legal pulse.
  for (uint8_t a = 0; a < 3; ++a) EXPECT_EQ(step_io_.drive(a).violations(), 0u);
  EXPECT_FALSE(timeline_.Filter(EventKind::kStepLineA, 0).empty());
}

TEST_F(BoardAppTest, EStopRampsOutAndRequiresNewReference) {
  Store(UniformImage(8, 0, 0, 1));
  ASSERT_TRUE(app_.Start(config_).ok());
  io_.SetInput(InputLine::kEnable, true);
  Home();
  Run(20000);
  ASSERT_EQ(step_io_.drive(0).position(), 8);
  io_.SetInput(InputLine::kEStop, true);
  Run(20000);
  EXPECT_TRUE(io_.output(OutputLine::kFault));
  EXPECT_EQ(step_io_.drive(0).position(), 0);
  EXPECT_TRUE(app_.control_tick().compensator().passthrough());
  io_.SetInput(InputLine::kEStop, false);
  Run(20000);
  EXPECT_FALSE(io_.output(OutputLine::kFault));
  EXPECT_FALSE(app_.control_tick().all_referenced());
  EXPECT_EQ(step_io_.drive(0).position(), 0);  // still pass-through until homed again
  Home();
  Run(20000);
  EXPECT_EQ(step_io_.drive(0).position(), 8);
}

TEST_F(BoardAppTest, BadImagesAreRefusedAndTheActiveTableIsUntouched) {
  const testing::AlignedBytes good = UniformImage(4, 4, 4, 11);
  Store(good);
  ASSERT_TRUE(app_.Start(config_).ok());
  io_.SetInput(InputLine::kEnable, true);
  Home();
  Run(20000);
  const uint32_t crc = app_.control_tick().compensator().table_crc32();
  testing::AlignedBytes other = UniformImage(-9, 1, 1, 12);
  // Truncated, corrupted and wrong-board images.
  EXPECT_FALSE(app_.ActivateImage(other.data(), other.size() - 4).ok());
  other[40] ^= 1;
  EXPECT_EQ(app_.ActivateImage(other.data(), other.size()).error(), Error::kImageBadCrc);
  BoardConfig y_half = config_;
  y_half.axis[1].resolution_e9 = 500000;
  ControlTick probe;
  ASSERT_TRUE(probe.Configure(y_half).ok());
  testing::AlignedBytes fine = UniformImage(1, 1, 1, 13);
  StoreLe32(fine.data() + 24 + 8 + 4 + 8 + 4, 500000);  // Y resolution in the AXES record
  testing::FixCrc(fine);
  EXPECT_EQ(app_.ActivateImage(fine.data(), fine.size()).error(), Error::kConfigResolutionMismatch);
  Run(5000);
  EXPECT_EQ(app_.control_tick().compensator().table_crc32(), crc);
  EXPECT_EQ(app_.control_tick().compensator().table_id(), 11u);
  EXPECT_EQ(step_io_.drive(0).position(), 4);
}

TEST_F(BoardAppTest, InvalidConfigurationKeepsFaultAndPassThrough) {
  BoardConfig bad = config_;
  bad.tick_hz = 0;
  EXPECT_EQ(app_.Start(bad).error(), Error::kConfigInvalid);
  EXPECT_TRUE(io_.output(OutputLine::kFault));
  EXPECT_FALSE(io_.output(OutputLine::kReady));
}

TEST_F(BoardAppTest, StepOutputRefusingTheDriveTimingKeepsFault) {
  // 15 us high + 15 us low per pulse does not fit a 20 us tick: the step output stage refuses.
  BoardConfig slow = config_;
  for (AxisConfig& ax : slow.axis) ax.drive.pulse_width_ns = ax.drive.step_space_ns = 15000;
  EXPECT_EQ(app_.Start(slow).error(), Error::kConfigInvalid);
  EXPECT_TRUE(io_.output(OutputLine::kFault));
  EXPECT_FALSE(io_.output(OutputLine::kReady));
  step_io_.add_steps(0, 10);
  Run(10);
  EXPECT_EQ(step_io_.drive(0).position(), 0);  // not started: no pulses
}

}  // namespace
}  // namespace volcomp
