// The configuration in force has one owner: BoardApp applies the stored settings to the HAL (step
// I/O, tick timer, CAN bit rate) at start and at every NMT reset node, in an order that never
// runs the tick at a rate the data path was not configured for, and makes a refusal visible.
// On the mock HAL, with the settings changed over CAN as an integrator would: 0x2000:3 (tick
// rate), 0x2000:2 (bit rate), 0x1010 "save", NMT reset node.
#include <gtest/gtest.h>

#include <vector>

#include "sdo_frames.hpp"
#include "volcomp/canopen/board_protocol.hpp"
#include "volcomp/firmware/board_app.hpp"
#include "volcomp/firmware/step_dir_io.hpp"
#include "volcomp/hal/mock/mock_devices.hpp"
#include "volcomp/hal/mock/mock_step_io.hpp"

namespace volcomp {
namespace {

using hal::InputLine;
using hal::OutputLine;
using testing::IsDownloadDone;
using testing::SdoDownload;

constexpr uint8_t kNode = 0x10;

class BoardAppConfigTest : public ::testing::Test {
 protected:
  BoardAppConfigTest()
      : io_(&clock_, nullptr),
        tables_(64 * 1024, 4096, 8, &clock_, nullptr),
        settings_(8192, 4096, 8, &clock_, nullptr),
        can_(&clock_, nullptr, 256),
        step_io_(DefaultBoardConfig(), nullptr),
        tick_io_(&step_io_),
        app_({&tick_io_, &io_, &tables_, &settings_, &can_, &clock_, &timer_}) {
    defaults_.node_id = kNode;
    defaults_.board.tick_hz = 20000;
    io_.SetInput(InputLine::kWriteEnable, true);
  }

  void Poll(int n = 1) {
    for (int i = 0; i < n; ++i) {
      app_.Poll();
      clock_.Advance(1000000);
    }
  }
  // An expedited download, answered by the board.
  void Write(uint16_t index, uint8_t sub, uint32_t value, uint8_t bytes) {
    can_.Inject(SdoDownload(kNode, index, sub, value, bytes));
    Poll();
    bool done = false;
    for (const CanFrame& f : can_.TakeSent()) done = done || IsDownloadDone(f, kNode, index, sub);
    EXPECT_TRUE(done) << "no download answer for " << std::hex << index << ":" << int{sub};
  }
  void StoreAndReset(uint32_t tick_hz, uint16_t bitrate_kbit) {
    Write(0x2000, 3, tick_hz, 4);
    Write(0x2000, 2, bitrate_kbit, 2);
    Write(0x1010, 1, testing::kSave, 4);
    can_.Inject(testing::NmtResetNode(kNode));
    Poll(2);
  }
  // EMCY frames (0x080 + node) sent since the last TakeSent().
  std::vector<CanFrame> Emcys() {
    std::vector<CanFrame> out;
    for (const CanFrame& f : can_.TakeSent()) {
      if (f.id == 0x080u + kNode) out.push_back(f);
    }
    return out;
  }

  BoardSettings defaults_;
  hal::mock::MockClock clock_;
  hal::mock::MockSlowIo io_;
  hal::mock::MockFlash tables_, settings_;
  hal::mock::MockCan can_;
  hal::mock::MockTickTimer timer_;
  hal::mock::MockStepIo step_io_;
  firmware::StepDirIo<hal::mock::MockStepIo> tick_io_;
  firmware::BoardApp<firmware::StepDirIo<hal::mock::MockStepIo>> app_;
};

TEST_F(BoardAppConfigTest, StartAppliesTheDefaultsToEveryDevice) {
  ASSERT_TRUE(app_.Start(defaults_).ok());
  EXPECT_TRUE(timer_.running());
  EXPECT_EQ(timer_.rate_hz(), 20000u);
  EXPECT_EQ(app_.settings().board.tick_hz, 20000u);
  EXPECT_EQ(app_.control_tick().compensation_divider(), CompensationDivider(20000));
  EXPECT_EQ(step_io_.config().tick_hz, 20000u);
  EXPECT_EQ(can_.bitrate_bps(), 1000000u);
  EXPECT_TRUE(app_.config_status().ok());
  EXPECT_FALSE(io_.output(OutputLine::kFault));
}

TEST_F(BoardAppConfigTest, StoredTickAndBitRateAreInForceAfterAResetNode) {
  ASSERT_TRUE(app_.Start(defaults_).ok());
  StoreAndReset(25000, 500);
  // The rate the timer runs at, the rate the data path assumes and the step I/O's tick agree.
  EXPECT_EQ(app_.settings().board.tick_hz, 25000u);
  EXPECT_EQ(app_.control_tick().compensation_divider(), CompensationDivider(25000));
  EXPECT_EQ(timer_.rate_hz(), 25000u);
  EXPECT_TRUE(timer_.running());
  EXPECT_EQ(step_io_.config().tick_hz, 25000u);
  EXPECT_EQ(can_.bitrate_bps(), 500000u);
  // Stopped once for the reset (SetRate refuses a running timer, so the order held), started twice.
  EXPECT_EQ(timer_.stops(), 1u);
  EXPECT_EQ(timer_.starts(), 2u);
  EXPECT_TRUE(app_.config_status().ok());
  EXPECT_TRUE(io_.output(OutputLine::kReady));
  EXPECT_FALSE(io_.output(OutputLine::kFault));
}

TEST_F(BoardAppConfigTest, StoredSettingsTheTimerRefusesGiveWayToTheDefaultsVisibly) {
  timer_.RefuseAbove(30000);
  ASSERT_TRUE(app_.Start(defaults_).ok());
  can_.TakeSent();
  StoreAndReset(50000, 500);
  // The board runs the factory defaults, whole: tick and bit rate.
  EXPECT_EQ(app_.settings().board.tick_hz, 20000u);
  EXPECT_EQ(app_.control_tick().compensation_divider(), CompensationDivider(20000));
  EXPECT_EQ(timer_.rate_hz(), 20000u);
  EXPECT_TRUE(timer_.running());
  EXPECT_EQ(can_.bitrate_bps(), 1000000u);
  EXPECT_EQ(app_.config_status().error(), Error::kConfigInvalid);
  EXPECT_EQ(app_.config_refused_by(), canopen::ConfigPart::kTickTimer);
  EXPECT_TRUE(io_.output(OutputLine::kFault));
  EXPECT_TRUE(io_.output(OutputLine::kReady));
  // EMCY 0xFF03 after the boot-up: error code and the refusing device.
  const std::vector<CanFrame> emcy = Emcys();
  ASSERT_EQ(emcy.size(), 1u);
  EXPECT_EQ(emcy[0].data[0], 0x03);
  EXPECT_EQ(emcy[0].data[1], 0xFF);
  EXPECT_NE(emcy[0].data[2] & 0x80, 0);  // error register: manufacturer
  EXPECT_EQ(emcy[0].data[3], static_cast<uint8_t>(Error::kConfigInvalid));
  EXPECT_EQ(emcy[0].data[5], static_cast<uint8_t>(canopen::ConfigPart::kTickTimer));
  // What the PC tool decodes from it (board_protocol.hpp).
  canopen::Emcy decoded;
  ASSERT_TRUE(canopen::DecodeEmcy(emcy[0], kNode, &decoded));
  EXPECT_EQ(decoded.code, 0xFF03);
  EXPECT_EQ(decoded.config_error(), Error::kConfigInvalid);
  EXPECT_EQ(decoded.config_part(), canopen::ConfigPart::kTickTimer);
  EXPECT_STREQ(canopen::ConfigPartName(decoded.config_part()), "tick timer");
  Poll(3);
  EXPECT_TRUE(io_.output(OutputLine::kFault));  // stays while the refusal stands
}

TEST_F(BoardAppConfigTest, ABitRateMismatchIsReportedWithoutFallingBack) {
  ASSERT_TRUE(app_.Start(defaults_).ok());
  StoreAndReset(25000, 500);
  can_.RefuseBitrate(Error::kCanBitrateMismatch);  // a port that can only compare (SocketCAN)
  can_.TakeSent();
  can_.Inject(testing::NmtResetNode(kNode));
  Poll();
  EXPECT_EQ(app_.settings().board.tick_hz, 25000u);  // the stored settings stay in force
  EXPECT_EQ(timer_.rate_hz(), 25000u);
  EXPECT_EQ(app_.config_status().error(), Error::kCanBitrateMismatch);
  EXPECT_EQ(app_.config_refused_by(), canopen::ConfigPart::kCanBitrate);
  EXPECT_TRUE(io_.output(OutputLine::kFault));
  const std::vector<CanFrame> emcy = Emcys();
  ASSERT_EQ(emcy.size(), 1u);
  EXPECT_NE(emcy[0].data[2] & 0x10, 0);  // error register: communication
  EXPECT_EQ(emcy[0].data[3], static_cast<uint8_t>(Error::kCanBitrateMismatch));
  // Restored ports clear it at the next reset.
  can_.RefuseBitrate(Status::Ok());
  can_.Inject(testing::NmtResetNode(kNode));
  Poll();
  EXPECT_TRUE(app_.config_status().ok());
  EXPECT_FALSE(io_.output(OutputLine::kFault));
}

TEST_F(BoardAppConfigTest, DefaultsTheHardwareRefusesLeaveTheBoardStopped) {
  timer_.RefuseAbove(10000);
  EXPECT_EQ(app_.Start(defaults_).error(), Error::kConfigInvalid);
  EXPECT_FALSE(app_.started());
  EXPECT_FALSE(timer_.running());
  EXPECT_TRUE(io_.output(OutputLine::kFault));
  EXPECT_FALSE(io_.output(OutputLine::kReady));
}

}  // namespace
}  // namespace volcomp
